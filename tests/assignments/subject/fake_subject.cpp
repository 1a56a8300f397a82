// A subject program that misbehaves as its name says (protocol_test.cpp runs it through a link
// named for the mode: the subject's environment is cleared), for protocol_test.cpp: what a
// student's code could do to the subject (print frames of its own, end mid-request, hang,
// leave a process behind) must fail the request with a message naming it, never pass as an
// answer.
//   echo     answers every request with its own numbers (a well-behaved subject)
//   forged   answers with a frame that carries another token
//   garbage  prints a line that is no frame
//   exit     reads the request, then ends without answering
//   short    announces 10 numbers, sends 1 and ends
//   hang     never answers
//   error    answers "error" with a message
//   child    answers with the pid of a child it leaves sleeping in its process group
//   env      answers 1 if it can see where the checker's reports go (GTEST_OUTPUT), else 0

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "assignments/subject/protocol.hpp"

using namespace mcrt::testing::assignment;

int main(int, char** argv) {
  const std::string name = argv[0];
  const std::string mode = name.substr(name.rfind('/') + 1);
  FrameReader in(STDIN_FILENO);
  std::string token, problem;
  if (!in.read_line(token, k_max_header_bytes, -1.0, problem)) return 1;
  for (;;) {
    Frame request;
    if (!in.read_frame(token, request, -1.0, problem)) return 0;
    if (mode == "echo") {
      write_frame(STDOUT_FILENO, token, "ok", request.values);
    } else if (mode == "forged") {
      write_frame(STDOUT_FILENO, std::string(32, '0'), "ok", request.values);
    } else if (mode == "garbage") {
      std::printf("hello from the student's code\n");
      std::fflush(stdout);
    } else if (mode == "exit") {
      return 0;
    } else if (mode == "short") {
      const std::string header = token + " ok 10\n";
      const double one = 1.0;
      write_all_bytes(STDOUT_FILENO, header.data(), header.size());
      write_all_bytes(STDOUT_FILENO, &one, sizeof one);
      return 0;
    } else if (mode == "hang") {
      pause();
    } else if (mode == "error") {
      write_error_frame(STDOUT_FILENO, token, "not implemented: a2.1 sample_uniform_hemisphere");
    } else if (mode == "env") {
      write_frame(STDOUT_FILENO, token, "ok", {std::getenv("GTEST_OUTPUT") != nullptr ? 1.0 : 0.0});
    } else if (mode == "child") {
      const pid_t child = fork();
      if (child == 0) {
        // no descriptor of the checker's or the test runner's: a regression fails, not hangs
        for (int fd = 0; fd < 3; ++fd) close(fd);
        for (;;) pause();
      }
      write_frame(STDOUT_FILENO, token, "ok", {static_cast<double>(child)});
    }
  }
}
