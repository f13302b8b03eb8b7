#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "gi/raytrace/render.hpp"
#include "gi/render/truth.hpp"

namespace gi {

// A reference picture of the ray tracer's (many samples per pixel, or many shadow rays)
// is expensive and the same on every run with the same scene, settings and code, so it
// is rendered once and kept in `folder` as a truth (render/truth.hpp: the picture, its
// standard error, what it is and checksums), named reference_<h> with <h> a hash of the
// scene and settings (not of the code: changed code renders the same files again rather
// than adding some). It is read back only when made for exactly this scene, these
// settings and this code, and every file checks out; otherwise (none, another code, a
// truncated, damaged or hand-edited file) it is rendered and written again.
// `scene_key` names everything that made the scene, exactly ("soft_shadow_scene,
// light size 0.0504"); the settings, the seed and the code are added here.
CachedTruth cached_reference(const World& world, const RenderSettings& settings, std::uint64_t seed, int threads,
                             const std::string& scene_key, const std::filesystem::path& folder);

// The key: the fingerprint of the settings' text (one line per input, doubles to 17
// significant digits, so they read back exactly), the code's fingerprint and the size.
TruthKey reference_key(const World& world, const RenderSettings& settings, std::uint64_t seed,
                       const std::string& scene_key);

// SHA-256 of the source files of core, image, geometry, scene, accel, render and
// raytrace, computed when the library is built (cmake/CodeFingerprint.cmake): a
// student's fix to a lab makes every cached reference stale.
const char* render_code_fingerprint();

}  // namespace gi
