// The reference cache as one verified unit and the files it is made of (issue 34), a folder
// of its own that deletes only what it wrote (issue 43): a PFM whose header and size disagree refused before any
// allocation, a FIFO refused without blocking, temporaries that never follow a planted link,
// dead writers' temporaries removed and live ones kept, and a spoiled cache rendered again.

#include "app/reference_cache.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/cli.hpp"
#include "io/exclusive_file.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "support/temp_files.hpp"

namespace fs = std::filesystem;
using namespace mcrt::testing;  // support/temp_files.hpp

namespace {

fs::path fresh_dir(const std::string& name) { return fresh_temp_dir("reference_cache_test", name); }

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
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
  EXPECT_THROW(mcrt::check_reference_folder(parent / "link", ""), mcrt::UsageError);
  EXPECT_THROW(mcrt::load_or_render_reference(parent / "link", tiny_spec()), mcrt::UsageError);
  EXPECT_TRUE(fs::is_empty(parent / "real"));
  fs::permissions(parent / "real", fs::perms::all);  // 0777, no sticky bit
  EXPECT_THROW(mcrt::check_reference_folder(parent / "real", ""), mcrt::UsageError);
  fs::permissions(parent / "real", fs::perms::all | fs::perms::sticky_bit);  // like /tmp
  EXPECT_NO_THROW(mcrt::check_reference_folder(parent / "real", ""));
  EXPECT_NO_THROW(mcrt::check_reference_folder(parent / "missing", ""));
  EXPECT_TRUE(fs::is_regular_file(parent / "missing" / "CACHEDIR.TAG"));  // made and tagged
}

// The cache follows --out's rule of a folder of one's own (app/run_folder.hpp): one that
// another group can write is refused too. Root only: it needs a group the test is not in.
TEST(ReferenceCacheTest, AFolderAnotherGroupCanWriteIsRefused) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give a folder another group";
  const fs::path dir = fresh_dir("group") / "cache";
  fs::create_directory(dir);
  ASSERT_EQ(::chown(dir.c_str(), static_cast<uid_t>(-1), ::getegid() + 4242), 0);
  ASSERT_EQ(::chmod(dir.c_str(), 0775), 0);
  EXPECT_THROW(mcrt::check_reference_folder(dir, ""), mcrt::UsageError);
  EXPECT_TRUE(fs::is_empty(dir));
}

// The exact signature line of the Cache Directory Tagging convention.
TEST(ReferenceCacheTest, TheFolderIsTaggedAsACache) {
  const fs::path dir = fresh_dir("tagged") / "cache";
  mcrt::load_or_render_reference(dir, tiny_spec());
  EXPECT_EQ(read_text(dir / "CACHEDIR.TAG").substr(0, 44),
            "Signature: 8a477f597d28d172789f06886806bc55\n");
}

// A folder holding files and no tag (a user's pictures) is not a cache: refused, untouched.
TEST(ReferenceCacheTest, AnUntaggedFolderWithFilesIsRefused) {
  const fs::path dir = fresh_dir("untagged");
  write_bytes(dir / "holiday.pfm", "a user's picture");
  write_bytes(dir / ".notes.tmp-draft", "a user's draft");
  try {
    mcrt::check_reference_folder(dir, "");
    ADD_FAILURE() << "an untagged folder with files was accepted";
  } catch (const mcrt::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--reference-dir"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("CACHEDIR.TAG"), std::string::npos) << e.what();
  }
  EXPECT_THROW(mcrt::load_or_render_reference(dir, tiny_spec()), mcrt::UsageError);
  EXPECT_EQ(read_text(dir / "holiday.pfm"), "a user's picture");
  EXPECT_EQ(read_text(dir / ".notes.tmp-draft"), "a user's draft");
  EXPECT_FALSE(fs::exists(dir / "CACHEDIR.TAG"));
}

// Each run replaces --out whole: a cache inside it (or a run inside the cache) is refused.
TEST(ReferenceCacheTest, ACacheAndAnOutputInsideOneAnotherAreRefused) {
  const fs::path parent = fresh_dir("nested");
  EXPECT_THROW(mcrt::check_reference_folder(parent / "run" / "cache", parent / "run"),
               mcrt::UsageError);
  EXPECT_THROW(mcrt::check_reference_folder(parent / "cache", parent / "cache" / "run"),
               mcrt::UsageError);
  EXPECT_THROW(mcrt::check_reference_folder(parent / "same", parent / "same/."), mcrt::UsageError);
  EXPECT_FALSE(fs::exists(parent / "run"));
  EXPECT_NO_THROW(mcrt::check_reference_folder(parent / "cache", parent / "cache-run"));
}

// $XDG_CACHE_HOME/mcrt-companion (absolute only), else ~/.cache/mcrt-companion, else refused.
TEST(ReferenceCacheTest, TheDefaultFolderFollowsTheXdgBaseDirectories) {
  const auto saved = [](const char* name) -> std::optional<std::string> {
    const char* value = std::getenv(name);
    return value ? std::optional<std::string>(value) : std::nullopt;
  };
  const std::optional<std::string> xdg = saved("XDG_CACHE_HOME"), home = saved("HOME");
  ::setenv("XDG_CACHE_HOME", "/x/cache", 1);
  ::setenv("HOME", "/h", 1);
  EXPECT_EQ(mcrt::reference_folder(""), fs::path("/x/cache/mcrt-companion"));
  EXPECT_EQ(mcrt::reference_folder("mine"), fs::path("mine"));
  ::setenv("XDG_CACHE_HOME", "relative", 1);  // ignored, as the specification says
  EXPECT_EQ(mcrt::reference_folder(""), fs::path("/h/.cache/mcrt-companion"));
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(mcrt::reference_folder(""), fs::path("/h/.cache/mcrt-companion"));
  ::unsetenv("HOME");
  EXPECT_THROW(mcrt::reference_folder(""), mcrt::UsageError);
  EXPECT_EQ(mcrt::reference_folder("mine"), fs::path("mine"));
  if (xdg) ::setenv("XDG_CACHE_HOME", xdg->c_str(), 1);
  if (home) ::setenv("HOME", home->c_str(), 1);
}

// Only files the index names are ever deleted: a user's files planted in the cache stay, a
// dead writer's temporary the index names goes, a live writer's (its lock held) stays, and a
// PFM the index names whose JSON is gone goes.
TEST(ReferenceCacheTest, OnlyFilesTheIndexNamesAreDeleted) {
  const fs::path dir = fresh_dir("index") / "cache";
  const mcrt::ReferenceSpec spec = tiny_spec();
  mcrt::load_or_render_reference(dir, spec);
  const std::string stem = mcrt::reference_stem(spec);
  for (const char* name : {"ground_truth_4096spp.pfm", ".notes.tmp-draft",
                           ".cornell_ls1_4x3.pfm.tmp-0123456789abcdef", "measured.pfm"})
    write_bytes(dir / name, "a user's file");
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(dir_fd, 0);
  const mcrt::NewFile dead = mcrt::create_temporary(dir_fd, stem + ".pfm");
  const mcrt::NewFile live = mcrt::create_temporary(dir_fd, stem + ".json");
  ASSERT_GE(dead.fd, 0);
  ASSERT_GE(live.fd, 0);
  ::close(dead.fd);  // its writer died: the lock is free
  std::ofstream(dir / "index.txt", std::ios::app) << dead.name << "\n" << live.name << "\n";
  const mcrt::Reference cached = mcrt::load_or_render_reference(dir, spec);
  EXPECT_FALSE(cached.rendered);
  EXPECT_FALSE(fs::exists(dir / dead.name));
  EXPECT_TRUE(fs::exists(dir / live.name));
  for (const char* name : {"ground_truth_4096spp.pfm", ".notes.tmp-draft",
                           ".cornell_ls1_4x3.pfm.tmp-0123456789abcdef", "measured.pfm"})
    EXPECT_EQ(read_text(dir / name), "a user's file") << name;
  ::close(live.fd);
  ::close(dir_fd);
  fs::remove(dir / (stem + ".json"));  // a writer killed between its two renames
  const mcrt::Reference again = mcrt::load_or_render_reference(dir, spec);
  EXPECT_TRUE(again.rendered);
  EXPECT_TRUE(fs::exists(dir / (stem + ".json")));
  EXPECT_EQ(read_text(dir / "ground_truth_4096spp.pfm"), "a user's file");
}

// Out of descriptors (EMFILE) at every step of a read and a write: the valid entry stays. With
// k descriptors free for k = 0..15, every open of the cache fails in turn (15 is more than a
// whole read and write take: the last runs succeed).
TEST(ReferenceCacheTest, RunningOutOfDescriptorsNeverDeletesAValidEntry) {
  const fs::path dir = fresh_dir("emfile") / "cache";
  const mcrt::ReferenceSpec spec = tiny_spec();
  const mcrt::Reference first = mcrt::load_or_render_reference(dir, spec);
  const std::string pfm = read_text(dir / (mcrt::reference_stem(spec) + ".pfm"));
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_NOFILE, &saved), 0);
  // Under the sanitizers, UBSan's vptr check tests memory through a pipe of its own: with
  // fewer than two descriptors free it reports a valid exception object as invalid. Those
  // counts are covered by the plain build.
#if defined(__SANITIZE_ADDRESS__)
  constexpr rlim_t k_fewest_free = 2;
#else
  constexpr rlim_t k_fewest_free = 0;
#endif
  for (rlim_t free = k_fewest_free; free <= 15; ++free) {
    const int lowest = ::open("/dev/null", O_RDONLY);  // the lowest free descriptor
    ASSERT_GE(lowest, 0);
    ::close(lowest);
    rlimit limited = saved;
    limited.rlim_cur = static_cast<rlim_t>(lowest) + free;
    ASSERT_EQ(::setrlimit(RLIMIT_NOFILE, &limited), 0);
    try {
      mcrt::load_or_render_reference(dir, spec);
    } catch (const std::exception&) {  // a failure is allowed; a lost entry is not
    }
    ::setrlimit(RLIMIT_NOFILE, &saved);
    const mcrt::Reference after = mcrt::load_or_render_reference(dir, spec);
    EXPECT_FALSE(after.rendered) << "the entry was lost with " << free << " descriptors free";
    EXPECT_EQ(after.image.pixels, first.image.pixels);
    EXPECT_EQ(read_text(dir / (mcrt::reference_stem(spec) + ".pfm")), pfm);
  }
}

}  // namespace
