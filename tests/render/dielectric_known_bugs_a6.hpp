#pragma once
// The known-wrong dielectrics of a6.4, each sample_dielectric but for one line, and the
// producer that plugs one in where a6's dielectric checks expect the student's function.
// tests/assignments/diagnosis_test.cpp shows each one's diagnosis. Never in a kit
// (scripts/make-assignment WITHHELD_FILES: every kit stubs a6.4).

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "assignments/a6/a6_produce.hpp"
#include "assignments/subject/requests.hpp"
#include "core/math.hpp"
#include "render/fresnel.hpp"
#include "render/material.hpp"
#include "render/specular.hpp"

namespace mcrt::testing::assignment {

/// A producer of a6_dielectric requests from one sampler (the solution or a known-wrong one).
template <class Sample>
struct DielectricVariant {
  Sample sample;
  std::vector<DielectricAnswer> a6_dielectric(double ior,
                                              const std::vector<DielectricQuery>& queries) const {
    return dielectric_answers(sample, ior, queries);
  }
};
template <class Sample>
DielectricVariant<Sample> with_dielectric(Sample sample) {
  return {sample};
}

/// Fresnel with the indices of entering, 1 into n, on both sides: n not inverted when leaving
/// (the directions are right, total internal reflection included).
inline BsdfSample dielectric_fresnel_not_inverted(const Material& material, const Vec3& wo,
                                                  const Vec3& n, bool entering, double u) {
  const double eta_i = entering ? 1.0 : material.ior, eta_t = entering ? material.ior : 1.0;
  const double eta = eta_i / eta_t;
  const double cos_i = std::clamp(glm::dot(wo, n), 0.0, 1.0);
  const std::optional<double> cos_t = refracted_cosine(cos_i, eta);
  if (!cos_t) return sample_mirror(material, wo, n);
  const double reflectance = fresnel_dielectric(cos_i, 1.0, material.ior);  // the mistake
  if (u < reflectance) return sample_mirror(material, wo, n);
  return {glm::normalize(refract(wo, n, cos_i, *cos_t, eta)), material.tint, true, true};
}

/// No total internal reflection: cos(theta_t) = sqrt(1 - sin^2(theta_t)) unchecked, NaN past
/// the critical angle (R is NaN, u < R false: a NaN refraction).
inline BsdfSample dielectric_without_total_internal_reflection(const Material& material,
                                                               const Vec3& wo, const Vec3& n,
                                                               bool entering, double u) {
  const double eta_i = entering ? 1.0 : material.ior, eta_t = entering ? material.ior : 1.0;
  const double eta = eta_i / eta_t;
  const double cos_i = std::clamp(glm::dot(wo, n), 0.0, 1.0);
  const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));  // the mistake: no check
  const double reflectance = fresnel_dielectric(cos_i, cos_t, eta_i, eta_t);
  if (u < reflectance) return sample_mirror(material, wo, n);
  return {glm::normalize(refract(wo, n, cos_i, cos_t, eta)), material.tint, true, true};
}

/// The refracted direction divided by eta: -wo + (cos_i - cos_t / eta) n points Snell's way
/// but has length 1 / eta.
inline BsdfSample dielectric_refraction_not_normalised(const Material& material, const Vec3& wo,
                                                       const Vec3& n, bool entering, double u) {
  const double eta_i = entering ? 1.0 : material.ior, eta_t = entering ? material.ior : 1.0;
  const double eta = eta_i / eta_t;
  const double cos_i = std::clamp(glm::dot(wo, n), 0.0, 1.0);
  const std::optional<double> cos_t = refracted_cosine(cos_i, eta);
  if (!cos_t) return sample_mirror(material, wo, n);
  const double reflectance = dielectric_reflectance(material, cos_i, *cos_t, eta_i, eta_t);
  if (u < reflectance) return sample_mirror(material, wo, n);
  return {-wo + (cos_i - *cos_t / eta) * n, material.tint, true, true};  // the mistake
}

}  // namespace mcrt::testing::assignment
