#pragma once
/// Converged reference images, cached on disk between runs: one per scene, light scale, image
/// size and depth cut, rendered by the best estimator (MIS, power heuristic, paths ended by
/// Russian roulette) at many samples per pixel. Beside each PFM a JSON file gives the settings
/// it was made with (seed, spp, scene, light scale, size, depth, estimator), its render time,
/// its standard error, and the PFM's size and checksum (written last: the pair is one unit). A
/// cached reference is reused only when every setting matches and the PFM verifies; otherwise
/// it is rendered again, with a progress bar.
///
/// The cache is a folder of its own, $XDG_CACHE_HOME/mcrt-companion (~/.cache/mcrt-companion)
/// unless --reference-dir names one, marked with a CACHEDIR.TAG (the Cache Directory Tagging
/// convention) and holding index.txt, the names of the files it wrote: it deletes only those.
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

/// The cache folder: `flag` (--reference-dir) if given, else $XDG_CACHE_HOME/mcrt-companion
/// (an absolute XDG_CACHE_HOME), else $HOME/.cache/mcrt-companion. Throws UsageError (exit 2,
/// naming --reference-dir) when neither variable is set to an absolute path.
std::filesystem::path reference_folder(const std::filesystem::path& flag);

/// Call it with the flags, before any work. Throws UsageError (exit 2, one line naming
/// --reference-dir) if `dir` and `out` (--out) lie inside one another, or `dir` may not hold
/// the cache: a symbolic link, not a folder, another user's, writable by others without the
/// sticky bit (anyone could replace its files), or a folder holding files without our
/// CACHEDIR.TAG. Creates and tags the folder if it is missing or empty; throws IoError (exit 1)
/// if it cannot.
void check_reference_folder(const std::filesystem::path& dir, const std::filesystem::path& out);

/// The reference for `spec`: the furnace's closed form; else the cached dir/<stem>.pfm if it
/// is whole (below); else a new render written there. The folder is checked as by
/// check_reference_folder, opened once, and every file is read and written relative to it.
/// A cached reference is used only if its JSON (a regular file of ours) has the spec's
/// settings and records the PFM's size and checksum, the PFM (a regular file of ours) has
/// that size (checked before reading), that checksum, and only finite non-negative values; any
/// other cache is rendered again, with one line on stderr saying why. Writers create both
/// temporary files exclusively and locked (io/exclusive_file.hpp), name them in the index, then
/// rename the PFM and the JSON, under an exclusive lock of the folder (readers take it shared).
/// Removed, and only if the index names them and they are regular files of ours: temporaries
/// whose lock is free (their writer is gone, whatever its PID namespace) and PFMs without a
/// JSON. Throws IoError if it cannot write; a failure never removes a cached entry.
Reference load_or_render_reference(const std::filesystem::path& dir, const ReferenceSpec& spec);

/// Rays a reference render would trace at most, for app/ray_limit (the estimate the chapter
/// refuses too much work by): pixels x spp x rays_per_sample.
double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample);

}  // namespace mcrt
