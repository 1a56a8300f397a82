// Writing outputs (common/io/output.hpp): a failed write or rename is an IoError naming the file
// and the system's real reason, and leaves no temporary file behind.

#include "io/output.hpp"

#include <filesystem>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "io/exclusive_file.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;
using namespace mcrt::testing;  // support/temp_files.hpp

namespace {

fs::path fresh_dir(const std::string& name) { return fresh_temp_dir("output_test", name); }

// The message of the IoError `write` throws, or "" if it throws none.
template <class Write>
std::string io_error(Write write) {
  try {
    write();
  } catch (const mcrt::IoError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputTest, WritesTheWholeFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("whole");
  const std::string bytes(100000, 'x');
  mcrt::write_file_atomic(dir / "a.txt", bytes);
  EXPECT_EQ(read_text(dir / "a.txt"), bytes);
  EXPECT_EQ(entries(dir), 1);
}

TEST(OutputTest, AFailedRenameGivesItsRealReasonAndRemovesTheTemporary) {
  const fs::path dir = fresh_dir("rename");
  fs::create_directories(dir / "target" / "inside");  // a non-empty folder cannot be replaced
  const std::string message = io_error([&] { mcrt::write_file_atomic(dir / "target", "new\n"); });
  EXPECT_NE(message.find((dir / "target").string()), std::string::npos) << message;
  EXPECT_EQ(message.find("Success"), std::string::npos) << message;
  EXPECT_TRUE(message.find("directory") != std::string::npos ||
              message.find("Directory") != std::string::npos)
      << message;
  EXPECT_EQ(entries(dir), 1);  // the temporary removed
}

TEST(OutputTest, AFailedWriteGivesItsRealReason) {
  const fs::path dir = fresh_dir("write");
  const fs::path missing = dir / "no_such_folder" / "a.txt";
  const std::string message = io_error([&] { mcrt::write_file_atomic(missing, "bytes"); });
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_EQ(message.find("disk full?"), std::string::npos) << message;
}

TEST(OutputTest, ADanglingLinkAsTheOutputFolderIsNamedAsSuch) {
  const fs::path dir = fresh_dir("dangling");
  fs::create_symlink(dir / "nowhere", dir / "out");
  const std::string message = io_error([&] { mcrt::prepare_output_dir(dir / "out"); });
  EXPECT_NE(message.find("dangling"), std::string::npos) << message;
}

// Issue 34: the temporary name was `.<name>.tmp-<pid>-<n>`, so another user could plant links
// under the next pids' names. It now holds 64 random bits and no pid.
TEST(OutputTest, TemporaryNamesCannotBeGuessed) {
  const fs::path dir = fresh_dir("names");
  const mcrt::NewFile one = mcrt::create_temporary(AT_FDCWD, dir / "summary.json");
  const mcrt::NewFile two = mcrt::create_temporary(AT_FDCWD, dir / "summary.json");
  ::close(one.fd);
  ::close(two.fd);
  const fs::path first = one.name, second = two.name;
  EXPECT_EQ(first.parent_path(), dir);  // beside it: rename() is atomic
  const std::string a = first.filename().string(), b = second.filename().string();
  EXPECT_EQ(a.rfind(".summary.json.tmp-", 0), 0u) << a;
  EXPECT_EQ(a.find(std::to_string(::getpid())), std::string::npos) << a;
  const std::size_t at = std::string(".summary.json.tmp-").size();
  EXPECT_NE(a.substr(at, 16), b.substr(at, 16)) << a << " " << b;  // not a counter
}

// Writing over a link replaces the link, never the file it points to.
TEST(OutputTest, AWriteReplacesALinkAndLeavesItsTargetAlone) {
  const fs::path dir = fresh_dir("link");
  write_text(dir / "victim", "precious");
  fs::create_symlink(dir / "victim", dir / "out.txt");
  mcrt::write_file_atomic(dir / "out.txt", "new");
  EXPECT_EQ(read_text(dir / "victim"), "precious");
  EXPECT_FALSE(fs::is_symlink(dir / "out.txt"));
  EXPECT_EQ(read_text(dir / "out.txt"), "new");
}

}  // namespace
