#pragma once
/// Converged reference images, cached on disk between runs: one per scene, light scale, image
/// size and depth cut, rendered by the best estimator (MIS, power heuristic, paths ended by
/// Russian roulette) at many samples per pixel. Beside each PFM a JSON file gives the settings
/// it was made with (seed, spp, scene, light scale, size, depth, estimator), its render time and
/// its standard error. A cached reference is reused only when every setting matches; otherwise
/// (or when missing or unreadable) it is rendered again, with a progress bar, and written with
/// atomic file writes (the cache sits outside any run's output folder).
///
/// It lives in io rather than render because it reads and writes files (render may not include
/// io: the layering rule).
///
/// The furnace needs no cache: its reference is the closed form (reference_image returns it).

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "render/image.hpp"
#include "render/scene.hpp"

namespace mcrt {

struct ReferenceSpec {
  SceneOptions scene;
  int width = 160;
  int height = 120;
  int spp = 1024;
  int max_depth = -1;  ///< < 0: no depth cut (the whole series)
  std::uint64_t seed = 1;
  int threads = 1;
  bool quiet = false;  ///< no progress bar
};

struct Reference {
  Image image;
  nlohmann::ordered_json info;  ///< the JSON beside the PFM (closed form: its description)
  bool rendered = false;        ///< rendered by this call (not read from the cache)
  double seconds = 0.0;         ///< this call's render time (0 when read from the cache)
};

/// `<scene>_ls<scale>_<w>x<h>` (and `_d<depth>` with a depth cut): the cache's file stem.
std::string reference_stem(const ReferenceSpec& spec);

/// The settings the JSON must match for a cached reference to be reused.
nlohmann::ordered_json reference_settings(const ReferenceSpec& spec);

/// The reference for `spec`: the furnace's closed form; else dir/<stem>.pfm if its JSON's
/// settings match, else a new render written there. Throws IoError if it cannot write.
Reference load_or_render_reference(const std::filesystem::path& dir, const ReferenceSpec& spec);

/// Rays a reference render would trace at most, for io/ray_limit (the estimate the chapter
/// refuses too much work by): pixels x spp x rays_per_sample.
double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample);

}  // namespace mcrt
