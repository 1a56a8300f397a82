#pragma once
// The subject protocol: how a trusted checker asks the subject program (the student's
// functions, built alone, run as an unprivileged user) for data, and how it answers.
//
// Every frame, both ways, is one header line "<token> <name> <count>\n" followed by `count`
// native doubles (8 bytes each). The token is 32 random hex digits that the checker sends as
// the first line of the subject's stdin: a stray print of student code (redirected to stderr by
// the subject anyway) never reads as a frame. A request's name says what is asked; an answer
// is "ok" with its numbers, or "error" whose count is the byte length of a message that follows
// (the student code's exception, such as "not implemented: a2.1 ...").

#include <cstddef>
#include <string>
#include <vector>

namespace mcrt::testing::assignment {

/// No request or answer carries more: the largest (a2's samples) is 3e5 values; a header
/// that claims more is malformed, not an allocation of gigabytes.
inline constexpr std::size_t k_max_frame_values = std::size_t{1} << 24;
/// A header line is "<32 hex> <name> <count>": far below this.
inline constexpr std::size_t k_max_header_bytes = 256;

/// 128 random bits as 32 hex digits (from /dev/urandom); throws std::runtime_error if it
/// cannot read them.
std::string random_token();

/// One frame read: its name and numbers, or the text of an "error" frame.
struct Frame {
  std::string name;
  std::vector<double> values;
  std::string text;
};

/// Writes all of `size` bytes to `fd` (retrying short writes and EINTR); false on failure.
bool write_all_bytes(int fd, const void* data, std::size_t size);

/// Writes one frame of numbers; false when the other side is gone.
bool write_frame(int fd, const std::string& token, const std::string& name,
                 const std::vector<double>& values);

/// Writes one "error" frame carrying `message`.
bool write_error_frame(int fd, const std::string& token, const std::string& message);

/// Reads frames from one file descriptor, through a buffer, each within a time limit.
class FrameReader {
 public:
  explicit FrameReader(int fd) : fd_(fd) {}
  /// Reads one line (without its newline) of at most `limit` bytes; false with `problem` set
  /// on end of file, a longer line or the deadline (seconds; negative: none).
  bool read_line(std::string& line, std::size_t limit, double seconds, std::string& problem);
  /// Reads one frame carrying `token`; false with `problem` saying what was wrong (the end of
  /// the stream, a wrong token, a malformed header, a short payload, the deadline).
  bool read_frame(const std::string& token, Frame& frame, double seconds, std::string& problem);

 private:
  bool fill(double deadline, std::string& problem);
  bool read_bytes(char* out, std::size_t size, double deadline, std::string& problem);
  int fd_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0;
};

}  // namespace mcrt::testing::assignment
