#include "geometry/nearest_dispatch.hpp"

#include "core/cpu_features.hpp"

namespace mcrt {

const bool Avx2Choice::k_has_avx2 = cpu_has_avx2();

}  // namespace mcrt
