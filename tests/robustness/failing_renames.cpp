// A disk that starts failing in the middle of a run, for the io-errors group: loaded with
// LD_PRELOAD, it lets the first MCRT_FAIL_RENAMES_AFTER renames (rename, renameat, renameat2)
// through and fails every later one with EIO, as a dying disk or a lost network mount does.
// Without the variable it changes nothing. Renames are where a run commits its files and its
// folder, so every step of the commit can be made to fail in turn.

#include <dlfcn.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>

namespace {

std::atomic<long> renames_so_far{0};

bool fail_this_rename() {
  const char* after = std::getenv("MCRT_FAIL_RENAMES_AFTER");
  if (after == nullptr) return false;
  if (renames_so_far.fetch_add(1) < std::atol(after)) return false;
  errno = EIO;
  return true;
}

template <typename Function>
Function real(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
}

}  // namespace

extern "C" {

int rename(const char* from, const char* to) {
  if (fail_this_rename()) return -1;
  static const auto next = real<int (*)(const char*, const char*)>("rename");
  return next(from, to);
}

int renameat(int from_dir, const char* from, int to_dir, const char* to) {
  if (fail_this_rename()) return -1;
  static const auto next = real<int (*)(int, const char*, int, const char*)>("renameat");
  return next(from_dir, from, to_dir, to);
}

int renameat2(int from_dir, const char* from, int to_dir, const char* to, unsigned flags) {
  if (fail_this_rename()) return -1;
  static const auto next = real<int (*)(int, const char*, int, const char*, unsigned)>("renameat2");
  return next(from_dir, from, to_dir, to, flags);
}

}  // extern "C"
