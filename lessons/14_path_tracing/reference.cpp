// Lesson 14: the references (reference.hpp).
#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "gi/report/progress.hpp"

namespace lesson14 {

bool uses_stored_reference(const Settings& s) {
  return s.scene == "cornell" && s.width == s.height && 256 % s.width == 0 &&
         s.path.max_depth == gi::PathSettings{}.max_depth;
}

gi::Truth own_reference(const gi::PathScene& scene, const Settings& s, gi::Lesson& lesson) {
  const std::string stem = "reference_" + s.scene + "_" + std::to_string(s.width) + "x" + std::to_string(s.height) +
                           "_depth" + std::to_string(s.path.max_depth);
  gi::TruthKey key = gi::path_truth_key(scene, s.path, s.width, s.height, gi::path_code_fingerprint());
  key.fingerprint += " spp " + std::to_string(s.reference_spp);
  const std::uint64_t seed = s.seed + 1000000;  // streams no picture measured uses
  const gi::CachedTruth cached = gi::cached_truth(lesson.out() / stem, key, seed, [&](const std::string& why) {
    lesson.say("rendering a reference: " + std::to_string(s.reference_spp) + " spp (" + why + ")");
    gi::Film film = gi::make_film(s.width, s.height, seed);
    gi::Progress progress("reference", s.reference_spp);
    for (int done = 0; done < s.reference_spp; done += 16) {
      gi::path_trace(film, scene, s.path, std::min(16, s.reference_spp - done), s.threads);
      progress.advance(std::min(16, s.reference_spp - done));
    }
    progress.finish();
    return film;
  }, gi::path_truth_about(s.scene, s.path));
  if (cached.from_cache) lesson.say("reference: read from " + cached.stem.string() + ".*, kept by an earlier run");
  for (const auto& file : gi::truth_files(cached.stem))
    lesson.record(file, gi::OutputKind::Cache, "the reference kept for later runs");
  return cached.truth;
}

gi::Truth furnace_truth(const Settings& s) {
  double L = 0;
  for (int k = 0; k <= s.path.max_depth; ++k) L += std::pow(0.5, k);
  gi::Truth exact;
  exact.mean = gi::Image(s.width, s.height, gi::Pixel(float(L)));
  exact.standard_error = gi::Image(s.width, s.height);
  return exact;
}

}  // namespace lesson14
