#pragma once
/// Chapter 05's image, four paths at a time: the layer below estimate_path_radiance.
///
/// render(camera, settings, estimate_path_radiance) follows one path to its end before it
/// starts the next, and each bounce's query tests the primitives against one ray. Here four
/// paths advance together, one per lane: each bounce tests every primitive against four rays
/// at once (Scene::closest_hits), the lines around the search and the bounce run on the four
/// lanes together (engine/path_lanes.hpp), and a lane whose path has ended takes the row's
/// next (pixel, sample). Two such groups of four take turns, so that one group's search runs
/// while the other's bounce waits on its latencies. Each lane runs the loop body of
/// estimate_path_radiance on the generator stream (pixel, sample), and each pixel's samples are
/// summed in sample order, so the image, the ray count and the non-finite count are those of
/// render(), bit for bit (tests/engine/path_tracer_lanes_test.cpp), and do not depend on the thread
/// count.

#include "geometry/camera.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "sampling/path_sampler.hpp"

namespace mcrt {

/// render(camera, settings, path radiance with at most `max_depth` bounces), four paths at a
/// time. A lane at a delta material (mirror, glass) leaves the four-lane bounce and takes
/// estimate_path_radiance's delta branch on its own (one uniform, sample_delta), between the
/// same search and end of step as the other lanes. With a `sampler` other than independent,
/// render_sampled's image instead (--sampler): each lane draws its uniforms from its sample's
/// PaddedSample, as the loop does, in place of its generator's.
RenderResult render_path_tracer_lanes(const Scene& scene, const Camera& camera,
                                      const RenderSettings& settings, int max_depth,
                                      PathSampler sampler = PathSampler::independent);

}  // namespace mcrt
