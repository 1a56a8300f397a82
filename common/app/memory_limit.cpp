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

[[noreturn]] void throw_out_of_memory() { throw OutOfMemory(); }

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

// What a container's memory limit (cgroup v2: memory.max less memory.current) leaves;
// infinity outside one or without a limit.
double left_in_cgroup() {
  std::ifstream max_file("/sys/fs/cgroup/memory.max");
  std::ifstream current_file("/sys/fs/cgroup/memory.current");
  std::string max_text;
  double current = 0.0;
  if (!(max_file >> max_text) || max_text == "max" || !(current_file >> current)) return HUGE_VAL;
  try {
    return std::max(0.0, std::stod(max_text) - current);
  } catch (const std::exception&) {
    return HUGE_VAL;
  }
}

}  // namespace

double available_memory_bytes() {
  const double machine = proc_kilobytes("/proc/meminfo", "MemAvailable");
  const double address_space = left_under(RLIMIT_AS, proc_kilobytes("/proc/self/status", "VmSize"));
  const double data = left_under(RLIMIT_DATA, proc_kilobytes("/proc/self/status", "VmData"));
  return std::min({machine, left_in_cgroup(), address_space, data});
}

void check_memory_limit(const MemoryUse& use, std::string_view flags, std::string_view remedy) {
  std::set_new_handler(throw_out_of_memory);
  const double available = available_memory_bytes();
  if (use.bytes <= available) return;
  throw UsageError(fmt::format("{}: about {:.3g} bytes of memory ({}), over the {:.3g} bytes "
                               "available; {}",
                               flags, use.bytes, use.counted, available, remedy));
}

}  // namespace mcrt
