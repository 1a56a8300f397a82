#include "sampling/sobol_matrices.hpp"

#include <stdexcept>

#include <boost/random/sobol.hpp>

namespace mcrt {

namespace {

// Boost's engine enumerates the points in Gray-code order, starting after the zero point:
// seeding it with n gives the xor of the columns for the bits of gray(n + 1). Column b alone
// is gray(n + 1) = 2^b, that is n = 2^(b+1) - 2.
std::array<std::array<std::uint32_t, 32>, k_sobol_max_dimensions> read_columns() {
  boost::random::sobol_engine<std::uint32_t, 32> engine(k_sobol_max_dimensions);
  std::array<std::array<std::uint32_t, 32>, k_sobol_max_dimensions> columns{};
  for (unsigned b = 0; b < 32; ++b) {
    engine.seed(static_cast<std::uint32_t>((std::uint64_t{2} << b) - 2));
    for (unsigned j = 0; j < k_sobol_max_dimensions; ++j) columns[j][b] = engine();
  }
  return columns;
}

}  // namespace

const std::array<std::uint32_t, 32>& sobol_columns(unsigned dimension) {
  static const auto columns = read_columns();
  if (dimension >= k_sobol_max_dimensions)
    throw std::out_of_range("sobol_columns: more dimensions than the table holds");
  return columns[dimension];
}

}  // namespace mcrt
