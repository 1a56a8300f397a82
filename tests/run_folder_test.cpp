// The output folder as a whole (common/io/run_folder.hpp): a run writes into a staging folder
// that replaces --out only when committed; a folder that is not a chapter's output is never
// replaced; a run that fails leaves nothing behind.

#include "io/run_folder.hpp"

#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "io/cli.hpp"
#include "io/output.hpp"
#include "support/exception_message.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;
using namespace mcrt::testing;  // support/: message_of, fresh_temp_dir, read_text, ...

namespace {

fs::path fresh_dir(const std::string& name) { return fresh_temp_dir("run_folder_test", name); }

// A finished run of a chapter into `out`, with one file `name` holding `text`.
void finished_run(const fs::path& out, const std::string& name, const std::string& text) {
  mcrt::RunFolder folder(out);
  write_text(folder.staging() / "summary.json", R"({"chapter": "ch01_ray_tracing", "seed": 1})");
  write_text(folder.staging() / name, text);
  folder.commit();
}

TEST(RunFolderTest, AFirstRunAppearsWholeAtCommitAndNotBefore) {
  const fs::path dir = fresh_dir("first");
  const fs::path out = dir / "parent" / "out";
  mcrt::RunFolder folder(out);
  EXPECT_EQ(folder.staging().parent_path(), fs::canonical(dir / "parent"));
  write_text(folder.staging() / "a.txt", "a");
  EXPECT_FALSE(fs::exists(out));
  folder.commit();
  EXPECT_EQ(read_text(out / "a.txt"), "a");
  EXPECT_EQ(entries(dir / "parent"), 1);  // the staging folder is gone
}

TEST(RunFolderTest, ASecondRunReplacesTheFirstWhole) {
  const fs::path dir = fresh_dir("swap");
  const fs::path out = dir / "out";
  finished_run(out, "old.txt", "old");
  finished_run(out, "new.txt", "new");
  EXPECT_FALSE(fs::exists(out / "old.txt"));  // no mix of two runs
  EXPECT_EQ(read_text(out / "new.txt"), "new");
  EXPECT_EQ(entries(dir), 1);  // the previous run is removed
}

TEST(RunFolderTest, AFailedRunLeavesThePreviousOneAndNoStagingFolder) {
  const fs::path dir = fresh_dir("failed");
  const fs::path out = dir / "out";
  finished_run(out, "old.txt", "old");
  {
    mcrt::RunFolder folder(out);
    write_text(folder.staging() / "new.txt", "new");
  }  // destroyed without commit: the run failed
  EXPECT_EQ(read_text(out / "old.txt"), "old");
  EXPECT_FALSE(fs::exists(out / "new.txt"));
  EXPECT_EQ(entries(dir), 1);
}

TEST(RunFolderTest, AFailedFirstRunRemovesTheParentsItCreated) {
  const fs::path dir = fresh_dir("parents");
  { mcrt::RunFolder folder(dir / "a" / "b" / "out"); }
  EXPECT_EQ(entries(dir), 0);
}

TEST(RunFolderTest, AnEmptyFolderIsAccepted) {
  const fs::path dir = fresh_dir("empty");
  fs::create_directory(dir / "out");
  finished_run(dir / "out", "a.txt", "a");
  EXPECT_EQ(read_text(dir / "out" / "a.txt"), "a");
}

TEST(RunFolderTest, AFolderThatIsNotAChaptersOutputIsRefusedAndKept) {
  const fs::path dir = fresh_dir("foreign");
  fs::create_directory(dir / "out");
  write_text(dir / "out" / "thesis.tex", "precious");
  const std::string message =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "out"); });
  EXPECT_NE(message.find("--out"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "out").string()), std::string::npos) << message;
  EXPECT_EQ(read_text(dir / "out" / "thesis.tex"), "precious");
  EXPECT_EQ(entries(dir), 1);  // no staging folder made
  // A summary.json of something else does not make it ours either.
  write_text(dir / "out" / "summary.json", R"({"chapter": "the methods chapter"})");
  EXPECT_NE(message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "out"); }), "");
}

TEST(RunFolderTest, TheCurrentFolderAndTheRootAreRefused) {
  EXPECT_NE(message_of<mcrt::UsageError>([] { mcrt::RunFolder folder("."); }), "");
  EXPECT_NE(message_of<mcrt::UsageError>([] { mcrt::RunFolder folder("/"); }), "");
  EXPECT_NE(message_of<mcrt::UsageError>([] { mcrt::RunFolder folder(".."); }), "");
}

TEST(RunFolderTest, ADanglingLinkAndAFileAreNamedAsSuch) {
  const fs::path dir = fresh_dir("dangling");
  fs::create_symlink(dir / "nowhere", dir / "link");
  const std::string dangling =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "link"); });
  EXPECT_NE(dangling.find("dangling"), std::string::npos) << dangling;
  write_text(dir / "file", "x");
  const std::string file = message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "file"); });
  EXPECT_NE(file.find("is a file"), std::string::npos) << file;
  EXPECT_EQ(entries(dir), 2);
}

TEST(RunFolderTest, ALinkToAPreviousRunIsFollowed) {
  const fs::path dir = fresh_dir("link");
  finished_run(dir / "real", "old.txt", "old");
  fs::create_directory_symlink(dir / "real", dir / "out");
  finished_run(dir / "out", "new.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "out"));
  EXPECT_EQ(read_text(dir / "real" / "new.txt"), "new");
  EXPECT_FALSE(fs::exists(dir / "real" / "old.txt"));
}

TEST(RunFolderTest, MessagesNameOutNotTheStagingFolder) {
  const fs::path dir = fresh_dir("names");
  mcrt::RunFolder folder(dir / "out");
  const std::string text = "cannot write '" + (folder.staging() / "a.png").string() + "'";
  EXPECT_EQ(folder.with_out_name(text), "cannot write '" + (dir / "out" / "a.png").string() + "'");
}

}  // namespace
