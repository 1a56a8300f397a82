#include "summary.hpp"

#include "output.hpp"

namespace mcrt {

void write_json(const std::filesystem::path& path, const Json& json) {
  write_file_atomic(path, json.dump(2) + "\n");
}

}  // namespace mcrt
