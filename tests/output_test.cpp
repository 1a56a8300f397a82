// Writing outputs (common/io/output.hpp): a failed write or rename is an IoError naming the file
// and the system's real reason, and leaves no temporary file behind.

#include "io/output.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

// A fresh, empty folder for one test.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("mcrt_output_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

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
  std::ifstream file(dir / "a.txt", std::ios::binary);
  const std::string read((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(read, bytes);
  EXPECT_EQ(entries(dir), 1);
}

TEST(OutputTest, AFailedRenameGivesItsRealReasonAndRemovesTheTemporary) {
  const fs::path dir = fresh_dir("rename");
  fs::create_directories(dir / "target" / "inside");  // a non-empty folder cannot be replaced
  const fs::path from = dir / ".temporary";
  std::ofstream(from) << "new\n";
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
