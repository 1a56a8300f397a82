// --out as a whole, through a real chapter program: a second run interrupted by SIGTERM leaves
// the first run as it was and no staging folder; a folder that is not a chapter's output is
// refused before any work and left untouched.

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "chapters/run_program.hpp"

using namespace mcrt::testing;
namespace fs = std::filesystem;

namespace {

TEST(RunFolderChapterTest, AnInterruptedSecondRunLeavesTheFirstWhole) {
  const fs::path dir = fresh_dir("run_folder_interrupted");
  const fs::path out = dir / "out";
  // No reference image (--reference-spp 0): its cache would be a second folder beside --out.
  ASSERT_EQ(run_program("ch05_path_tracer",
                        "--width 8 --height 6 --spp 1 --reference-spp 0 "
                        "--quiet --out " +
                            out.string())
                .exit_code,
            0);
  const std::string first = read_text(out / "summary.json");
  // A run of several seconds, interrupted after a moment.
  const std::string program = std::string(MCRT_BIN_DIR) + "/ch05_path_tracer";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execl(program.c_str(), program.c_str(), "--width", "256", "--height", "192", "--spp",
            "1,4,16,64,256", "--reference-spp", "0", "--threads", "1", "--quiet", "--out",
            out.c_str(), nullptr);
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_EQ(read_text(out / "summary.json"), first);
  EXPECT_FALSE(fs::exists(out / "spp_0004.png"));  // nothing of the second run
  EXPECT_EQ(entries(dir), 1);                      // no staging folder left
}

TEST(RunFolderChapterTest, AForeignFolderIsRefusedAndLeftUntouched) {
  const fs::path dir = fresh_dir("run_folder_foreign");
  { std::ofstream(dir / "notes.txt") << "mine\n"; }
  const ProgramRun run =
      run_program("ch01_ray_tracing", "--width 8 --height 6 --out " + dir.string());
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("--out"), std::string::npos) << run.err;
  EXPECT_EQ(read_text(dir / "notes.txt"), "mine\n");
  EXPECT_EQ(entries(dir), 1);
  for (const auto& entry : fs::directory_iterator(dir.parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".run_folder_foreign.staging"),
              std::string::npos);
}

}  // namespace
