// The reference cache as one verified unit and the files it is made of (issue 34): SHA-256
// against the standard's examples, a PFM whose header and size disagree refused before any
// allocation, a FIFO refused without blocking, temporaries that never follow a planted link,
// dead writers' temporaries removed and live ones kept, and a spoiled cache rendered again.

#include "io/reference_cache.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/cli.hpp"
#include "io/exclusive_file.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/sha256.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;
using namespace mcrt::testing;  // support/temp_files.hpp

namespace {

fs::path fresh_dir(const std::string& name) { return fresh_temp_dir("reference_cache_test", name); }

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The examples of FIPS 180-4's appendix, and lengths on both sides of the padding's edges
// (55, 56 and 64 bytes fill one block, spill into a second, and fill one exactly).
TEST(Sha256Test, MatchesTheStandardsExamples) {
  EXPECT_EQ(mcrt::sha256_hex(""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(mcrt::sha256_hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(mcrt::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(mcrt::sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(mcrt::sha256_hex(std::string(55, 'a')),
            "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  EXPECT_EQ(mcrt::sha256_hex(std::string(64, 'a')),
            "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
}

// A 30-byte file whose header claims 10000 x 10000 pixels (1.2 GB of floats) is refused at
// once: the size is compared before anything is allocated.
TEST(PfmTest, AHeaderLargerThanItsFileIsRefusedBeforeAllocating) {
  const std::string bytes = std::string("PF\n10000 10000\n-1.0\n") + std::string(10, '\0');
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(mcrt::decode_pfm(bytes, "huge.pfm"), mcrt::IoError);
  const fs::path dir = fresh_dir("huge");
  write_bytes(dir / "huge.pfm", bytes);
  EXPECT_THROW(mcrt::read_pfm(dir / "huge.pfm"), mcrt::IoError);
  // Allocating and filling 1.2 GB takes seconds; a refusal takes microseconds.
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(500));
}

TEST(PfmTest, TrailingBytesAreRefusedAndAWholeFileReadsBack) {
  mcrt::Image image(3, 2, mcrt::Color(0.25, 0.5, 2.0));
  const std::string bytes = mcrt::encode_pfm(image);
  EXPECT_EQ(mcrt::decode_pfm(bytes, "a.pfm").pixels, image.pixels);
  EXPECT_THROW(mcrt::decode_pfm(bytes + std::string(12, '\0'), "a.pfm"), mcrt::IoError);
  EXPECT_THROW(mcrt::decode_pfm(bytes.substr(0, bytes.size() - 1), "a.pfm"), mcrt::IoError);
}

// Opening a FIFO for reading waits for a writer: it must be refused without being opened.
TEST(PfmTest, AFifoIsRefusedWithoutBlocking) {
  const fs::path dir = fresh_dir("fifo");
  ASSERT_EQ(::mkfifo((dir / "a.pfm").c_str(), 0644), 0);
  EXPECT_THROW(mcrt::read_pfm(dir / "a.pfm"), mcrt::IoError);
}

// A link planted under any name a writer might use is never written through: the writer's
// name is new each time and created with O_EXCL|O_NOFOLLOW.
TEST(ExclusiveFileTest, TemporariesNeverFollowAPlantedLink) {
  const fs::path dir = fresh_dir("links");
  write_bytes(dir / "victim", "precious");
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(dir_fd, 0);
  const mcrt::NewFile a = mcrt::create_temporary(dir_fd, "x.pfm");
  const mcrt::NewFile b = mcrt::create_temporary(dir_fd, "x.pfm");
  ASSERT_GE(a.fd, 0);
  ASSERT_GE(b.fd, 0);
  EXPECT_NE(a.name, b.name);
  struct stat status {};
  ASSERT_EQ(::fstat(a.fd, &status), 0);
  EXPECT_EQ(status.st_mode & 022, 0u);  // nobody else may write it
  ::close(a.fd);
  ::close(b.fd);
  // A link under a name already drawn: the open fails rather than follows it.
  ::unlinkat(dir_fd, a.name.c_str(), 0);
  fs::create_symlink(dir / "victim", dir / a.name);
  EXPECT_LT(::openat(dir_fd, a.name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644), 0);
  // Every file of a run goes through write_file_atomic: many writes, the victim untouched.
  for (int i = 0; i < 50; ++i) mcrt::write_file_atomic(dir / "x.pfm", "new bytes");
  EXPECT_EQ(read_text(dir / "victim"), "precious");
  ::close(dir_fd);
}

// A dead writer's temporary (its lock free) is removed; a live writer's (its lock held) stays.
TEST(ExclusiveFileTest, OnlyDeadWritersTemporariesAreRemoved) {
  const fs::path dir = fresh_dir("leftovers");
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(dir_fd, 0);
  write_bytes(dir / ".a.pfm.tmp-1234-0", "dead");
  fs::create_symlink("/nonexistent", dir / ".a.json.tmp-99");
  const mcrt::NewFile live = mcrt::create_temporary(dir_fd, "b.pfm");
  ASSERT_GE(live.fd, 0);
  write_bytes(dir / "kept.pfm", "not a temporary");
  EXPECT_EQ(mcrt::remove_abandoned_temporaries(dir_fd), 2);
  EXPECT_TRUE(fs::exists(dir / live.name));
  EXPECT_TRUE(fs::exists(dir / "kept.pfm"));
  EXPECT_FALSE(fs::exists(dir / ".a.pfm.tmp-1234-0"));
  ::close(live.fd);
  EXPECT_EQ(mcrt::remove_abandoned_temporaries(dir_fd), 1);  // its writer is gone now
  ::close(dir_fd);
}

mcrt::ReferenceSpec tiny_spec() {
  mcrt::ReferenceSpec spec;
  spec.scene.scene = "cornell";
  spec.width = 4;
  spec.height = 3;
  spec.spp = 4;
  spec.quiet = true;
  return spec;
}

// A cache written, read back as it was, and a spoiled one (NaN with a matching hash, a value
// changed without one) rendered again into the same reference.
TEST(ReferenceCacheTest, ACacheIsUsedOnlyWhenItVerifies) {
  const fs::path dir = fresh_dir("cache") / "reference";
  const mcrt::ReferenceSpec spec = tiny_spec();
  const mcrt::Reference first = mcrt::load_or_render_reference(dir, spec);
  EXPECT_TRUE(first.rendered);
  const mcrt::Reference cached = mcrt::load_or_render_reference(dir, spec);
  EXPECT_FALSE(cached.rendered);
  EXPECT_EQ(cached.image.pixels, first.image.pixels);
  EXPECT_FALSE(cached.info.contains("pfm"));  // the hash stays in the cache's own JSON

  const fs::path pfm = dir / (mcrt::reference_stem(spec) + ".pfm");
  std::string bytes = read_text(pfm);
  bytes[bytes.size() - 1] ^= 0x01;  // one bit of one value
  write_bytes(pfm, bytes);
  const mcrt::Reference again = mcrt::load_or_render_reference(dir, spec);
  EXPECT_TRUE(again.rendered);
  EXPECT_EQ(again.image.pixels, first.image.pixels);
}

TEST(ReferenceCacheTest, ALinkOrAnOpenFolderIsRefusedWithExitTwo) {
  const fs::path parent = fresh_dir("refused");
  fs::create_directory(parent / "real");
  fs::create_directory_symlink(parent / "real", parent / "link");
  EXPECT_THROW(mcrt::check_reference_folder(parent / "link"), mcrt::UsageError);
  EXPECT_THROW(mcrt::load_or_render_reference(parent / "link", tiny_spec()), mcrt::UsageError);
  EXPECT_TRUE(fs::is_empty(parent / "real"));
  fs::permissions(parent / "real", fs::perms::all);  // 0777, no sticky bit
  EXPECT_THROW(mcrt::check_reference_folder(parent / "real"), mcrt::UsageError);
  fs::permissions(parent / "real", fs::perms::all | fs::perms::sticky_bit);  // like /tmp
  EXPECT_NO_THROW(mcrt::check_reference_folder(parent / "real"));
  EXPECT_NO_THROW(mcrt::check_reference_folder(parent / "missing"));  // created when written
}

}  // namespace
