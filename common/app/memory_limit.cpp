#include "app/memory_limit.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <new>
#include <string>

#include <fmt/format.h>

#include <sys/resource.h>

#include "app/usage_error.hpp"

namespace mcrt {

namespace {

// A failed allocation, said in words: what ran out and what to lower.
class OutOfMemory : public std::bad_alloc {
 public:
  const char* what() const noexcept override {
    return "out of memory: an allocation failed (the machine or ulimit -v gives this run less "
           "than it needs); lower --width, --height or --threads";
  }
};

// A "Name: value kB" line of a /proc file, in bytes; infinity if absent.
double proc_kilobytes(const char* file, std::string_view name) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with(name) && line.size() > name.size() && line[name.size()] == ':') {
      try {
        return std::stod(line.substr(name.size() + 1)) * 1024.0;
      } catch (const std::exception&) {
        break;
      }
    }
  return HUGE_VAL;
}

// What a resource limit leaves beside `used` bytes; infinity without a limit.
double left_under(int resource, double used) {
  rlimit limit{};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return HUGE_VAL;
  return std::max(0.0, static_cast<double>(limit.rlim_cur) - (std::isfinite(used) ? used : 0.0));
}

// The first number in `file` (infinity if none, or "max").
double number_in(const std::filesystem::path& file) {
  std::ifstream in(file);
  double value = HUGE_VAL;
  return in >> value ? value : HUGE_VAL;
}

}  // namespace

double left_in_cgroup(const std::filesystem::path& root) {
  const auto left = [&](const char* limit, const char* used) {  // infinity unless both are read
    const double l = number_in(root / limit), u = number_in(root / used);
    return std::isfinite(l) && std::isfinite(u) ? std::max(0.0, l - u) : HUGE_VAL;
  };
  return std::min(left("memory.max", "memory.current"),
                  left("memory/memory.limit_in_bytes", "memory/memory.usage_in_bytes"));
}

double available_memory_bytes() {
  const double machine = proc_kilobytes("/proc/meminfo", "MemAvailable");
  const double address_space = left_under(RLIMIT_AS, proc_kilobytes("/proc/self/status", "VmSize"));
  const double data = left_under(RLIMIT_DATA, proc_kilobytes("/proc/self/status", "VmData"));
  return std::min({machine, left_in_cgroup(), address_space, data});
}

void check_memory_limit(const MemoryUse& use, std::string_view flags, std::string_view remedy) {
  std::set_new_handler([] { throw OutOfMemory(); });
  const double available = available_memory_bytes();
  if (use.bytes <= available) return;
  throw UsageError(
      fmt::format("{}: about {:.3g} bytes of memory ({}), over the {:.3g} bytes "
                  "available; {}",
                  flags, use.bytes, use.counted, available, remedy));
}

}  // namespace mcrt
