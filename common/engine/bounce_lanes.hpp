#pragma once
/// The bounce of estimate_path_radiance for four paths at once: from each lane's hit and two
/// uniforms, the direction sampled uniformly on the hemisphere, the path weight times
/// f_r cos(theta_i) / pdf, and the ray that leaves the hit in that direction.
///
/// A diffuse lane's f_r is rho / pi, computed on the four lanes together. A lane whose material
/// has a glossy lobe (the bit `lobed`) needs f_r(wi, wo, n) of its own directions: it is left
/// out of the four-lane weight and ray, and bounced last by the one-lane code (Material::f_r),
/// from the same wi, wo and n; so a scene without lobes pays two tests of `lobed` per bounce.
///
/// bounce_lanes_avx2 computes the four lanes with one instruction per operation, in the order
/// the one-path code does them (sample_uniform_hemisphere, cos_sin_two_pi, Frame, spawn_ray,
/// the weight update), without FMA, so every lane is the same bit for bit as the one-path code,
/// which bounce_lanes_portable runs lane by lane (tests/engine/path_tracer_lanes_test.cpp).

#include <cstdint>

#include "geometry/ray_lanes.hpp"

namespace mcrt {

inline constexpr int k_bounce_lanes = RayLanes::k_lanes;

/// Four paths at their hits, coordinate by coordinate: axis 0, 1, 2 are x, y, z.
struct BounceLanes {
  HitLanes hit;                                    ///< where the paths are (Scene::hits_in_lanes)
  alignas(32) double albedo[3][k_bounce_lanes]{};  ///< rho of the hit's material
  alignas(32) double u0[k_bounce_lanes]{}, u1[k_bounce_lanes]{};  ///< cos(theta) and phi / 2 pi
  alignas(32) double beta[3][k_bounce_lanes]{
      {1, 1, 1, 1},
      {1, 1, 1, 1},
      {1, 1, 1, 1}};  ///< the path weight (beta_0 = 1), updated in place
  alignas(32) std::int64_t bouncing[k_bounce_lanes]{};  ///< all bits set where the path goes on
  unsigned lobed = 0;  ///< bit l: lane l bounces off a material with a glossy lobe
  /// False only where no material has a lobe (the engine knows it from the scene): then
  /// shade_lanes_avx2 leaves `lobed` at 0 without looking at the lanes' materials.
  bool lobes_possible = true;
  double specular[k_bounce_lanes]{}, exponent[k_bounce_lanes]{};  ///< its rho_s and m, where lobed
};

/// For every bouncing lane, beta *= f_r cos(theta_i) / pdf and `rays` gets the new ray; the
/// other lanes of beta and rays are left as they are. `rays` holds the rays that reached the
/// hits (wo = -their direction). AVX2 where the processor has it.
void bounce_lanes(BounceLanes& lanes, RayLanes& rays);
/// One lane at a time, with the one-path functions.
void bounce_lanes_portable(BounceLanes& lanes, RayLanes& rays);
/// Four lanes per instruction; only call it where the processor has AVX2.
void bounce_lanes_avx2(BounceLanes& lanes, RayLanes& rays);

}  // namespace mcrt
