#include "engine/bounce_lanes.hpp"

#include "core/cpu_features.hpp"
#include "geometry/hit.hpp"
#include "render/material.hpp"
#include "sampling/sampling.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace mcrt {

// ASSIGNMENT a4.1 BEGIN needs=a2.1 withheld stub: void bounce_lanes(BounceLanes&, RayLanes&) { NOT_IMPLEMENTED(bounce_lanes); } void bounce_lanes_portable(BounceLanes&, RayLanes&) { NOT_IMPLEMENTED(bounce_lanes_portable); } void bounce_lanes_avx2(BounceLanes&, RayLanes&) { NOT_IMPLEMENTED(bounce_lanes_avx2); }
namespace {

Vec3 lane_of(const double (&v)[3][k_bounce_lanes], int l) { return {v[0][l], v[1][l], v[2][l]}; }

// Lane l's material as shade_lanes left it: its albedo, and its lobe where the lane is lobed.
Material material_of(const BounceLanes& lanes, int l) {
  Material m;
  m.albedo = lane_of(lanes.albedo, l);
  if ((lanes.lobed >> l) & 1u) {
    m.specular = lanes.specular[l];
    m.exponent = lanes.exponent[l];
  }
  return m;
}

// beta f_r(wi, wo, n) cos(theta_i) / pdf for lane l, wo from the ray that reached its hit: the
// one-path loop's line, in its order.
Color bounced_weight(const BounceLanes& lanes, const RayLanes& rays, int l, const Vec3& wi,
                     double cos_theta_i) {
  const Vec3 wo = -rays.get(l).direction;
  const Color brdf = material_of(lanes, l).f_r(wi, wo, lane_of(lanes.hit.normal, l));
  return lane_of(lanes.beta, l) * (brdf * cos_theta_i / uniform_hemisphere_pdf());
}

// The lines of estimate_path_radiance after the emission, for lane l: its direction, its weight
// beta f_r cos / pdf and its new ray.
void bounce_one_lane(BounceLanes& lanes, RayLanes& rays, int l) {
  const Vec3 normal = lane_of(lanes.hit.normal, l);
  const Vec3 local = sample_uniform_hemisphere({lanes.u0[l], lanes.u1[l]});
  const Vec3 wi = Frame(normal).to_world(local);
  const double cos_theta_i = local.z;
  const Color beta = bounced_weight(lanes, rays, l, wi, cos_theta_i);
  for (int axis = 0; axis < 3; ++axis) lanes.beta[axis][l] = beta[axis];
  Hit hit;
  hit.point = lane_of(lanes.hit.point, l);
  hit.normal = normal;
  rays.set(l, spawn_ray(hit, wi));
}

// The bouncing lanes whose material has a lobe, one at a time by the one-path code (its
// direction is the four-lane sampler's, bit for bit). Out of line and called last, so that
// the four-lane bounce of a diffuse scene keeps its own code and registers.
[[gnu::noinline]] void bounce_lobed_lanes(BounceLanes& lanes, RayLanes& rays) {
  for (int l = 0; l < k_bounce_lanes; ++l)
    if (((lanes.lobed >> l) & 1u) != 0 && lanes.bouncing[l] != 0) bounce_one_lane(lanes, rays, l);
}

}  // namespace

void bounce_lanes(BounceLanes& lanes, RayLanes& rays) {
  static const bool avx2 = cpu_has_avx2();
  if (avx2)
    bounce_lanes_avx2(lanes, rays);
  else
    bounce_lanes_portable(lanes, rays);
}

// The lines of estimate_path_radiance after the emission, lane by lane.
void bounce_lanes_portable(BounceLanes& lanes, RayLanes& rays) {
  for (int l = 0; l < k_bounce_lanes; ++l)
    if (lanes.bouncing[l] != 0) bounce_one_lane(lanes, rays, l);
}

#if defined(__x86_64__)

namespace {

// Each helper is the one-path code's expression on four lanes: same operations, same order.
using D4 = __m256d;

[[gnu::target("avx2")]] inline D4 load(const double* p) { return _mm256_load_pd(p); }
[[gnu::target("avx2")]] inline D4 broadcast(double x) { return _mm256_set1_pd(x); }
[[gnu::target("avx2")]] inline D4 add(D4 a, D4 b) { return _mm256_add_pd(a, b); }
[[gnu::target("avx2")]] inline D4 sub(D4 a, D4 b) { return _mm256_sub_pd(a, b); }
[[gnu::target("avx2")]] inline D4 mul(D4 a, D4 b) { return _mm256_mul_pd(a, b); }
[[gnu::target("avx2")]] inline D4 div(D4 a, D4 b) { return _mm256_div_pd(a, b); }
// where ? a : b, lane by lane (where: all bits set or clear).
[[gnu::target("avx2")]] inline D4 select(D4 where, D4 a, D4 b) {
  return _mm256_blendv_pd(b, a, where);
}
// glm::dot's order: (x1 y1 + x2 y2) + x3 y3.
[[gnu::target("avx2")]] inline D4 dot(D4 x1, D4 x2, D4 x3, D4 y1, D4 y2, D4 y3) {
  return add(add(mul(x1, y1), mul(x2, y2)), mul(x3, y3));
}
// std::max(a, b) = a < b ? b : a, which is _mm256_max_pd(b, a) (it returns its second
// operand unless the first is greater), NaN included.
[[gnu::target("avx2")]] inline D4 std_max(D4 a, D4 b) { return _mm256_max_pd(b, a); }
// to[l] = value[l] in the lanes where `where` is set; the others keep theirs.
[[gnu::target("avx2")]] inline void store_where(D4 where, double* to, D4 value) {
  _mm256_store_pd(to, select(where, value, load(to)));
}
[[gnu::target("avx2")]] inline D4 abs(D4 a) { return _mm256_andnot_pd(broadcast(-0.0), a); }
// -a: the sign bit flipped, as unary minus does (0 - a would turn -0 into +0, not into -(-0)).
[[gnu::target("avx2")]] inline D4 negate(D4 a) { return _mm256_xor_pd(broadcast(-0.0), a); }

// One step of Horner's rule: k + x2 c.
[[gnu::target("avx2")]] inline D4 term(D4 x2, D4 c, double k) {
  return add(broadcast(k), mul(x2, c));
}

// cos_sin_two_pi on four lanes (core/cos_sin.hpp): the quarter turn q picks the signs and the
// order of (cos x, sin x) by selects instead of tables.
[[gnu::target("avx2")]] inline void cos_sin_two_pi(D4 u, D4& cos_out, D4& sin_out) {
  const D4 quarters = mul(broadcast(4.0), u);
  const __m128i q = _mm256_cvttpd_epi32(add(quarters, broadcast(0.5)));  // u >= 0: truncation
  const D4 x = mul(sub(quarters, _mm256_cvtepi32_pd(q)), broadcast(0.5 * k_pi));
  const D4 x2 = mul(x, x);
  const D4 sin_x = add(
      x, mul(mul(x, x2),
             term(x2,
                  term(x2,
                       term(x2,
                            term(x2,
                                 term(x2,
                                      term(x2, broadcast(-1.0 / 1307674368000.0), 1.0 / 6227020800),
                                      -1.0 / 39916800),
                                 1.0 / 362880),
                            -1.0 / 5040),
                       1.0 / 120),
                  -1.0 / 6)));
  const D4 cos_x = term(x2,
                        term(x2,
                             term(x2,
                                  term(x2,
                                       term(x2,
                                            term(x2,
                                                 term(x2,
                                                      term(x2, broadcast(1.0 / 20922789888000.0),
                                                           -1.0 / 87178291200.0),
                                                      1.0 / 479001600),
                                                 -1.0 / 3628800),
                                            1.0 / 40320),
                                       -1.0 / 720),
                                  1.0 / 24),
                             -1.0 / 2),
                        1.0);
  // q mod 4 = 0, 1, 2, 3: cos takes cos x, -sin x, -cos x, sin x; sin takes sin x, cos x,
  // -sin x, -cos x. The signs are +-1.0 factors, as in the one-lane tables.
  const __m128i one = _mm_set1_epi32(1), two = _mm_set1_epi32(2);
  const D4 swapped =
      _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm_cmpeq_epi32(_mm_and_si128(q, one), one)));
  const D4 cos_sign =
      _mm256_cvtepi32_pd(_mm_sub_epi32(one, _mm_and_si128(_mm_add_epi32(q, one), two)));
  const D4 sin_sign = _mm256_cvtepi32_pd(_mm_sub_epi32(one, _mm_and_si128(q, two)));
  cos_out = mul(cos_sign, select(swapped, sin_x, cos_x));
  sin_out = mul(sin_sign, select(swapped, cos_x, sin_x));
}

}  // namespace

[[gnu::target("avx2")]] void bounce_lanes_avx2(BounceLanes& lanes, RayLanes& rays) {
  const D4 one = broadcast(1.0), zero = _mm256_setzero_pd();
  // sample_uniform_hemisphere: cos(theta) = u0, sin(theta) = sqrt(max(0, 1 - cos^2)).
  const D4 cos_theta = load(lanes.u0);
  const D4 sin_theta = _mm256_sqrt_pd(std_max(zero, sub(one, mul(cos_theta, cos_theta))));
  D4 cos_phi, sin_phi;
  cos_sin_two_pi(load(lanes.u1), cos_phi, sin_phi);
  const D4 lx = mul(sin_theta, cos_phi), ly = mul(sin_theta, sin_phi), lz = cos_theta;

  // Frame(n): sign = copysign(1, n.z), a = -1 / (sign + n.z), b = n.x n.y a.
  const D4 nx = load(lanes.hit.normal[0]), ny = load(lanes.hit.normal[1]),
           nz = load(lanes.hit.normal[2]);
  const D4 sign = _mm256_or_pd(_mm256_and_pd(broadcast(-0.0), nz), one);
  const D4 a = div(broadcast(-1.0), add(sign, nz));
  const D4 b = mul(mul(nx, ny), a);
  const D4 tx = add(one, mul(mul(mul(sign, nx), nx), a)), ty = mul(sign, b),
           tz = mul(negate(sign), nx);
  const D4 bx = b, by = add(sign, mul(mul(ny, ny), a)), bz = negate(ny);
  // Frame::to_world: (l.x t + l.y b) + l.z n.
  const D4 wx = add(add(mul(lx, tx), mul(ly, bx)), mul(lz, nx));
  const D4 wy = add(add(mul(lx, ty), mul(ly, by)), mul(lz, ny));
  const D4 wz = add(add(mul(lx, tz), mul(ly, bz)), mul(lz, nz));

  // The lanes that bounce: all bits set (blendv reads the sign bit).
  const D4 mask =
      _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i*>(lanes.bouncing)));

  // Lanes with a glossy lobe are left alone here: bounce_lobed_lanes does them at the end.
  D4 diffuse = mask;
  if (lanes.lobed != 0) {
    const __m256i bits =
        _mm256_and_si256(_mm256_set1_epi64x(lanes.lobed), _mm256_setr_epi64x(1, 2, 4, 8));
    diffuse =
        _mm256_andnot_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(bits, _mm256_setzero_si256())),
                         mask);
  }

  // beta *= (rho / pi) cos(theta_i) / (1 / 2 pi), in Material::brdf()'s and the loop's order.
  for (int axis = 0; axis < 3; ++axis) {
    const D4 factor = div(mul(mul(load(lanes.albedo[axis]), broadcast(k_inv_pi)), cos_theta),
                          broadcast(k_inv_two_pi));
    store_where(diffuse, lanes.beta[axis], mul(load(lanes.beta[axis]), factor));
  }

  // spawn_ray: the origin pushed 1e-7 (1 + max |p_i|) along the normal, to the side of wi.
  const D4 px = load(lanes.hit.point[0]), py = load(lanes.hit.point[1]),
           pz = load(lanes.hit.point[2]);
  const D4 scale = add(one, std_max(std_max(abs(px), abs(py)), abs(pz)));
  const D4 offset = mul(broadcast(1e-7), scale);
  const D4 side =
      select(_mm256_cmp_pd(dot(wx, wy, wz, nx, ny, nz), zero, _CMP_GE_OQ), one, broadcast(-1.0));
  const D4 push = mul(side, offset);
  const D4 ox = add(px, mul(push, nx)), oy = add(py, mul(push, ny)), oz = add(pz, mul(push, nz));
  store_where(diffuse, rays.origin_x, ox);
  store_where(diffuse, rays.origin_y, oy);
  store_where(diffuse, rays.origin_z, oz);
  store_where(diffuse, rays.direction_x, wx);
  store_where(diffuse, rays.direction_y, wy);
  store_where(diffuse, rays.direction_z, wz);
  if (lanes.lobed != 0) bounce_lobed_lanes(lanes, rays);
}

#else

void bounce_lanes_avx2(BounceLanes& lanes, RayLanes& rays) { bounce_lanes_portable(lanes, rays); }

#endif

// ASSIGNMENT a4.1 END

}  // namespace mcrt
