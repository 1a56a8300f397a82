// Writing outputs (common/io/output.hpp): a failed write or rename is an IoError naming the file
// and the system's real reason, and leaves no temporary file behind.

#include "io/output.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

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
  const fs::path from = dir / ".temporary";
  write_text(from, "new\n");
  const std::string message = io_error([&] { mcrt::commit_file(from, dir / "target"); });
  EXPECT_NE(message.find((dir / "target").string()), std::string::npos) << message;
  EXPECT_EQ(message.find("Success"), std::string::npos) << message;
  EXPECT_TRUE(message.find("directory") != std::string::npos ||
              message.find("Directory") != std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(from));
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

}  // namespace
