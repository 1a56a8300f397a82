// The output folder as a whole (common/app/run_folder.hpp): a run writes into a staging folder
// that replaces --out only when committed; a folder holding anything its manifest does not
// list is never replaced; a run that fails leaves nothing behind; a killed run's staging
// folder is removed by the next run, and nothing else is.

#include "app/run_folder.hpp"

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/cli.hpp"
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
  const std::string suffix = "0123456789abcdef";
  EXPECT_EQ(mcrt::staging_name("out", suffix), ".out.staging-0123456789abcdef");
  const std::string longest(NAME_MAX, 'a');
  EXPECT_LE(mcrt::staging_name(longest, suffix).size() + 9, std::size_t{NAME_MAX});  // -previous
  std::string accents;
  while (accents.size() < NAME_MAX - 1) accents += "\xc3\xa9";  // é, two bytes each
  const std::string name = mcrt::staging_name(accents, suffix);
  const std::size_t kept = name.size() - std::string(".staging-").size() - suffix.size() - 1;
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

// A staging folder as a run leaves it: a manifest listing itself and a half-written image.
fs::path staging_like(const fs::path& dir, const std::string& name) {
  fs::create_directory(dir / name);
  write_text(dir / name / mcrt::k_manifest_name, std::string(mcrt::k_manifest_name) + "\n");
  write_text(dir / name / "image.pfm", "half");
  return dir / name;
}

// Issue 43: staleness was judged by the pid in the name, so a live run of another PID
// namespace was taken for dead, and a user's `.draft.staging-999999` was deleted.
TEST(RunFolderTest, OnlyAnUnlockedStagingFolderOfOursIsRemoved) {
  const fs::path dir = fresh_dir("stale");
  const fs::path killed = staging_like(dir, mcrt::staging_name("out", "00000000deadbeef"));
  const fs::path set_aside =
      staging_like(dir, mcrt::staging_name("o", "00000000deadbeef") + "-previous");
  // A live run's, whatever its pid says: its manifest is locked (flock conflicts between two
  // opens even in one process, as it does between namespaces).
  const fs::path living = staging_like(dir, mcrt::staging_name("out", "0000000000000001"));
  const int lock = ::open((living / mcrt::k_manifest_name).c_str(), O_RDONLY);
  ASSERT_EQ(::flock(lock, LOCK_EX), 0);
  // Names the user chose, a run's manifest copied in or not: kept.
  const fs::path draft = staging_like(dir, ".draft.staging-999999");
  fs::create_directory(dir / ".notes.staging-999998");
  const fs::path no_manifest = dir / mcrt::staging_name("mine", "00000000deadbeef");
  fs::create_directory(no_manifest);
  write_text(no_manifest / "thesis.tex", "precious");
  { mcrt::RunFolder folder(dir / "out"); }
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_FALSE(fs::exists(set_aside));
  EXPECT_TRUE(fs::exists(living / "image.pfm"));
  EXPECT_TRUE(fs::exists(draft / "image.pfm"));
  EXPECT_TRUE(fs::exists(dir / ".notes.staging-999998"));
  EXPECT_EQ(read_text(no_manifest / "thesis.tex"), "precious");
  ::close(lock);
}

// The staging folder is marked live from its first moment: another run never removes it.
TEST(RunFolderTest, ALiveRunsStagingFolderIsKeptByAnother) {
  const fs::path dir = fresh_dir("live");
  mcrt::RunFolder first(dir / "a");
  write_text(first.staging() / "image.pfm", "being written");
  { mcrt::RunFolder second(dir / "b"); }
  EXPECT_EQ(read_text(first.staging() / "image.pfm"), "being written");
  first.commit();
  EXPECT_EQ(read_text(dir / "a" / "image.pfm"), "being written");
}

// An existing folder keeps its mode (setgid) when replaced.
TEST(RunFolderTest, AnExistingFolderKeepsItsMode) {
  const fs::path dir = fresh_dir("mode");
  fs::create_directory(dir / "out");
  ASSERT_EQ(::chmod((dir / "out").c_str(), 02750), 0);
  finished_run(dir / "out", "a.txt", "a");
  finished_run(dir / "out", "b.txt", "b");
  struct stat info {};
  ASSERT_EQ(::stat((dir / "out").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 02750u);
  EXPECT_EQ(read_text(dir / "out" / "b.txt"), "b");
  EXPECT_EQ(entries(dir / "out"), 3);  // summary.json, b.txt and the manifest
}

// Issue 43: a folder others can write (a shared 3777 one) is refused before anything is
// made, as git refuses a repository another user owns; it used to be written into.
TEST(RunFolderTest, AFolderOthersCanWriteIsRefusedAndKept) {
  const fs::path dir = fresh_dir("shared");
  finished_run(dir / "shared", "a.txt", "a");
  ASSERT_EQ(::chmod((dir / "shared").c_str(), 03777), 0);
  const std::string refusal =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder f(dir / "shared"); });
  EXPECT_NE(refusal.find("--out"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("other users"), std::string::npos) << refusal;
  EXPECT_EQ(read_text(dir / "shared" / "a.txt"), "a");
  EXPECT_EQ(entries(dir), 1);
  // Nor may a new --out be made in such a folder, unless its sticky bit keeps others from
  // renaming what the run makes (a root-owned /tmp).
  const fs::path open_parent = dir / "open";
  fs::create_directory(open_parent);
  ASSERT_EQ(::chmod(open_parent.c_str(), 0777), 0);
  EXPECT_NE(message_of<mcrt::UsageError>([&] { mcrt::RunFolder f(open_parent / "out"); }), "");
  EXPECT_EQ(entries(open_parent), 0);
  ASSERT_EQ(::chmod(open_parent.c_str(), 01777), 0);
  finished_run(open_parent / "out", "a.txt", "a");
  EXPECT_EQ(read_text(open_parent / "out" / "a.txt"), "a");
}

// Under umask 0 a new --out and its new parents were 0777, a folder the next run refuses.
TEST(RunFolderTest, UnderUmaskZeroNewFoldersAreNotWritableByOthers) {
  const fs::path dir = fresh_dir("umask");
  const mode_t previous = ::umask(0);
  finished_run(dir / "new" / "out", "a.txt", "a");
  finished_run(dir / "new" / "out", "b.txt", "b");  // accepted: its own folder
  ::umask(previous);
  for (const fs::path& folder : {dir / "new", dir / "new" / "out"}) {
    struct stat info {};
    ASSERT_EQ(::stat(folder.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & S_IWOTH, 0u) << folder;
  }
  EXPECT_EQ(read_text(dir / "new" / "out" / "b.txt"), "b");
}

// Issue 43: root wrote into another user's folders (a 3777 drop box, a new --out in their
// 0755 home), where their owner could swap the staging folder for links. Root only (it needs
// a folder of another owner); skipped otherwise.
TEST(RunFolderTest, AnotherUsersFolderIsRefusedAndKept) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a folder another owner";
  const fs::path dir = fresh_dir("owner");
  constexpr uid_t k_other = 65534;  // a uid that is not root's; no process of it is started
  fs::create_directory(dir / "dropbox");
  ASSERT_EQ(::chown((dir / "dropbox").c_str(), k_other, k_other), 0);
  ASSERT_EQ(::chmod((dir / "dropbox").c_str(), 0755), 0);
  const std::string refusal =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder f(dir / "dropbox"); });
  EXPECT_NE(refusal.find("another user"), std::string::npos) << refusal;
  EXPECT_NE(message_of<mcrt::UsageError>([&] { mcrt::RunFolder f(dir / "dropbox" / "out"); }), "");
  EXPECT_NE(message_of<mcrt::UsageError>([&] { mcrt::RunFolder f(dir / "dropbox" / "a" / "b"); }),
            "");
  EXPECT_EQ(entries(dir / "dropbox"), 0);
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
  const std::string file =
      message_of<mcrt::UsageError>([&] { mcrt::RunFolder folder(dir / "file"); });
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
