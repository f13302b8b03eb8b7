#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "gi/pathtrace/path_trace.hpp"
#include "gi/render/truth.hpp"

namespace gi {

// A converged path-traced picture is the truth every method of the course is scored
// against (render/truth.hpp): the files, their checks and how a picture is scored are the
// render floor's; what a path-traced truth is of is said here.

// A hash (FNV-1a, 64 bits, as 16 hex digits) of the scene as the path tracer sees it and
// of what else fixes the converged picture (size, depth limit): a truth of a scene that
// has since changed (e.g. new reflectances) is refused, not used.
std::string path_truth_fingerprint(const PathScene& scene, const PathSettings& settings, int width, int height);

// The key of a path-traced truth of that scene, settings and size, made by `code`.
TruthKey path_truth_key(const PathScene& scene, const PathSettings& settings, int width, int height,
                        const std::string& code = "any");

// What a path-traced truth says of itself beside its key: scene, strategy, depth limits.
std::vector<std::pair<std::string, std::string>> path_truth_about(const std::string& scene,
                                                                  const PathSettings& settings);

// SHA-256 of the sources of the path tracer and every topic it uses, computed when the
// library is built (cmake/CodeFingerprint.cmake). A truth a lesson renders and keeps is
// keyed by it, so that changed code -- a student's lab 14 -- renders it again. The stored
// truths in lessons/references/ are not: they are what a student's code is measured
// against, whatever that code is.
const char* path_code_fingerprint();

// The stored truths of lessons/references/ (made by 14_make_reference): the Cornell box
// at 256 x 256, the box with the mirror and glass balls at 128 x 128, as
// FOLDER/<scene>_<side>x<side>.*. The side of `scene`'s, or nothing for a scene without one.
std::optional<int> stored_truth_side(const std::string& scene);

// The stored truth of `scene` (rendered with the default path settings) in `folder`,
// averaged down to width x height (a square size that divides its side). Throws
// std::runtime_error in one line naming the file and what is wrong when it is missing,
// damaged or made for another scene or size, and std::invalid_argument for a scene
// without one or a size that does not divide it.
Truth stored_truth(const std::filesystem::path& folder, const std::string& scene, int width, int height);
// The same from the files at `stem`, side x side.
Truth stored_truth_at(const std::filesystem::path& stem, const std::string& scene, int side, int width, int height);

}  // namespace gi
