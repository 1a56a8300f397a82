#include "assignments/subject/protocol.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace mcrt::testing::assignment {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool is_hex_token(const std::string& s) {
  if (s.size() != 32) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

}  // namespace

std::string random_token() {
  std::ifstream in("/dev/urandom", std::ios::binary);
  unsigned char bytes[16];
  if (!in.read(reinterpret_cast<char*>(bytes), sizeof bytes))
    throw std::runtime_error("cannot read /dev/urandom for the subject's token");
  std::string token;
  for (unsigned char b : bytes) token += fmt::format("{:02x}", b);
  return token;
}

bool write_all_bytes(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool write_frame(int fd, const std::string& token, const std::string& name,
                 const std::vector<double>& values) {
  const std::string header = fmt::format("{} {} {}\n", token, name, values.size());
  return write_all_bytes(fd, header.data(), header.size()) &&
         write_all_bytes(fd, values.data(), values.size() * sizeof(double));
}

bool write_error_frame(int fd, const std::string& token, const std::string& message) {
  const std::string header = fmt::format("{} error {}\n", token, message.size());
  return write_all_bytes(fd, header.data(), header.size()) &&
         write_all_bytes(fd, message.data(), message.size());
}

bool FrameReader::fill(double deadline, std::string& problem) {
  if (begin_ > 0) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(begin_));
    begin_ = 0;
  }
  for (;;) {
    if (deadline >= 0.0) {
      const double left = deadline - now_seconds();
      if (left <= 0.0) {
        problem = "no answer within the time limit";
        return false;
      }
      pollfd p{fd_, POLLIN, 0};
      const int r = ::poll(&p, 1, static_cast<int>(left * 1000.0) + 1);
      if (r < 0 && errno == EINTR) continue;
      if (r == 0) continue;  // the loop's deadline check says so
    }
    char chunk[65536];
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      problem = fmt::format("cannot read: {}", std::strerror(errno));
      return false;
    }
    if (n == 0) {
      problem = "the subject program closed its output (it ended or crashed)";
      return false;
    }
    buffer_.insert(buffer_.end(), chunk, chunk + n);
    return true;
  }
}

bool FrameReader::read_line(std::string& line, std::size_t limit, double seconds,
                            std::string& problem) {
  const double deadline = seconds < 0.0 ? -1.0 : now_seconds() + seconds;
  for (;;) {
    const auto first = buffer_.begin() + static_cast<std::ptrdiff_t>(begin_);
    const auto end = std::find(first, buffer_.end(), '\n');
    if (end != buffer_.end() && static_cast<std::size_t>(end - first) <= limit) {
      line.assign(first, end);
      begin_ += line.size() + 1;
      return true;
    }
    if (static_cast<std::size_t>(buffer_.end() - first) > limit) {
      problem = fmt::format("a line longer than {} bytes where a frame header belongs", limit);
      return false;
    }
    if (!fill(deadline, problem)) return false;
  }
}

bool FrameReader::read_bytes(char* out, std::size_t size, double deadline, std::string& problem) {
  while (size > 0) {
    if (begin_ == buffer_.size() && !fill(deadline, problem)) return false;
    const std::size_t n = std::min(size, buffer_.size() - begin_);
    std::memcpy(out, buffer_.data() + begin_, n);
    begin_ += n;
    out += n;
    size -= n;
  }
  return true;
}

bool FrameReader::read_frame(const std::string& token, Frame& frame, double seconds,
                             std::string& problem) {
  const double deadline = seconds < 0.0 ? -1.0 : now_seconds() + seconds;
  std::string line;
  if (!read_line(line, k_max_header_bytes, seconds, problem)) return false;
  const std::size_t a = line.find(' '), b = line.find(' ', a == std::string::npos ? a : a + 1);
  if (a == std::string::npos || b == std::string::npos) {
    problem = "a malformed frame header (not \"<token> <name> <count>\")";
    return false;
  }
  if (!is_hex_token(line.substr(0, a)) || line.substr(0, a) != token) {
    problem = "a frame without this run's token (a stray print or a forged frame)";
    return false;
  }
  frame.name = line.substr(a + 1, b - a - 1);
  const std::string count_text = line.substr(b + 1);
  if (frame.name.empty() || count_text.empty() || count_text.size() > 12 ||
      count_text.find_first_not_of("0123456789") != std::string::npos) {
    problem = "a malformed frame header (its name or count)";
    return false;
  }
  const std::size_t count = std::stoull(count_text);
  if (count > k_max_frame_values * sizeof(double)) {
    problem = fmt::format("a frame of {} values, more than any request needs", count);
    return false;
  }
  frame.values.clear();
  frame.text.clear();
  if (frame.name == "error") {
    frame.text.resize(count);
    return read_bytes(frame.text.data(), count, deadline, problem);
  }
  if (count > k_max_frame_values) {
    problem = fmt::format("a frame of {} values, more than any request needs", count);
    return false;
  }
  frame.values.resize(count);
  if (!read_bytes(reinterpret_cast<char*>(frame.values.data()), count * sizeof(double), deadline,
                  problem)) {
    problem = "a frame cut short: " + problem;
    return false;
  }
  return true;
}

}  // namespace mcrt::testing::assignment
