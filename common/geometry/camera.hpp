#pragma once
/// Pinhole look-at camera with a vertical field of view and a near plane.

#include <cmath>

#include "geometry/ray.hpp"

namespace mcrt {

/// Where the camera is and how it looks: the scene's part of a camera.
struct CameraSpec {
  Vec3 eye{0.0};
  Vec3 direction{0.0, 0.0, -1.0};  ///< view direction (need not be unit)
  Vec3 up{0.0, 1.0, 0.0};
  double vertical_fov = 0.7;  ///< radians, full angle
  double near = 0.0;          ///< rays start this far from the eye along their direction
};

class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height)
      : eye_(spec.eye), near_(spec.near), width_(width), height_(height) {
    forward_ = glm::normalize(spec.direction);
    const Vec3 right = glm::normalize(glm::cross(forward_, spec.up));
    const Vec3 up = glm::cross(right, forward_);
    const double half_height = std::tan(0.5 * spec.vertical_fov);
    const double half_width = half_height * width / height;
    // Screen at unit distance: x_screen in [-1,1] spans 2*half_width, y_screen 2*half_height.
    right_ = 2.0 * half_width * right;
    up_ = 2.0 * half_height * up;
  }

  /// The ray through image position (px, py) in pixels, row 0 at the top:
  /// d = forward + (px/w - 1/2) right + (1/2 - py/h) up, direction = d / |d|,
  /// origin = eye + near * direction: on the sphere of radius `near` round the eye, as smallpt
  /// runs it (its `Ray(cam.o + d*140, d.norm())` normalises d in place, and g++ evaluates the
  /// second argument first), not on the plane eye + near * d, whose corners reach further.
  Ray generate_ray(double px, double py) const {
    const Vec3 d = forward_ + (px / width_ - 0.5) * right_ + (0.5 - py / height_) * up_;
    const Vec3 direction = glm::normalize(d);
    return {eye_ + near_ * direction, direction};
  }

  /// The ray through pixel (x, y) at offset u in [0,1)^2 inside it.
  Ray generate_ray(int x, int y, Vec2 u) const { return generate_ray(x + u.x, y + u.y); }

  int width() const { return width_; }
  int height() const { return height_; }

  /// What generate_ray computes from, for the engines that make four rays at once.
  struct Frame {
    Vec3 eye, forward, right, up;
    double near;
  };
  Frame frame() const { return {eye_, forward_, right_, up_, near_}; }

 private:
  Vec3 eye_, forward_, right_, up_;
  double near_;
  int width_, height_;
};

}  // namespace mcrt
