// Fast engines against their plain references, everywhere (issue #17, part 2): every size from
// 0 to 64 (every remainder of the 16 disk lanes and of the 4-sphere blocks, several times
// over) and a few large random sizes, over several seeds and streams; what comes back must be
// equal, and so must what is left behind (the generator's state after a count: the next call
// draws the same numbers).
//
//  - count_in_disk (AVX2 where the processor has it) and count_in_disk_portable against the
//    lecture's loop, written here: DiskPoints one point at a time.
//  - SphereSet::nearest_avx2 and nearest_portable against a plain loop over
//    intersect_distance, for every count of spheres from 0 to 64; QuadSet the same way.
//  - SphereSet::nearest_lanes and QuadSet::nearest_lanes, four rays at once, in both engines,
//    against the plain loop for each ray, for every count from 0 to 64.
//  - QuadSet with groups of quads behind boxes (add_group), which the AVX2 searches skip for
//    rays that miss the box: every search against the plain loop over all the quads, with
//    rays aimed at the boxes' corners and edges, where a box without its pad would be missed.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "geometry/quad_set.hpp"
#include "geometry/ray_lanes.hpp"
#include "geometry/sphere_set.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"
#include "sampling/sampling.hpp"
#include "support/plain_nearest.hpp"

using namespace mcrt;

namespace {

// ---------------------------------------------------------------------------------------------
// The disk counter.

// The reference: the lecture's loop, M of estimate_disk_area, one point at a time.
std::uint64_t plain_count_in_disk(std::uint64_t n, Rng& rng) {
  DiskPoints points(rng);
  std::uint64_t m = 0;
  for (std::uint64_t i = 0; i < n; ++i) m += inside_unit_disk(points.next());
  return m;
}

// The generator's next draws: equal for equal states (a state differing anywhere changes
// them, barring a 2^-256 accident).
std::array<std::uint32_t, 8> next_draws(Rng& rng) {
  std::array<std::uint32_t, 8> draws{};
  for (auto& d : draws) d = rng.next_bits();
  return draws;
}

struct CountCase {
  std::uint64_t n, seed, stream;
};

void expect_engines_agree(const CountCase& c) {
  Rng plain_rng(c.seed, c.stream), fast_rng(c.seed, c.stream), portable_rng(c.seed, c.stream);
  const std::uint64_t plain = plain_count_in_disk(c.n, plain_rng);
  const std::uint64_t fast = count_in_disk(c.n, fast_rng);
  const std::uint64_t portable = count_in_disk_portable(c.n, portable_rng);
  EXPECT_EQ(fast, plain) << "n " << c.n << " seed " << c.seed << " stream " << c.stream;
  EXPECT_EQ(portable, plain) << "n " << c.n << " seed " << c.seed << " stream " << c.stream;
  const auto after = next_draws(plain_rng);
  EXPECT_EQ(next_draws(fast_rng), after) << "state left by count_in_disk, n " << c.n;
  EXPECT_EQ(next_draws(portable_rng), after) << "state left by count_in_disk_portable, n " << c.n;
}

constexpr std::uint64_t k_seeds[] = {1, 2, 20261122};
constexpr std::uint64_t k_streams[] = {0, 1, 0xfffffffffULL};

TEST(DiskCounterDifferentialTest, EverySizeFrom0To64OverSeedsAndStreams) {
  for (std::uint64_t n = 0; n <= 64; ++n)
    for (std::uint64_t seed : k_seeds)
      for (std::uint64_t stream : k_streams) expect_engines_agree({n, seed, stream});
}

TEST(DiskCounterDifferentialTest, LargeRandomSizes) {
  Rng sizes(77, 0);
  for (int i = 0; i < 6; ++i) {
    // Up to ~2^18 points, every remainder mod 16 equally likely.
    const std::uint64_t n = 16 * sizes.uniform_below(1u << 14) + sizes.uniform_below(16);
    expect_engines_agree(
        {n, k_seeds[i % 3], k_streams[(i / 3) % 3] + static_cast<std::uint64_t>(i)});
  }
}

// Consecutive counts from one generator: each call must leave it where the plain loop does,
// or the second count would differ.
TEST(DiskCounterDifferentialTest, ConsecutiveCallsFromOneGenerator) {
  Rng plain_rng(9, 4), fast_rng(9, 4), portable_rng(9, 4);
  for (std::uint64_t n : {0u, 17u, 5u, 64u, 1000u, 15u, 16u, 1u}) {
    const std::uint64_t plain = plain_count_in_disk(n, plain_rng);
    EXPECT_EQ(count_in_disk(n, fast_rng), plain) << "n " << n;
    EXPECT_EQ(count_in_disk_portable(n, portable_rng), plain) << "n " << n;
  }
}

// The parallel count is the sum of its chunks' counts, chunk j from stream
// stream_index(stream, j), each counted by the plain loop.
TEST(DiskCounterDifferentialTest, ParallelCountIsTheSumOfPlainChunkCounts) {
  const std::uint64_t n = k_disk_chunk + 37;
  std::uint64_t plain = 0;
  for (std::uint64_t j = 0; j * k_disk_chunk < n; ++j) {
    Rng rng(3, stream_index(8, j));
    plain += plain_count_in_disk(std::min(k_disk_chunk, n - j * k_disk_chunk), rng);
  }
  EXPECT_EQ(count_in_disk_parallel(n, 3, 8, 1), plain);
  EXPECT_EQ(count_in_disk_parallel(n, 3, 8, 2), plain);
}

// ---------------------------------------------------------------------------------------------
// The sphere set.

using mcrt::testing::plain_nearest;  // support/plain_nearest.hpp

Vec3 random_point(Rng& rng, double scale) {
  return scale * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
}

TEST(SphereSetDifferentialTest, EveryCountFrom0To64WithRandomRays) {
  const bool avx2 = SphereSet::has_avx2();
  int hits = 0, ties = 0;
  for (std::uint64_t seed : {5u, 6u})
    for (std::size_t count = 0; count <= 64; ++count) {
      Rng rng(seed, count);
      std::vector<Sphere> spheres;
      SphereSet set;
      for (std::size_t i = 0; i < count; ++i) {
        // One sphere in five repeats an earlier one (an exact tie: the lower index must win);
        // radii from 0.2 to 3 in a box of side 16, so rays see zero to many spheres.
        const Sphere s = i % 5 == 4 ? spheres[rng.uniform_below(static_cast<std::uint32_t>(i))]
                                    : Sphere{random_point(rng, 16.0), 0.2 + 2.8 * rng.uniform(),
                                             static_cast<std::uint32_t>(i)};
        spheres.push_back(s);
        set.add(s);
      }
      ASSERT_EQ(set.size(), count);
      for (int r = 0; r < 150; ++r) {
        const Vec3 local = sample_uniform_sphere(rng.uniform2());
        const Ray ray{random_point(rng, 20.0), local};
        // Default range, a window, and a range starting beyond some near roots.
        const Interval range = r % 3 == 0 ? Interval{}
                               : r % 3 == 1
                                   ? Interval{4.0 * rng.uniform(), 4.0 + 20.0 * rng.uniform()}
                                   : Interval{1e-9, 6.0 * rng.uniform()};
        const SphereSet::Nearest plain = plain_nearest(spheres, ray, range);
        const SphereSet::Nearest portable = set.nearest_portable(ray, range);
        const SphereSet::Nearest chosen = set.nearest(ray, range);
        EXPECT_EQ(portable.index, plain.index) << count << " spheres, ray " << r;
        EXPECT_EQ(portable.t, plain.t) << count << " spheres, ray " << r;
        EXPECT_EQ(chosen.index, plain.index) << count << " spheres, ray " << r;
        EXPECT_EQ(chosen.t, plain.t) << count << " spheres, ray " << r;
        if (avx2) {
          const SphereSet::Nearest fast = set.nearest_avx2(ray, range);
          EXPECT_EQ(fast.index, plain.index) << count << " spheres, ray " << r;
          EXPECT_EQ(fast.t, plain.t) << count << " spheres, ray " << r;
        }
        if (plain.index == count) continue;
        ++hits;
        for (std::size_t j = 0; j < count; ++j)
          ties += j != plain.index && spheres[j].center == spheres[plain.index].center &&
                  spheres[j].radius == spheres[plain.index].radius;
      }
    }
  // The floors make sure the comparison is not vacuous (no hits, or no decided ties, would let
  // a wrong loop pass); the counts at these fixed seeds are far above them.
  EXPECT_GT(hits, 3000);
  EXPECT_GT(ties, 300);
}

// A random quad: axis-aligned one time in three (rays along an axis then run parallel to it),
// with one edge along an axis one time in six (the sides of a box turned about that axis,
// whose vectors have two coordinates that are not zero), edges from 0.5 to 6 long, in a box
// of side 16; one quad in five repeats an earlier one.
Quad random_quad(Rng& rng, const std::vector<Quad>& earlier) {
  if (earlier.size() % 5 == 4)
    return earlier[rng.uniform_below(static_cast<std::uint32_t>(earlier.size()))];
  const Vec3 corner = random_point(rng, 16.0);
  const auto shape = rng.uniform_below(6);
  if (shape < 3) {
    const auto axis = rng.uniform_below(3);
    Vec3 u(0.0), v(0.0);
    u[(axis + 1) % 3] = 0.5 + 5.5 * rng.uniform();
    v[(axis + 2) % 3] = (shape == 0 ? -1.0 : 1.0) * (0.5 + 5.5 * rng.uniform());
    if (shape < 2) return {corner, u, v};
    v[axis] = 0.5 + 5.5 * rng.uniform();  // u along an axis, v across it
    return {corner, u, v};
  }
  return {corner, (0.5 + 5.5 * rng.uniform()) * sample_uniform_sphere(rng.uniform2()),
          (0.5 + 5.5 * rng.uniform()) * sample_uniform_sphere(rng.uniform2())};
}

TEST(QuadSetDifferentialTest, EveryCountFrom0To64WithRandomRays) {
  const bool avx2 = QuadSet::has_avx2();
  int hits = 0, ties = 0;
  for (std::uint64_t seed : {7u, 8u})
    for (std::size_t count = 0; count <= 64; ++count) {
      Rng rng(seed, count);
      std::vector<Quad> quads;
      QuadSet set;
      for (std::size_t i = 0; i < count; ++i) {
        quads.push_back(random_quad(rng, quads));
        set.add(quads.back());
      }
      ASSERT_EQ(set.size(), count);
      for (int r = 0; r < 150; ++r) {
        // One ray in four runs along an axis: parallel to a third of the quads.
        Vec3 direction = sample_uniform_sphere(rng.uniform2());
        if (r % 4 == 3) direction = Vec3(0.0), direction[r % 3] = rng.uniform() < 0.5 ? -1.0 : 1.0;
        const Ray ray{random_point(rng, 20.0), direction};
        const Interval range = r % 3 == 0 ? Interval{}
                               : r % 3 == 1
                                   ? Interval{4.0 * rng.uniform(), 4.0 + 20.0 * rng.uniform()}
                                   : Interval{1e-9, 6.0 * rng.uniform()};
        const QuadSet::Nearest plain = plain_nearest(quads, ray, range);
        const QuadSet::Nearest portable = set.nearest_portable(ray, range);
        const QuadSet::Nearest chosen = set.nearest(ray, range);
        EXPECT_EQ(portable.index, plain.index) << count << " quads, ray " << r;
        EXPECT_EQ(portable.t, plain.t) << count << " quads, ray " << r;
        EXPECT_EQ(chosen.index, plain.index) << count << " quads, ray " << r;
        EXPECT_EQ(chosen.t, plain.t) << count << " quads, ray " << r;
        if (avx2) {
          const QuadSet::Nearest fast = set.nearest_avx2(ray, range);
          EXPECT_EQ(fast.index, plain.index) << count << " quads, ray " << r;
          EXPECT_EQ(fast.t, plain.t) << count << " quads, ray " << r;
        }
        if (plain.index == count) continue;
        ++hits;
        for (std::size_t j = 0; j < count; ++j)
          ties += j != plain.index && quads[j].corner() == quads[plain.index].corner() &&
                  quads[j].edge_u() == quads[plain.index].edge_u() &&
                  quads[j].edge_v() == quads[plain.index].edge_v();
      }
    }
  // As for the spheres: floors that keep the comparison from being vacuous.
  EXPECT_GT(hits, 1000);
  EXPECT_GT(ties, 100);
}

// A ray within the parallel threshold of a quad's plane (|n.d| < 1e-12 |n|) misses it in every
// engine, even where its far-off crossing of the plane lands inside the quad: random rays never
// come that close, and rays along an axis give n.d = 0 exactly, which no engine can take for a
// hit. The unit square at z = 0 (|n| = 1); the ray starts delta above the plane with slope -s,
// so it crosses the plane at x = -1 + delta / s = 0.5, inside. Just above the threshold
// (s = 1e-11) every engine takes the hit, so the misses below it are the threshold's doing.
TEST(QuadSetDifferentialTest, RaysWithinTheParallelThresholdMissInEveryEngine) {
  const Quad square{Vec3(0.0), {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0};
  QuadSet set;
  set.add(square);
  for (double slope : {1e-13, 5e-13, 9e-13, 1e-11}) {
    const Ray ray{{-1.0, 0.5, 1.5 * slope}, glm::normalize(Vec3(1.0, 0.0, -slope))};
    const bool parallel = slope < 1e-12;
    const std::size_t expected = parallel ? 1 : 0;  // index 1 = size(): no hit
    EXPECT_EQ(intersect_distance(square, ray, Interval{}).has_value(), !parallel) << slope;
    EXPECT_EQ(set.nearest_portable(ray, Interval{}).index, expected) << slope;
    EXPECT_EQ(set.nearest(ray, Interval{}).index, expected) << slope;
    if (QuadSet::has_avx2()) {
      EXPECT_EQ(set.nearest_avx2(ray, Interval{}).index, expected) << slope;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Four rays at once: nearest_lanes (both engines) against the plain loop, ray by ray.

// Groups of four random rays sharing t_min, each lane with its own range end and, in one lane
// of two, an earlier hit held at that end (index 999): a lane must take the plain loop's
// nearest primitive in (t_min, its end), or keep what it held when there is none.
template <class Set, class Shape>
void expect_lanes_agree(const std::vector<Shape>& shapes, const Set& set, Rng& rng, int groups,
                        const char* what, int& hits) {
  for (int g = 0; g < groups; ++g) {
    const double t_min = g % 2 == 0 ? Interval{}.min : 4.0 * rng.uniform();
    RayLanes rays;
    NearestLanes start(0.0);
    Ray ray[RayLanes::k_lanes];
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      Vec3 direction = sample_uniform_sphere(rng.uniform2());
      // One ray in four runs along an axis: parallel to a third of the axis-aligned quads.
      if ((g + l) % 4 == 3)
        direction = Vec3(0.0), direction[l % 3] = rng.uniform() < 0.5 ? -1.0 : 1.0;
      ray[l] = Ray{random_point(rng, 20.0), direction};
      rays.set(l, ray[l]);
      start.t[l] = l % 3 == 0 ? Interval{}.max : t_min + 30.0 * rng.uniform();
      start.index[l] = (g + l) % 2 == 0 ? -1.0 : 999.0;
    }
    NearestLanes portable = start, chosen = start, fast = start;
    set.nearest_lanes_portable(rays, t_min, portable);
    set.nearest_lanes(rays, t_min, chosen);
    if (Set::has_avx2()) set.nearest_lanes_avx2(rays, t_min, fast);
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      const auto plain = plain_nearest(shapes, ray[l], Interval{t_min, start.t[l]});
      const bool hit = plain.index != shapes.size();
      hits += hit;
      const double t = hit ? plain.t : start.t[l];
      const double index = hit ? static_cast<double>(plain.index) : start.index[l];
      for (const NearestLanes* lanes : {&portable, &chosen, &fast}) {
        if (lanes == &fast && !Set::has_avx2()) continue;
        EXPECT_EQ(lanes->t[l], t) << shapes.size() << " " << what << ", group " << g << " lane "
                                  << l;
        EXPECT_EQ(lanes->index[l], index)
            << shapes.size() << " " << what << ", group " << g << " lane " << l;
      }
    }
  }
}

TEST(SphereSetDifferentialTest, FourRaysAtOnceForEveryCountFrom0To64) {
  int hits = 0;
  for (std::size_t count = 0; count <= 64; ++count) {
    Rng rng(9, count);
    std::vector<Sphere> spheres;
    SphereSet set;
    for (std::size_t i = 0; i < count; ++i) {
      // As above: one sphere in five repeats an earlier one.
      const Sphere s = i % 5 == 4 ? spheres[rng.uniform_below(static_cast<std::uint32_t>(i))]
                                  : Sphere{random_point(rng, 16.0), 0.2 + 2.8 * rng.uniform(),
                                           static_cast<std::uint32_t>(i)};
      spheres.push_back(s);
      set.add(s);
    }
    expect_lanes_agree(spheres, set, rng, 40, "spheres", hits);
  }
  EXPECT_GT(hits, 2000);  // a floor, as above: the fixed seed gives far more
}

TEST(QuadSetDifferentialTest, FourRaysAtOnceForEveryCountFrom0To64) {
  int hits = 0;
  for (std::size_t count = 0; count <= 64; ++count) {
    Rng rng(10, count);
    std::vector<Quad> quads;
    QuadSet set;
    for (std::size_t i = 0; i < count; ++i) {
      quads.push_back(random_quad(rng, quads));
      set.add(quads.back());
    }
    expect_lanes_agree(quads, set, rng, 40, "quads", hits);
  }
  EXPECT_GT(hits, 700);  // a floor, as above: the fixed seed gives far more
}

// The four-ray search tests an axis-aligned quad without the products by zero of its dot
// products, which can change the sign of a zero sum. Every bit of t and index must still be
// the plain loop's: quads on whole-number planes with edges of both signs, rays starting on
// those planes and edges (numerators and edge coordinates exactly zero), directions with
// +0 and -0 coordinates, t_min 0 and 1e-9.
TEST(QuadSetDifferentialTest, AxisAlignedQuadsKeepEveryBitOnTheirPlanesAndEdges) {
  Rng rng(12, 0);
  std::vector<Quad> quads;
  QuadSet set;
  for (int i = 0; i < 24; ++i) {
    const auto axis = rng.uniform_below(3);
    Vec3 corner, u(0.0), v(0.0);
    for (int c = 0; c < 3; ++c) corner[c] = static_cast<double>(rng.uniform_below(7)) - 2.0;
    u[(axis + 1) % 3] = (rng.uniform() < 0.5 ? -1.0 : 1.0) * (1.0 + rng.uniform_below(3));
    v[(axis + 2) % 3] = (rng.uniform() < 0.5 ? -1.0 : 1.0) * (1.0 + rng.uniform_below(3));
    quads.push_back({corner, u, v});
    set.add(quads.back());
  }
  auto whole_point = [&] {
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = static_cast<double>(rng.uniform_below(9)) - 3.0;
    return p;
  };
  int hits = 0;
  for (int g = 0; g < 4000; ++g) {
    const double t_min = g % 2 == 0 ? 0.0 : Interval{}.min;
    RayLanes rays;
    Ray ray[RayLanes::k_lanes];
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      Vec3 direction;
      switch ((g + l) % 3) {
        case 0: {  // along an axis, with signed zeros elsewhere
          for (int c = 0; c < 3; ++c) direction[c] = rng.uniform() < 0.5 ? -0.0 : 0.0;
          direction[rng.uniform_below(3)] = rng.uniform() < 0.5 ? -1.0 : 1.0;
          break;
        }
        case 1: {  // in a coordinate plane
          direction = sample_uniform_sphere(rng.uniform2());
          direction[rng.uniform_below(3)] = rng.uniform() < 0.5 ? -0.0 : 0.0;
          break;
        }
        default: direction = sample_uniform_sphere(rng.uniform2());
      }
      ray[l] = Ray{whole_point(), direction};
      rays.set(l, ray[l]);
    }
    NearestLanes portable(Interval{}.max), fast(Interval{}.max);
    set.nearest_lanes_portable(rays, t_min, portable);
    if (QuadSet::has_avx2()) set.nearest_lanes_avx2(rays, t_min, fast);
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      const QuadSet::Nearest plain = plain_nearest(quads, ray[l], Interval{t_min, Interval{}.max});
      const bool hit = plain.index != quads.size();
      hits += hit;
      const double index = hit ? static_cast<double>(plain.index) : -1.0;
      for (const NearestLanes* lanes : {&portable, &fast}) {
        if (lanes == &fast && !QuadSet::has_avx2()) continue;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(lanes->t[l]), std::bit_cast<std::uint64_t>(plain.t))
            << "group " << g << " lane " << l;
        EXPECT_EQ(lanes->index[l], index) << "group " << g << " lane " << l;
      }
    }
  }
  EXPECT_GT(hits, 2000);  // a floor, as above: the fixed seed gives 2958
}

// ---------------------------------------------------------------------------------------------
// Groups of quads behind boxes.

// The six faces of the box [0, size] turned by `angle` about +y and moved to `offset` (as the
// cornell scene builds its blocks).
std::vector<Quad> box_faces(Vec3 size, double angle, Vec3 offset) {
  const double c = std::cos(angle), s = std::sin(angle);
  auto turn = [&](Vec3 v) { return Vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z); };
  const Vec3 dx = turn({size.x, 0, 0}), dy{0, size.y, 0}, dz = turn({0, 0, size.z});
  const Vec3 far = offset + turn(size);
  return {{offset, dx, dy}, {offset, dz, dy}, {offset, dx, dz},
          {far, -dx, -dy},  {far, -dz, -dy},  {far, -dx, -dz}};
}

// A point of quad q: a corner, an edge's midpoint or its centre (a, b in {0, 1/2, 1}), where a
// ray aimed at it grazes the quad's edge, and for an axis-aligned box its bounds, or a random
// point of the quad.
Vec3 target_on(const Quad& q, Rng& rng) {
  const bool random = rng.uniform_below(4) == 0;
  const double a = random ? rng.uniform() : 0.5 * rng.uniform_below(3);
  const double b = random ? rng.uniform() : 0.5 * rng.uniform_below(3);
  return q.corner() + a * q.edge_u() + b * q.edge_v();
}

// Sets of loose quads and boxes (half of them axis-aligned), in a random order; rays from
// random points, from points on the faces (as a bounce leaves a box) and along the axes, aimed
// at points of the quads. Every search must give the plain loop's answer over all the quads.
TEST(QuadSetDifferentialTest, GroupsBehindBoxesGiveThePlainLoopsAnswer) {
  const bool avx2 = QuadSet::has_avx2();
  int hits = 0, group_hits = 0;
  for (std::uint64_t trial = 0; trial < 40; ++trial) {
    Rng rng(11, trial);
    std::vector<Quad> quads;
    std::vector<bool> grouped;
    QuadSet set;
    // Up to nine parts, so that many sets hold more than four groups: the one-ray search tests
    // the groups' boxes four at a time.
    const int parts = 1 + static_cast<int>(rng.uniform_below(9));
    for (int part = 0; part < parts; ++part) {
      if (rng.uniform_below(3) == 0) {
        quads.push_back(random_quad(rng, quads));
        grouped.push_back(false);
        set.add(quads.back());
        continue;
      }
      const double angle = rng.uniform_below(2) == 0 ? 0.0 : 6.3 * rng.uniform();
      const Vec3 size(0.5 + 6.0 * rng.uniform(), 0.5 + 6.0 * rng.uniform(),
                      0.5 + 6.0 * rng.uniform());
      const std::vector<Quad> faces = box_faces(size, angle, random_point(rng, 12.0));
      quads.insert(quads.end(), faces.begin(), faces.end());
      grouped.insert(grouped.end(), faces.size(), true);
      set.add_group(faces);
    }
    ASSERT_EQ(set.size(), quads.size());
    for (int g = 0; g < 60; ++g) {
      RayLanes rays;
      Ray ray[RayLanes::k_lanes];
      for (int l = 0; l < RayLanes::k_lanes; ++l) {
        const Quad& aim = quads[rng.uniform_below(static_cast<std::uint32_t>(quads.size()))];
        const Quad& from = quads[rng.uniform_below(static_cast<std::uint32_t>(quads.size()))];
        const int kind = (g + l) % 4;
        Vec3 origin = kind == 0 ? target_on(from, rng) : random_point(rng, 20.0);
        Vec3 direction = glm::normalize(target_on(aim, rng) - origin);
        if (kind == 3) {  // along an axis, from a point of a quad's plane
          origin = target_on(from, rng);
          direction = Vec3(0.0);
          direction[l % 3] = rng.uniform() < 0.5 ? -1.0 : 1.0;
        }
        if (!(glm::length(direction) > 0.5)) direction = Vec3(0, 0, 1);  // origin on the target
        ray[l] = Ray{origin, direction};
        rays.set(l, ray[l]);
      }
      NearestLanes chosen(Interval{}.max), fast(Interval{}.max);
      set.nearest_lanes(rays, Interval{}.min, chosen);
      if (avx2) set.nearest_lanes_avx2(rays, Interval{}.min, fast);
      for (int l = 0; l < RayLanes::k_lanes; ++l) {
        const QuadSet::Nearest plain = plain_nearest(quads, ray[l], Interval{});
        const std::string where = "trial " + std::to_string(trial) + ", group " +
                                  std::to_string(g) + " lane " + std::to_string(l);
        const QuadSet::Nearest portable = set.nearest_portable(ray[l], Interval{});
        EXPECT_EQ(portable.index, plain.index) << where;
        EXPECT_EQ(portable.t, plain.t) << where;
        const QuadSet::Nearest one = set.nearest(ray[l], Interval{});
        EXPECT_EQ(one.index, plain.index) << where;
        EXPECT_EQ(one.t, plain.t) << where;
        const bool hit = plain.index != quads.size();
        const double index = hit ? static_cast<double>(plain.index) : -1.0;
        EXPECT_EQ(chosen.index[l], index) << where;
        EXPECT_EQ(chosen.t[l], plain.t) << where;
        if (avx2) {
          const QuadSet::Nearest fast_one = set.nearest_avx2(ray[l], Interval{});
          EXPECT_EQ(fast_one.index, plain.index) << where;
          EXPECT_EQ(fast_one.t, plain.t) << where;
          EXPECT_EQ(fast.index[l], index) << where;
          EXPECT_EQ(fast.t[l], plain.t) << where;
        }
        hits += hit;
        group_hits += hit && grouped[plain.index];
      }
    }
  }
  // Floors that keep the comparison from being vacuous: most rays are aimed at a quad, and
  // most of the quads are in groups.
  EXPECT_GT(hits, 5000);
  EXPECT_GT(group_hits, 3000);
}

}  // namespace
