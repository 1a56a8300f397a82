#pragma once
/// Four paths between their searches, one per lane: the lines of estimate_path_radiance's loop
/// around the search and the bounce, for four paths at once.
///
///   scene.hits_in_lanes(...)     the four closest hits
///   shade_lanes(...)             radiance += beta Le; stop at the depth cut; two uniforms
///   bounce_lanes(...)            beta *= f_r cos / pdf; the next rays
///   end_lanes(...)               stop on a black weight; which paths ended
///
/// shade_lanes_avx2 and end_lanes_avx2 do each line for the four lanes with one instruction per
/// operation, in the one-path code's order, so every lane keeps the one-path code's bits; the
/// portable versions run the lanes one at a time (tests/engine/path_lanes_test.cpp).

#include <cstdint>
#include <span>

#include "core/pcg32_lanes.hpp"
#include "core/rng.hpp"
#include "engine/bounce_lanes.hpp"
#include "render/material.hpp"

namespace mcrt {

/// Each lane's path: what it has gathered, how far it has gone, and its generator. A lane is
/// ready for a new path when its radiance and depth are 0 and its weight in BounceLanes is 1:
/// so it starts, and so end_lanes leaves every lane whose path ended.
struct PathLanes {
  static constexpr int k_lanes = k_bounce_lanes;
  alignas(32) double radiance[3][k_lanes]{};  ///< the estimate so far, axis by axis
  alignas(32) double finished[3][k_lanes]{};  ///< the estimates of the paths end_lanes ended
  alignas(32) std::int64_t depth[k_lanes]{};  ///< bounces taken
  alignas(32) std::int64_t live[k_lanes]{};   ///< all bits set where the lane holds a path
  Pcg32Lanes<k_lanes> rng;                    ///< lane l draws the numbers of its path's Rng

  /// Lane l, ready for a new path, starts the one whose generator is Rng(seed, stream).
  void start(int l, std::uint64_t seed, std::uint64_t stream) {
    if (live[l] == 0) live[l] = -1;  // written only when it changes (the next read is a vector)
    rng.seed_lane(l, Rng::starting_state(seed, stream), stream);
  }
  /// Lane l, ready for a new path, starts one whose generator is PCG32 at (state, increment):
  /// a start of engine/path_starts.hpp, its camera ray's two draws made.
  void start_at(int l, std::uint64_t state, std::uint64_t increment) {
    if (live[l] == 0) live[l] = -1;
    rng.state[l] = state;
    rng.increment[l] = increment;
  }
  /// Lane l holds no path.
  void stop(int l) { live[l] = 0; }
  /// Rng::uniform2() of lane l's generator: two draws of 32 bits, each times 2^-32.
  Vec2 uniform2(int l) {
    const double u0 = rng.next(l) * 0x1p-32;
    return {u0, rng.next(l) * 0x1p-32};
  }
  Color finished_of(int l) const { return {finished[0][l], finished[1][l], finished[2][l]}; }
  /// The lanes that hold a path, as bits 0-3.
  unsigned live_lanes() const {
    unsigned bits = 0;
    for (int l = 0; l < k_lanes; ++l) bits |= static_cast<unsigned>(live[l] != 0) << l;
    return bits;
  }
};

/// For every live lane whose ray hit: radiance += beta Le(hit). The lane bounces (bounce.bouncing)
/// unless its depth is max_depth; a bouncing lane gets its material's albedo (and its lobe, with
/// its bit in bounce.lobed, if it has one) and two uniforms,
/// drawn as Rng::uniform2 draws them. (Every lane's generator draws its two numbers: a lane
/// that does not bounce ends its path, and its next path reseeds it.) AVX2 where the
/// processor has it.
void shade_lanes(std::span<const Material> materials, int max_depth, PathLanes& paths,
                 BounceLanes& bounce);
void shade_lanes_portable(std::span<const Material> materials, int max_depth, PathLanes& paths,
                          BounceLanes& bounce);
void shade_lanes_avx2(std::span<const Material> materials, int max_depth, PathLanes& paths,
                      BounceLanes& bounce);

/// After bounce_lanes: a bouncing lane whose weight is not black goes on, and its depth goes up
/// by one. The live lanes that do not go on are returned, as bits 0-3: their paths have ended
/// (no hit, the depth cut, or a black weight), and their estimates are in `finished`. Every
/// lane that does not go on is made ready for a new path. AVX2 where the processor has it.
unsigned end_lanes(PathLanes& paths, BounceLanes& bounce);
unsigned end_lanes_portable(PathLanes& paths, BounceLanes& bounce);
unsigned end_lanes_avx2(PathLanes& paths, BounceLanes& bounce);

}  // namespace mcrt
