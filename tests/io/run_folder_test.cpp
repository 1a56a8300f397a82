// The output folder as a whole (common/io/run_folder.hpp): a run writes into a staging folder
// that replaces --out only when committed; a folder holding anything its manifest does not
// list is never replaced; a run that fails leaves nothing behind; a killed run's staging
// folder is removed by the next run, and nothing else is.

#include "io/run_folder.hpp"

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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
  // A summary.json, even one naming a chapter, does not make it a run's either.
  write_text(dir / "out" / "summary.json", R"({"chapter": "ch01_ray_tracing"})");
  EXPECT_NE(message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "out"); }), "");
}

TEST(RunFolderTest, TheManifestListsEverythingTheRunWroteAndItself) {
  const fs::path dir = fresh_dir("manifest");
  {
    mcrt::RunFolder folder(dir / "out");
    write_text(folder.staging() / "b.txt", "b");
    fs::create_directory(folder.staging() / "plots");
    write_text(folder.staging() / "plots" / "a.svg", "a");
    folder.commit();
  }
  EXPECT_EQ(read_text(dir / "out" / mcrt::k_manifest_name),
            std::string(mcrt::k_manifest_name) + "\nb.txt\nplots/\nplots/a.svg\n");
  EXPECT_EQ(mcrt::first_foreign_entry(dir / "out"), std::nullopt);
}

// Issue 34: a user's notes added inside a previous run's folder were deleted by the next run.
TEST(RunFolderTest, AFileAddedToAPreviousRunIsNamedAndKept) {
  const fs::path dir = fresh_dir("added");
  finished_run(dir / "out", "old.txt", "old");
  fs::create_directory(dir / "out" / "my_edits");
  write_text(dir / "out" / "notes.txt", "mine");
  const std::string message =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "out"); });
  EXPECT_NE(message.find("'my_edits/'"), std::string::npos) << message;  // the first, sorted
  EXPECT_EQ(read_text(dir / "out" / "notes.txt"), "mine");
  EXPECT_EQ(read_text(dir / "out" / "old.txt"), "old");
  EXPECT_EQ(entries(dir), 1);
  // Inside a folder the run wrote, too.
  fs::remove(dir / "out" / "my_edits");
  fs::remove(dir / "out" / "notes.txt");
  ASSERT_EQ(mcrt::first_foreign_entry(dir / "out"), std::nullopt);
  {
    mcrt::RunFolder folder(dir / "out");
    fs::create_directory(folder.staging() / "plots");
    folder.commit();
  }
  write_text(dir / "out" / "plots" / "mine.txt", "mine");
  EXPECT_EQ(mcrt::first_foreign_entry(dir / "out"), "plots/mine.txt");
}

// Issue 34: a FIFO in place of a previous run's file blocked the check forever.
TEST(RunFolderTest, AFifoInAPreviousRunIsRefusedWithoutOpeningIt) {
  const fs::path dir = fresh_dir("fifo");
  finished_run(dir / "out", "summary.json", "{}");
  fs::remove(dir / "out" / "summary.json");
  ASSERT_EQ(::mkfifo((dir / "out" / "summary.json").c_str(), 0600), 0);
  const std::string message =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "out"); });
  EXPECT_NE(message.find("'summary.json'"), std::string::npos) << message;
  // The same for a FIFO in place of the manifest.
  fs::remove(dir / "out" / "summary.json");
  fs::remove(dir / "out" / mcrt::k_manifest_name);
  ASSERT_EQ(::mkfifo((dir / "out" / mcrt::k_manifest_name).c_str(), 0600), 0);
  EXPECT_EQ(mcrt::first_foreign_entry(dir / "out"), mcrt::k_manifest_name);
}

// Issue 34: HOME=H --out ~ replaced the whole home when it held a copied summary.json.
TEST(RunFolderTest, HomeIsRefusedWhateverItHolds) {
  const fs::path dir = fresh_dir("home");
  fs::create_directory(dir / "home");
  const char* saved = std::getenv("HOME");
  const std::string previous = saved ? saved : "";
  ::setenv("HOME", (dir / "home").c_str(), 1);
  const std::string empty_home =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "home"); });
  ::setenv("HOME", previous.c_str(), 1);
  EXPECT_NE(empty_home.find("home folder"), std::string::npos) << empty_home;
  EXPECT_EQ(entries(dir), 1);
}

TEST(RunFolderTest, StagingNamesFitTheLimitAndKeepWholeCharacters) {
  EXPECT_EQ(mcrt::staging_name("out", 42), ".out.staging-42");
  const std::string longest(NAME_MAX, 'a');
  EXPECT_LE(mcrt::staging_name(longest, 4194304).size() + 9, std::size_t{NAME_MAX});  // -previous
  std::string accents;
  while (accents.size() < NAME_MAX - 1) accents += "\xc3\xa9";  // é, two bytes each
  const std::string name = mcrt::staging_name(accents, 123456);
  const std::size_t kept = name.size() - std::string(".staging-123456").size() - 1;
  EXPECT_EQ(kept % 2, 0u) << "a character cut in two";
}

// Issue 34: a folder name of 246 to 255 bytes failed, its staging name being too long.
TEST(RunFolderTest, AFolderNameOfTheLongestLengthWorks) {
  const fs::path dir = fresh_dir("long");
  const fs::path out = dir / std::string(NAME_MAX, 'x');
  finished_run(out, "a.txt", "a");
  finished_run(out, "b.txt", "b");
  EXPECT_EQ(read_text(out / "b.txt"), "b");
  EXPECT_FALSE(fs::exists(out / "a.txt"));
  EXPECT_EQ(entries(dir), 1);
}

// A pid no process has: a child that has exited and been waited for.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// Issue 34: staging folders of runs killed by SIGKILL piled up.
TEST(RunFolderTest, AKilledRunsStagingFolderIsRemovedAndNothingElse) {
  const fs::path dir = fresh_dir("stale");
  const pid_t gone = dead_pid();
  const fs::path killed = dir / mcrt::staging_name("out", gone);
  fs::create_directory(killed);
  write_text(killed / mcrt::k_manifest_name, std::string(mcrt::k_manifest_name) + "\n");
  write_text(killed / "image.pfm", "half");
  const fs::path empty = dir / (mcrt::staging_name("other", gone) + "-previous");
  fs::create_directory(empty);
  // Named like one, but without a manifest: not a run's, kept.
  const fs::path look_alike = dir / mcrt::staging_name("mine", gone);
  fs::create_directory(look_alike);
  write_text(look_alike / "thesis.tex", "precious");
  // A living process's: kept.
  const fs::path living = dir / mcrt::staging_name("out", ::getppid());
  fs::create_directory(living);
  { mcrt::RunFolder folder(dir / "out"); }
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_FALSE(fs::exists(empty));
  EXPECT_EQ(read_text(look_alike / "thesis.tex"), "precious");
  EXPECT_TRUE(fs::exists(living));
}

// An existing folder keeps its mode (a shared folder, setgid and sticky) when replaced.
TEST(RunFolderTest, AnExistingFolderKeepsItsMode) {
  const fs::path dir = fresh_dir("mode");
  fs::create_directory(dir / "out");
  ASSERT_EQ(::chmod((dir / "out").c_str(), 03777), 0);
  finished_run(dir / "out", "a.txt", "a");
  finished_run(dir / "out", "b.txt", "b");
  struct stat info {};
  ASSERT_EQ(::stat((dir / "out").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 03777u);
  EXPECT_EQ(read_text(dir / "out" / "b.txt"), "b");
  EXPECT_EQ(entries(dir / "out"), 3);  // summary.json, b.txt and the manifest
}

// Issue 34: an empty shared folder of another user, given as --out to root, was replaced by a
// root-owned 0755 folder. Root only (it needs a folder of another owner); skipped otherwise.
TEST(RunFolderTest, AnotherUsersFolderIsWrittenIntoAndKeepsItsOwner) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a folder another owner";
  const fs::path dir = fresh_dir("owner");
  fs::create_directory(dir / "shared");
  constexpr uid_t k_other = 65534;  // nobody
  ASSERT_EQ(::chown((dir / "shared").c_str(), k_other, k_other), 0);
  ASSERT_EQ(::chmod((dir / "shared").c_str(), 03777), 0);
  finished_run(dir / "shared", "a.txt", "a");
  finished_run(dir / "shared", "b.txt", "b");  // a second run replaces the first inside it
  {
    mcrt::RunFolder failed(dir / "shared");  // and a failed one leaves it as it was
    write_text(failed.staging() / "c.txt", "c");
  }
  struct stat info {};
  ASSERT_EQ(::stat((dir / "shared").c_str(), &info), 0);
  EXPECT_EQ(info.st_uid, k_other);
  EXPECT_EQ(info.st_mode & 07777, 03777u);
  EXPECT_EQ(read_text(dir / "shared" / "b.txt"), "b");
  EXPECT_FALSE(fs::exists(dir / "shared" / "a.txt"));
  EXPECT_EQ(entries(dir / "shared"), 3);  // summary.json, b.txt, the manifest: no staging left
  EXPECT_EQ(entries(dir), 1);
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
