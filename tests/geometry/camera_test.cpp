// Camera rays through the image's corners and centre, for a simple camera and for the
// sphere Cornell box's camera (which must match smallpt's to compare renders pixel for pixel).

#include <cmath>
#include <cstddef>
#include <utility>

#include <gtest/gtest.h>

#include "geometry/camera.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

constexpr double k_tol = 1e-12;  // a handful of ulps on unit vectors

TEST(CameraTest, CentreRayLooksAlongTheViewDirection) {
  const Camera camera({{1, 2, 3}, {0, 0, -2}, {0, 1, 0}, k_pi / 2, 0.0}, 200, 100);
  const Ray ray = camera.generate_ray(100.0, 50.0);
  EXPECT_NEAR(ray.direction.x, 0.0, k_tol);
  EXPECT_NEAR(ray.direction.y, 0.0, k_tol);
  EXPECT_NEAR(ray.direction.z, -1.0, k_tol);
  EXPECT_EQ(ray.origin, Vec3(1, 2, 3));
}

TEST(CameraTest, CornersSpanTheFieldOfViewWithRowZeroAtTheTop) {
  // 90 degrees vertical: tan(45) = 1, so the top edge is at y/z = 1; aspect 2:1 gives x/z = 2.
  const Camera camera({Vec3(0.0), {0, 0, -1}, {0, 1, 0}, k_pi / 2, 0.0}, 200, 100);
  const Ray top_left = camera.generate_ray(0.0, 0.0);
  EXPECT_NEAR(top_left.direction.x / -top_left.direction.z, -2.0, k_tol);
  EXPECT_NEAR(top_left.direction.y / -top_left.direction.z, 1.0, k_tol);
  const Ray bottom_right = camera.generate_ray(200.0, 100.0);
  EXPECT_NEAR(bottom_right.direction.x / -bottom_right.direction.z, 2.0, k_tol);
  EXPECT_NEAR(bottom_right.direction.y / -bottom_right.direction.z, -1.0, k_tol);
}

TEST(CameraTest, PixelOffsetIsInsideThePixel) {
  const Camera camera({Vec3(0.0), {0, 0, -1}, {0, 1, 0}, 1.0, 0.0}, 10, 10);
  const Ray a = camera.generate_ray(3, 4, {0.25, 0.75});
  const Ray b = camera.generate_ray(3.25, 4.75);
  EXPECT_EQ(a.direction, b.direction);
}

TEST(CameraTest, RaysStartAtTheNearDistanceFromTheEyeAlongThemselves) {
  const Camera camera({{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 1.0, 5.0}, 64, 48);
  for (double px : {0.0, 17.5, 64.0})
    for (double py : {0.0, 30.0, 48.0}) {
      const Ray ray = camera.generate_ray(px, py);
      // On the sphere of radius 5 round the eye, on the ray itself (smallpt's start points).
      EXPECT_NEAR(glm::length(ray.origin), 5.0, k_tol);
      EXPECT_NEAR(glm::length(ray.origin - 5.0 * ray.direction), 0.0, k_tol);
    }
}

// smallpt: cx = (w .5135 / h, 0, 0), cy = normalize(cx x d) .5135, and the ray through
// screen point (sx, sy) in [0,1]^2 (y up) is d' = cx (sx - .5) + cy (sy - .5) + d. smallpt
// writes Ray(cam.o + d'*140, d'.norm()), and norm() normalises d' in place: g++ evaluates the
// second argument first, so the ray starts at o + 140 normalize(d'), as it runs. Our image
// row 0 is smallpt's top row (smallpt writes rows flipped).
TEST(CameraTest, CornellSpheresMatchesSmallptsCamera) {
  const Scene scene = make_cornell_spheres();
  const int w = 256, h = 192;
  const Camera camera(scene.camera, w, h);
  const Vec3 o(50, 52, 295.6), d = glm::normalize(Vec3(0, -0.042612, -1));
  const Vec3 cx(w * .5135 / h, 0, 0);
  const Vec3 cy = glm::normalize(glm::cross(cx, d)) * .5135;
  for (const Vec2 screen : {Vec2(0, 0), Vec2(1, 1), Vec2(0.5, 0.5), Vec2(0.25, 0.9)}) {
    const Vec3 dd = cx * (screen.x - 0.5) + cy * (screen.y - 0.5) + d;
    const Ray expected{o + glm::normalize(dd) * 140.0, glm::normalize(dd)};
    const Ray ray = camera.generate_ray(screen.x * w, (1.0 - screen.y) * h);
    EXPECT_NEAR(glm::length(ray.origin - expected.origin), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(ray.direction - expected.direction), 0.0, 1e-12);
  }
}

// The closed geometric fact behind the top rows: every camera ray of smallpt's scene (and of
// cornell-spheres, the same box and camera) starts inside the box: the room is the part of
// space inside all six wall balls (radius 1e5) and outside the balls (light, mirror, glass). Checked on a grid over the whole image,
// its edges and corners included, at smallpt's 1024 x 768 and at chapter 05's sizes. (With
// the start points on the plane o + 140 d' the top row started at y = 81.77, above the
// ceiling at 81.6, and saw the light's ball from outside.)
TEST(CameraTest, NoCameraRayOfTheSphereBoxStartsOutsideTheBox) {
  for (const Scene& scene : {make_cornell_spheres(), make_smallpt()})
    for (const auto& [w, h] :
         {std::pair{1024, 768}, std::pair{320, 240}, std::pair{256, 192}, std::pair{32, 24}}) {
      const Camera camera(scene.camera, w, h);
      constexpr int k_steps = 64;
      for (int i = 0; i <= k_steps; ++i)
        for (int j = 0; j <= k_steps; ++j) {
          const Ray ray = camera.generate_ray(w * i / double(k_steps), h * j / double(k_steps));
          for (std::size_t k = 0; k < scene.spheres().size(); ++k) {
            const Sphere& s = scene.spheres()[k];
            const double distance = glm::length(ray.origin - s.center);
            const bool wall = s.radius == 1e5,
                       in_the_room = wall ? distance < s.radius : distance > s.radius;
            ASSERT_TRUE(in_the_room)
                << scene.name << " " << w << "x" << h << " at (" << i << ", " << j
                << "): the ray starts at " << ray.origin.x << ", " << ray.origin.y << ", "
                << ray.origin.z << ", beyond sphere " << k;
          }
        }
    }
}

}  // namespace
