// The main of a checker: a public or hidden test program built from the instructor's sources
// only, whose checks send their requests to the subject program (RemoteSubject). The subject's
// process group is killed before gtest writes its report. Run as root, it refuses a report
// folder that the subject's user could write (the verdicts would then be forgeable).

#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "assignments/subject/subject.hpp"

namespace {

/// Kills the subject after the last test, before the report is written (gtest tears the
/// environments down before it writes the XML).
class SubjectEnvironment : public ::testing::Environment {
 public:
  void TearDown() override { mcrt::testing::assignment::subject().stop(); }
};

/// The folder of GTEST_OUTPUT ("xml:DIR/" or "xml:FILE"), or "" when there is none.
std::string report_folder() {
  const char* output = std::getenv("GTEST_OUTPUT");
  if (output == nullptr) return "";
  std::string path = output;
  if (path.rfind("xml:", 0) != 0) return "";
  path = path.substr(4);
  if (!path.empty() && path.back() != '/') path = path.substr(0, path.rfind('/') + 1);
  return path.empty() ? "." : path;
}

/// Whether the user `nobody` (the subject's, when root) could write into `folder`.
bool writable_by_subject(const std::string& folder) {
  const passwd* user = ::getpwnam("nobody");
  struct stat st {};
  if (user == nullptr || ::stat(folder.c_str(), &st) != 0) return false;
  return st.st_uid == user->pw_uid || (st.st_mode & S_IWOTH) ||
         (st.st_gid == user->pw_gid && (st.st_mode & S_IWGRP));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const std::string folder = report_folder();
  if (::geteuid() == 0 && !folder.empty() && writable_by_subject(folder)) {
    std::fprintf(
        stderr,
        "checker: the report folder %s is writable by nobody, who runs the subject: refused\n",
        folder.c_str());
    return 1;
  }
  ::testing::AddGlobalTestEnvironment(new SubjectEnvironment);
  return RUN_ALL_TESTS();
}
