#pragma once
/// Converged reference images cached between runs: one per scene, light scale, image size and
/// depth cut, rendered by MIS with Russian roulette at many samples per pixel. Beside each PFM a
/// JSON gives its settings, render time, standard error, and the PFM's size and checksum
/// (written last: the pair is one unit); an entry is reused only when all of it matches. The
/// cache is a folder of its own (the XDG cache by default), tagged with CACHEDIR.TAG, and
/// deletes only files its index.txt names. The furnace needs none: its reference is the
/// closed form.

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "render/image.hpp"
#include "render/scene.hpp"

namespace CLI {
class App;
}

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

/// `flag` (--reference-dir) if given, else $XDG_CACHE_HOME/mcrt-companion, else
/// $HOME/.cache/mcrt-companion (absolute paths only); UsageError if neither is set.
std::filesystem::path reference_folder(const std::filesystem::path& flag);

/// The flag `--reference-dir` (into `dir`), with the help every chapter with a reference gives.
void add_reference_dir_option(CLI::App& app, std::filesystem::path& dir);

/// Before any work: UsageError naming --reference-dir if `dir` and `out` lie inside one
/// another, or `dir` is a link, not a folder, another user's, writable by others without the
/// sticky bit, or holds files without our CACHEDIR.TAG. Creates and tags a missing or empty
/// folder (IoError if it cannot).
void check_reference_folder(const std::filesystem::path& dir, const std::filesystem::path& out);

/// The reference for `spec`: the furnace's closed form, a cached entry that verifies (regular
/// files of ours, the spec's settings, the PFM's size and recorded checksum, finite
/// non-negative values), or a new render written there (one line on stderr says why a cached
/// one is not used). Writers name their locked temporaries in the index first; only those
/// whose lock is free and PFMs without a JSON, named by the index, are ever removed. Throws
/// IoError if it cannot write.
Reference load_or_render_reference(const std::filesystem::path& dir, const ReferenceSpec& spec);

/// Rays a reference render would trace at most (app/ray_limit): pixels x spp x rays_per_sample.
double reference_predicted_rays(const ReferenceSpec& spec, double rays_per_sample);

}  // namespace mcrt
