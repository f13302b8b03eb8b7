// What the lessons make of a scene file, and of --scene NAME|FILE (scene_file.hpp).
#include "gi/scene/scene_file.hpp"

#include <algorithm>
#include <stdexcept>

#include "gi/core/did_you_mean.hpp"
#include "gi/scene/builtin_scenes.hpp"

namespace gi {

Scene ray_tracing_scene(const SceneFile& file, std::vector<std::string>& warnings) {
  Scene s = file.scene;
  for (const FilePolygon& p : file.polygons) {
    if (p.from_quads) continue;
    const auto& c = p.shape.corners;
    s.add(Triangle{c[0], c[1], c[2], p.material});
    if (p.shape.count == 4) s.add(Triangle{c[0], c[2], c[3], p.material});
  }
  warnings.insert(warnings.end(), file.warnings.begin(), file.warnings.end());
  if (s.lights.empty() && s.area_lights.empty())
    warnings.push_back(file.file + ": no point_lights or quad_lights, which are what light the ray tracer's scene: "
                                   "it shows only what emits and the ambient light");
  return s;
}

bool names_a_file(const std::string& choice) {
  std::string lower = choice;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return choice.find('/') != std::string::npos || (lower.size() > 5 && lower.ends_with(".json"));
}

Scene load_scene(const std::string& choice, std::vector<std::string>& warnings, const SceneFileRules& rules) {
  if (names_a_file(choice)) return ray_tracing_scene(read_scene_file(choice, rules), warnings);
  const std::vector<std::string> names = scene_names();
  if (std::find(names.begin(), names.end(), choice) == names.end()) {
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown scene '" + choice.substr(0, 64) + "'" + did_you_mean(choice, names) +
                                "; built-in scenes: " + known + "; or a scene file ending in .json");
  }
  return make_scene(choice);
}

}  // namespace gi
