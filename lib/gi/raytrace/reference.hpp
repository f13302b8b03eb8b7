#pragma once
#include <filesystem>
#include <string>

#include "gi/image/image.hpp"
#include "gi/raytrace/render.hpp"

namespace gi {

// A reference image is expensive (hundreds of samples per pixel) and the same on
// every run with the same scene, settings and code, so it is rendered once and kept
// in `folder`:
//   reference_<h>.pfm  the image (PFM keeps the linear floats exactly)
//   reference_<h>.key  the key -- the scene, every setting exactly, the fingerprint
//                      of the render code -- and the PFM's size and checksum
// where <h> is a hash of the scene and settings (not of the code: changed code
// renders the same file again rather than adding one). The image is read back only
// when the stored key equals this one and the PFM's size, header and checksum match;
// otherwise (no file, another key, a truncated, damaged or hand-edited file) it is
// rendered and both files are written again, each atomically, the PFM first: a run
// killed between the two leaves a PFM without its key, which is not trusted.
// `scene_key` names everything that made the scene, exactly ("soft_shadow_scene,
// light size 0.0504"); the settings and the code are added here.
struct CachedImage {
  Image image;
  std::filesystem::path file;  // the PFM
  bool from_cache = false;     // read back, rather than rendered now
  std::string reason;          // why it was rendered: "no cached image", "... made by other library code" ...
};
CachedImage cached_reference(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads,
                             const std::string& scene_key, const std::filesystem::path& folder);

// The key: one line per input, doubles to 17 significant digits (they read back
// exactly), and the fingerprint of the code.
std::string reference_key(const World& world, const RenderSettings& settings, std::uint64_t seed,
                          const std::string& scene_key);

// SHA-256 of the source files of core, image, geometry, scene, accel and raytrace,
// computed when the library is built (cmake/CodeFingerprint.cmake): a student's fix
// to a lab makes every cached reference stale.
const char* render_code_fingerprint();

}  // namespace gi
