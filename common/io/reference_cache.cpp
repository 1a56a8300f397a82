#include "io/reference_cache.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "render/mis.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/russian_roulette.hpp"
#include "render/two_render_error.hpp"

namespace mcrt {

namespace {

// The reference's samples start here, far from every sample index a chapter's images use.
constexpr std::uint64_t k_reference_first_sample = std::uint64_t{1} << 30;

bool is_furnace(const ReferenceSpec& spec) { return spec.scene.scene == "furnace"; }

Reference furnace_reference(const ReferenceSpec& spec) {
  const SceneParams& p = spec.scene.params;
  const double value =
      spec.max_depth < 0 ? furnace_radiance_untruncated(p.furnace_albedo, p.furnace_emission)
                         : furnace_radiance(p.furnace_albedo, p.furnace_emission, spec.max_depth);
  Reference r;
  r.image = Image(spec.width, spec.height, Color(value));
  r.info = reference_settings(spec);
  r.info["estimator"] = "closed form";
  r.info["spp"] = 0;
  r.info["standard_error_rms"] = 0.0;
  return r;
}

std::optional<nlohmann::ordered_json> read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// The cached reference if its settings match and its image reads back at the right size.
std::optional<Reference> load_cached(const std::filesystem::path& dir, const ReferenceSpec& spec) {
  const std::string stem = reference_stem(spec);
  const auto info = read_json(dir / (stem + ".json"));
  if (!info || !info->contains("settings") || (*info)["settings"] != reference_settings(spec))
    return std::nullopt;
  try {
    Reference r;
    r.image = read_pfm(dir / (stem + ".pfm"));
    if (r.image.width != spec.width || r.image.height != spec.height) return std::nullopt;
    r.info = *info;
    return r;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Two independent halves A and B (spp/2 each, at least 1): the reference is their mean, and
// E[(A - B)^2] / 2 = Var[A] gives its standard error, Var[(A + B)/2] = Var[A] / 2.
Reference render_reference(const ReferenceSpec& spec) {
  const Scene scene = make_scene(spec.scene.scene, spec.scene.params);
  const Camera camera(scene.camera, spec.width, spec.height);
  const int half = std::max(1, spec.spp / 2);
  ProgressBar progress(fmt::format("reference {}", reference_stem(spec)), 2ull * spec.height,
                       spec.quiet);
  const PathEnd end{Roulette{}, spec.max_depth};
  const auto mis = [&](const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_mis_radiance(scene, ray, end, MisHeuristic::power, rng, count);
  };
  const RenderSettings a_settings{half, k_reference_first_sample, spec.seed, spec.threads,
                                  &progress};
  RenderSettings b_settings = a_settings;
  b_settings.first_sample += static_cast<std::uint64_t>(half);
  const RenderResult a = render(camera, a_settings, mis);
  const RenderResult b = render(camera, b_settings, mis);
  progress.finish();
  Reference r;
  r.image = Image(spec.width, spec.height);
  double relative_variance = 0.0;  // mean of Var[R] / (R^2 + 0.01): its own relative MSE
  for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
    // Rounded to float, as the PFM stores it: a fresh reference and a cached one are the same.
    r.image.pixels[i] = Color(glm::vec3(0.5 * (a.image.pixels[i] + b.image.pixels[i])));
    for (int c = 0; c < 3; ++c) {
      const double d = a.image.pixels[i][c] - b.image.pixels[i][c], m = r.image.pixels[i][c];
      relative_variance += d * d / 4.0 / (m * m + 0.01);  // (A - B)^2 / 4 estimates Var[R]
    }
  }
  relative_variance /= 3.0 * static_cast<double>(r.image.pixels.size());
  r.rendered = true;
  r.seconds = a.seconds + b.seconds;
  r.info = {{"settings", reference_settings(spec)},
            {"estimator", "mis (power heuristic), Russian roulette"},
            {"seed", spec.seed},
            {"spp", 2 * half},
            {"seconds", r.seconds},
            {"rays", a.rays + b.rays},
            {"standard_error_rms", std::sqrt(two_render_mean_squared_error(a.image, b.image) / 2.0)},
            {"relative_mse_of_reference", relative_variance},
            {"mean_radiance", mean_radiance(r.image)}};
  return r;
}

}  // namespace

std::string reference_stem(const ReferenceSpec& spec) {
  std::string stem = fmt::format("{}_ls{}_{}x{}", spec.scene.scene,
                                 spec.scene.scene == "cornell" ? spec.scene.params.light_scale : 1.0,
                                 spec.width, spec.height);
  if (is_furnace(spec))
    stem += fmt::format("_a{}_e{}", spec.scene.params.furnace_albedo,
                        spec.scene.params.furnace_emission);
  if (spec.max_depth >= 0) stem += fmt::format("_d{}", spec.max_depth);
  return stem;
}

nlohmann::ordered_json reference_settings(const ReferenceSpec& spec) {
  const SceneParams& p = spec.scene.params;
  return {{"scene", spec.scene.scene},
          {"light_scale", spec.scene.scene == "cornell" ? p.light_scale : 1.0},
          {"furnace_albedo", p.furnace_albedo},
          {"furnace_emission", p.furnace_emission},
          {"width", spec.width},
          {"height", spec.height},
          {"spp", 2 * std::max(1, spec.spp / 2)},
          {"max_depth", spec.max_depth},
          {"seed", spec.seed},
          {"estimator", "mis_power"}};
}

Reference load_or_render_reference(const std::filesystem::path& dir, const ReferenceSpec& spec) {
  if (is_furnace(spec)) return furnace_reference(spec);
  if (auto cached = load_cached(dir, spec)) return std::move(*cached);
  Reference r = render_reference(spec);
  const bool created = std::filesystem::create_directories(dir);
  const std::string stem = reference_stem(spec);
  try {
    write_file_atomic(dir / (stem + ".pfm"), encode_pfm(r.image));
    write_file_atomic(dir / (stem + ".json"), r.info.dump(2) + "\n");
  } catch (...) {
    // The cache holds whole references only: no PFM without its JSON, no folder left empty.
    std::error_code ignored;
    std::filesystem::remove(dir / (stem + ".pfm"), ignored);
    if (created) std::filesystem::remove(dir, ignored);  // removes it only if empty
    throw;
  }
  return r;
}

double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample) {
  return static_cast<double>(spec.width) * spec.height * 2.0 * std::max(1, spec.spp / 2) *
         rays_per_sample;
}

}  // namespace mcrt
