// Chapter 05's path tracer in four lanes (engine/path_tracer_lanes.hpp) against the lecture's
// loop, render(camera, settings, estimate_path_radiance): the same image bit for bit, the same
// ray count and the same count of non-finite estimates, for every scene, for image widths and
// sample counts that leave every remainder of the four lanes and of a chunk of paths, for
// depths 0 to 10, for first_sample > 0 and for 1 and 2 threads; and with --sampler jittered and
// sobol, render_sampled's image with the same loop. Both run the same operations on the same
// streams (or points), so nothing but a bug can make them differ: the comparison is exact.
//
// The four-ray searches are also compared with closest_hit ray by ray, on the rays real paths
// meet and on rays from random points in random directions, with their results built into Hits
// one lane at a time (hit_in_lane) and four at a time (hits_in_lanes, both engines).

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/cpu_features.hpp"
#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/path_tracer.hpp"
#include "engine/path_tracer_lanes.hpp"
#include "render/render.hpp"
#include "render/sampled_render.hpp"
#include "render/scene.hpp"
#include "sampling/path_sampler.hpp"
#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

// Equal as bits, so a NaN equals the same NaN and 0.0 differs from -0.0.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const Color& a, const Color& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

struct Case {
  std::string scene;
  int width, height, spp, depth;
  std::uint64_t first_sample;
  int threads;
};

// The lanes' image against the lecture's loop: render_sampled with estimate_path_radiance,
// which for independent streams is render() itself; with --sampler jittered or sobol the lanes
// draw their uniforms from their samples' padded sets, as the loop does.
void expect_lecture_image(const Case& c, PathSampler sampler = PathSampler::independent) {
  SCOPED_TRACE(name_of(sampler) + " " + c.scene + " " + std::to_string(c.width) + "x" +
               std::to_string(c.height) + " spp " + std::to_string(c.spp) + " depth " +
               std::to_string(c.depth) + " first sample " + std::to_string(c.first_sample) +
               " threads " + std::to_string(c.threads));
  const Scene scene = make_scene(c.scene);
  const Camera camera(scene.camera, c.width, c.height);
  const RenderSettings settings{c.spp, c.first_sample, 11, c.threads, nullptr};
  const RenderResult lecture =
      render_sampled(camera, settings, sampler,
                     [&](const Ray& ray, auto& uniforms, RayCount& count) {
                       return estimate_path_radiance(scene, ray, c.depth, uniforms, count);
                     });
  const RenderResult lanes = render_path_tracer_lanes(scene, camera, settings, c.depth, sampler);
  ASSERT_EQ(lanes.image.width, lecture.image.width);
  ASSERT_EQ(lanes.image.height, lecture.image.height);
  std::size_t differing = 0, first = lecture.image.pixels.size();
  for (std::size_t i = 0; i < lecture.image.pixels.size(); ++i)
    if (!same_bits(lanes.image.pixels[i], lecture.image.pixels[i])) {
      ++differing;
      first = std::min(first, i);
    }
  EXPECT_EQ(differing, 0u) << "first differing pixel: " << first;
  EXPECT_EQ(lanes.rays, lecture.rays);
  EXPECT_EQ(lanes.non_finite_samples, lecture.non_finite_samples);
}

// Every scene (the delta lanes of smallpt take a whole set for their one uniform, the glossy
// lanes of veach-plates are bounced one at a time); widths 1 to 9 with 1 to 3 spp (every
// remainder of the lanes, pixels whose samples span both groups); a row of 1031 paths (two
// chunks); 16, 17 and 33 spp (Sobol' blocks of 16: a pixel's samples in flight in different
// blocks); depths 0 to 3 and 40 (sets beyond the 32 a pixel caches); later samples and 1 to 3
// threads.
TEST(PathTracerLanesTest, GivesTheSampledLoopsImageWithEveryPaddedSampler) {
  for (const PathSampler sampler : {PathSampler::jittered, PathSampler::sobol}) {
    for (const std::string& name : scene_names())
      expect_lecture_image({name, 24, 18, 8, 10, 0, 2}, sampler);
    for (int width = 1; width <= 9; ++width)
      for (int spp = 1; spp <= 3; ++spp)
        expect_lecture_image({"smallpt", width, 7, spp, 10, 0, 1}, sampler);
    expect_lecture_image({"cornell", 1031, 1, 1, 10, 0, 1}, sampler);
    for (int spp : {16, 17, 33})
      expect_lecture_image({"cornell-spheres", 9, 4, spp, 10, 0, 1}, sampler);
    for (int depth : {0, 1, 2, 3, 40}) {
      expect_lecture_image({"furnace", 8, 6, 4, depth, 0, 1}, sampler);
      expect_lecture_image({"smallpt", 12, 9, 4, depth, 0, 1}, sampler);
    }
    for (int threads : {1, 2, 3})
      expect_lecture_image({"veach-plates", 17, 9, 5, 10, 5, threads}, sampler);
  }
}

TEST(PathTracerLanesTest, GivesTheLectureLoopsImageOnEveryScene) {
  for (const std::string& name : scene_names()) expect_lecture_image({name, 40, 30, 8, 10, 0, 2});
}

// Widths 1 to 9 with 1 to 3 spp leave every remainder of four lanes in a row; 1031 paths in a
// row (width 1031, 1 spp) fill one chunk of 1024 and start another; depth 0 ends every path at
// its first hit; in the furnace every path runs to the depth cut, in the Cornell box many leave
// through the open front first.
TEST(PathTracerLanesTest, GivesTheLectureLoopsImageAtEverySizeAndDepth) {
  for (int width = 1; width <= 9; ++width)
    for (int spp = 1; spp <= 3; ++spp)
      expect_lecture_image({"cornell-spheres", width, 3, spp, 10, 0, 1});
  expect_lecture_image({"cornell", 1031, 2, 1, 10, 0, 1});
  expect_lecture_image({"cornell", 300, 2, 7, 10, 0, 2});
  for (int depth = 0; depth <= 4; ++depth) {
    expect_lecture_image({"cornell", 24, 18, 4, depth, 0, 1});
    expect_lecture_image({"furnace", 16, 12, 4, depth, 0, 1});
  }
}

// Veach's plates: glossy lobes, whose lanes bounce_lanes weighs one at a time beside diffuse
// ones, and an open scene, where most paths leave after a bounce or two and lanes end at every
// step. Widths 1 to 9 with 1 to 3 spp at a height whose rows cross the plates and the lights;
// one row of 1031 paths; depths 0 to 4 and 10.
TEST(PathTracerLanesTest, GivesTheLectureLoopsImageOnVeachPlatesAtEverySizeAndDepth) {
  for (int width = 1; width <= 9; ++width)
    for (int spp = 1; spp <= 3; ++spp)
      expect_lecture_image({"veach-plates", width, 7, spp, 10, 0, 1});
  expect_lecture_image({"veach-plates", 1031, 2, 1, 10, 0, 1});
  for (int depth = 0; depth <= 4; ++depth)
    expect_lecture_image({"veach-plates", 24, 18, 4, depth, 0, 1});
  for (int threads : {1, 2}) expect_lecture_image({"veach-plates", 33, 17, 5, 10, 5, threads});
}

// smallpt's scene: lanes at the mirror and the glass ball take the delta branch one lane at a
// time (one uniform, not two) beside diffuse lanes. Widths 1 to 9 with 1 to 3 spp at a height
// whose rows cross both balls; one row of 1031 paths; depths 0 to 4, 10 and 40 (paths that
// bounce on inside the glass); later samples and 1 to 3 threads.
TEST(PathTracerLanesTest, GivesTheLectureLoopsImageOnSmallptAtEverySizeDepthAndThreadCount) {
  for (int width = 1; width <= 9; ++width)
    for (int spp = 1; spp <= 3; ++spp) expect_lecture_image({"smallpt", width, 7, spp, 10, 0, 1});
  expect_lecture_image({"smallpt", 1031, 2, 1, 10, 0, 1});
  for (int depth : {0, 1, 2, 3, 4, 10, 40})
    expect_lecture_image({"smallpt", 24, 18, 4, depth, 0, 1});
  for (int threads : {1, 2, 3}) expect_lecture_image({"smallpt", 33, 17, 5, 10, 5, threads});
}

TEST(PathTracerLanesTest, GivesTheLectureLoopsImageForLaterSamplesAndAnyThreadCount) {
  for (int threads : {1, 2, 3}) expect_lecture_image({"cornell", 33, 17, 5, 10, 5, threads});
}

// Rays from random points of the scene's bounds in random directions, and the rays of real
// paths (camera rays and their bounces): hit_in_lane of closest_hits gives closest_hit's Hit,
// field by field, in every lane.
void expect_closest_hits(const Scene& scene, const std::vector<Ray>& rays) {
  for (std::size_t first = 0; first + RayLanes::k_lanes <= rays.size();
       first += RayLanes::k_lanes) {
    RayLanes lanes;
    for (int l = 0; l < RayLanes::k_lanes; ++l) lanes.set(l, rays[first + l]);
    const Scene::ClosestLanes nearest = scene.closest_hits(lanes);
    HitLanes portable, fast;
    scene.hits_in_lanes_portable(nearest, lanes, portable);
    if (cpu_has_avx2()) scene.hits_in_lanes_avx2(nearest, lanes, fast);
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      const Ray& ray = rays[first + l];
      const std::optional<Hit> expected = scene.closest_hit(ray);
      const std::optional<Hit> got = scene.hit_in_lane(nearest, l, ray);
      ASSERT_EQ(got.has_value(), expected.has_value()) << "ray " << first + l;
      if (!expected) {
        EXPECT_FALSE(portable.found(l)) << "ray " << first + l;
        if (cpu_has_avx2()) {
          EXPECT_FALSE(fast.found(l)) << "ray " << first + l;
        }
        continue;
      }
      EXPECT_TRUE(same_bits(got->t, expected->t)) << "ray " << first + l;
      EXPECT_TRUE(same_bits(got->point, expected->point)) << "ray " << first + l;
      EXPECT_TRUE(same_bits(got->normal, expected->normal)) << "ray " << first + l;
      EXPECT_EQ(got->material, expected->material) << "ray " << first + l;
      for (const HitLanes* hits : {&portable, &fast}) {
        if (hits == &fast && !cpu_has_avx2()) continue;
        ASSERT_TRUE(hits->found(l)) << "ray " << first + l;
        EXPECT_EQ(hits->material[l], expected->material) << "ray " << first + l;
        for (int axis = 0; axis < 3; ++axis) {
          EXPECT_TRUE(same_bits(hits->point[axis][l], expected->point[axis]))
              << "ray " << first + l;
          EXPECT_TRUE(same_bits(hits->normal[axis][l], expected->normal[axis]))
              << "ray " << first + l;
        }
      }
    }
  }
}

TEST(PathTracerLanesTest, FourRaySearchesGiveEachRaysClosestHit) {
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    const Scene scene = make_scene(name);
    const Camera camera(scene.camera, 32, 24);
    std::vector<Ray> rays;
    Rng rng(3, 0);
    for (int y = 0; y < camera.height(); ++y)
      for (int x = 0; x < camera.width(); ++x) {
        Ray ray = camera.generate_ray(x, y, rng.uniform2());
        for (int bounce = 0; bounce < 4; ++bounce) {
          rays.push_back(ray);
          const std::optional<Hit> hit = scene.closest_hit(ray);
          if (!hit) break;
          ray = spawn_ray(*hit,
                          Frame(hit->normal).to_world(sample_uniform_hemisphere(rng.uniform2())));
        }
      }
    // Random rays from a box around every scene (the sphere box's walls are at most 170 from
    // the origin, the quad box's at most 555, the furnace's 1): some start outside, some inside
    // the primitives, some miss everything.
    for (int i = 0; i < 4000; ++i) {
      const Vec3 origin(rng.uniform() * 700 - 100, rng.uniform() * 700 - 100,
                        rng.uniform() * 700 - 100);
      rays.emplace_back(i % 2 ? origin : origin * 0.002, sample_uniform_sphere(rng.uniform2()));
    }
    expect_closest_hits(scene, rays);
  }
}

}  // namespace
