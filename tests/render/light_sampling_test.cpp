// Light sampling on a scene (render/light_sampling.hpp): which part of a sphere light it aims
// at from where the shading point is. (Its estimates are checked in next_event_estimation's
// checks and tests, which use it.)

#include <gtest/gtest.h>

#include "render/light_sampling.hpp"
#include "render/next_event_estimation_procedures.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

// Where light sampling aims on a sphere light (light_sampling.hpp): the cap from inside the
// enclosure (the room), the cone of the whole sphere from outside both (above the ceiling),
// the whole sphere from inside it (the furnace).
TEST(LightSamplingTest, SphereLightPartFollowsTheShadingPoint) {
  const Scene spheres = make_cornell_spheres();
  const Emitter& e = spheres.emitters()[0];
  const Sphere& light = spheres.spheres()[e.index];
  EXPECT_EQ(sphere_light_part(light, e, Vec3(50, 40, 80)), SphereLightPart::cap);
  EXPECT_EQ(sphere_light_part(light, e, Vec3(50, 81.5, 80)), SphereLightPart::cap);
  EXPECT_EQ(sphere_light_part(light, e, mcrt::testing::k_above_ceiling), SphereLightPart::cone);
  const Scene furnace = make_furnace(0.5, 1.0);
  EXPECT_EQ(sphere_light_part(furnace.spheres()[0], furnace.emitters()[0], Vec3(0.3, 0, 0)),
            SphereLightPart::whole);
  EXPECT_EQ(sphere_light_part(furnace.spheres()[0], furnace.emitters()[0], Vec3(0, 3, 0)),
            SphereLightPart::cone);
}

}  // namespace
