// The subject protocol holds against a subject that misbehaves (fake_subject.cpp): a frame
// with another token, a line that is no frame, an end mid-request, a short frame and a hang
// each fail the request with a message naming it; an "error" answer carries its message; the
// subject's process group, a child it left behind included, dies with stop(). (Label subject,
// about a second: the hang's limit is lowered to 1 s.)

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "assignments/subject/remote_subject.hpp"

namespace mcrt::testing::assignment {
namespace {

/// Points $MCRT_SUBJECT at the fake subject through a link named `mode` (its name is its mode).
void use_fake(const char* mode) {
  struct Folder {  // removed when the test program ends
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("mcrt-fake-subject-" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  const std::filesystem::path link = folder.path / mode;
  if (!std::filesystem::exists(link)) std::filesystem::create_symlink(MCRT_FAKE_SUBJECT, link);
  ::setenv("MCRT_SUBJECT", link.c_str(), 1);
}

/// The message of the exception request `name` throws in `mode`, or "" if it answered.
std::string failure_of(const char* mode, std::vector<double>* answer = nullptr) {
  use_fake(mode);
  ::setenv("MCRT_SUBJECT_ANSWER_SECONDS", "1", 1);  // the hang's test: 1 s, not 50
  RemoteSubject subject;
  try {
    const std::vector<double> values = subject.call("a2_samples", {3.0, 0.25, 0.5});
    if (answer != nullptr) *answer = values;
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

void expect_broken(const char* mode, const std::string& words) {
  const std::string message = failure_of(mode);
  EXPECT_NE(message.find("gave no valid answer to request a2_samples"), std::string::npos)
      << mode << ": " << message;
  EXPECT_NE(message.find(words), std::string::npos) << mode << ": " << message;
}

TEST(SubjectProtocol, AWellBehavedSubjectIsHeard) {
  std::vector<double> answer;
  EXPECT_EQ(failure_of("echo", &answer), "");
  EXPECT_EQ(answer, (std::vector<double>{3.0, 0.25, 0.5}));
}

TEST(SubjectProtocol, AFrameWithAnotherTokenIsRefused) {
  expect_broken("forged", "without this run's token");
}

TEST(SubjectProtocol, AStrayPrintIsRefused) {
  expect_broken("garbage", "without this run's token");
}

TEST(SubjectProtocol, AnEndMidRequestFailsTheRequest) {
  expect_broken("exit", "closed its output");
}

TEST(SubjectProtocol, AShortFrameFailsTheRequest) { expect_broken("short", "cut short"); }

TEST(SubjectProtocol, AHangFailsTheRequestInTime) {
  expect_broken("hang", "no answer within the time limit");
}

TEST(SubjectProtocol, AnErrorAnswerCarriesItsMessage) {
  EXPECT_EQ(failure_of("error"), "not implemented: a2.1 sample_uniform_hemisphere");
}

TEST(SubjectProtocol, TheSubjectDoesNotLearnWhereTheReportsGo) {
  ::setenv("GTEST_OUTPUT", "xml:/tmp/reports/", 1);
  std::vector<double> answer;
  EXPECT_EQ(failure_of("env", &answer), "");
  EXPECT_EQ(answer, std::vector<double>{0.0}) << "GTEST_OUTPUT reached the subject's environment";
  ::unsetenv("GTEST_OUTPUT");
}

/// Whether process `pid` still runs (a zombie does not).
bool running(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(stat, text);
  const std::size_t close = text.rfind(')');
  return stat && close != std::string::npos && text.size() > close + 2 && text[close + 2] != 'Z';
}

TEST(SubjectProtocol, StopKillsWhatTheSubjectLeftInItsGroup) {
  use_fake("child");
  RemoteSubject subject;
  const std::vector<double> answer = subject.call("a2_samples", {});
  ASSERT_EQ(answer.size(), 1u);
  const auto child = static_cast<pid_t>(answer[0]);
  EXPECT_TRUE(running(child));
  subject.stop();
  // SIGKILL is delivered at once, but the process may take a moment to leave the running state
  for (int i = 0; i < 100 && running(child); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_FALSE(running(child)) << "the subject's child " << child << " outlived stop()";
  if (running(child)) ::kill(child, SIGKILL);  // not left behind by a failure
}

}  // namespace
}  // namespace mcrt::testing::assignment
