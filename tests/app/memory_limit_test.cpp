// Memory is work too (common/app/memory_limit.hpp): a run over what the machine can give is
// refused with its estimate, and a failed allocation says what ran out.

#include "app/memory_limit.hpp"

#include <cmath>
#include <new>
#include <string>

#include <gtest/gtest.h>

#include "app/cli.hpp"

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
    void* p = ::operator new(std::size_t{1} << 50);
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
