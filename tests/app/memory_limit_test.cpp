// Memory is work too (common/app/memory_limit.hpp): a run over what the machine can give is
// refused with its estimate, a container's limit (cgroup v2 or v1) counts, and a failed
// allocation says what ran out.

#include "app/memory_limit.hpp"

#include <cmath>
#include <filesystem>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "support/temp_files.hpp"

namespace {

TEST(MemoryLimitTest, ARunOverWhatIsAvailableIsRefusedWithItsEstimate) {
  const double available = mcrt::available_memory_bytes();
  ASSERT_GT(available, 0.0);
  EXPECT_NO_THROW(mcrt::check_memory_limit({1e6, "a megabyte"}, "--width", "lower it"));
  try {
    mcrt::check_memory_limit({1e18, "an exabyte"}, "--width, --height", "lower them");
    FAIL() << "an exabyte was not refused";
  } catch (const mcrt::UsageError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--width, --height:", 0), 0u) << message;
    EXPECT_NE(message.find("1e+18 bytes"), std::string::npos) << message;
    EXPECT_NE(message.find("lower them"), std::string::npos) << message;
  }
}

// 2^50 bytes (a petabyte) is beyond any machine's address space: the allocation fails, and
// after a chapter's check it says so in words instead of a bare std::bad_alloc.
TEST(MemoryLimitTest, AFailedAllocationNamesItsCause) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's allocator ends the process on an impossible allocation "
                  "before any new handler runs";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "AddressSanitizer's allocator ends the process on an impossible allocation "
                  "before any new handler runs";
#endif
#endif
  mcrt::check_memory_limit({0.0, "nothing"}, "--width", "lower it");
  try {
    void* p = ::operator new (std::size_t{1} << 50);
    ::operator delete(p);
    FAIL() << "a petabyte was allocated";
  } catch (const std::bad_alloc& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out of memory: ", 0), 0u) << e.what();
  }
}

TEST(MemoryLimitTest, ImagesAreCountedAtTheirSizeInMemory) {
  const mcrt::MemoryUse use = mcrt::images_in_memory(1000.0, 3.0, 2, "3 images");
  // 64 MB base + 2 stacks of 8 MiB + 3 x 1000 pixels x 24 bytes.
  EXPECT_DOUBLE_EQ(use.bytes, 64e6 + 2 * 8.0 * 1024 * 1024 + 72000.0);
}

}  // namespace

namespace {

// A planted cgroup tree: `files` maps a path under the root to its contents.
std::filesystem::path cgroup_tree(const std::string& name,
                                  const std::vector<std::pair<std::string, std::string>>& files) {
  const std::filesystem::path root = mcrt::testing::fresh_temp_dir("memory_limit_test", name);
  for (const auto& [path, text] : files) {
    std::filesystem::create_directories((root / path).parent_path());
    mcrt::testing::write_text(root / path, text);
  }
  return root;
}

TEST(CgroupLimitTest, VersionTwoLeavesMaxLessCurrent) {
  EXPECT_EQ(mcrt::left_in_cgroup(
                cgroup_tree("v2", {{"memory.max", "1000000\n"}, {"memory.current", "250000\n"}})),
            750000.0);
  EXPECT_EQ(mcrt::left_in_cgroup(cgroup_tree("v2_unlimited", {{"memory.max", "max\n"},
                                                              {"memory.current", "250000\n"}})),
            HUGE_VAL);
}

// The OOM killer of a cgroup v1 container ended runs the check had let through (exit 137).
TEST(CgroupLimitTest, VersionOneIsReadToo) {
  EXPECT_EQ(mcrt::left_in_cgroup(cgroup_tree("v1", {{"memory/memory.limit_in_bytes", "2000000\n"},
                                                    {"memory/memory.usage_in_bytes", "500000\n"}})),
            1500000.0);
}

TEST(CgroupLimitTest, NoLimitOrAnUnreadableOneIsInfinity) {
  EXPECT_EQ(mcrt::left_in_cgroup(cgroup_tree("none", {})), HUGE_VAL);
  EXPECT_EQ(mcrt::left_in_cgroup(cgroup_tree("half", {{"memory.max", "1000000\n"}})), HUGE_VAL);
  EXPECT_EQ(mcrt::left_in_cgroup(
                cgroup_tree("used_up", {{"memory.max", "1000\n"}, {"memory.current", "5000\n"}})),
            0.0);
}

}  // namespace
