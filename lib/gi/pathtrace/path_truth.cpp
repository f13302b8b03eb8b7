#include "gi/pathtrace/path_truth.hpp"

#include <sstream>
#include <stdexcept>

#include "gi/pathtrace/bsdf.hpp"
#include "gi/pathtrace/path_scenes.hpp"

namespace gi {

namespace {

// FNV-1a over the bytes of each value fed in.
struct Fingerprint {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  void add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ULL;
  }
  void add(double x) { add(&x, sizeof x); }
  void add(const vec3& v) { add(v.x), add(v.y), add(v.z); }
  std::string hex() const {
    std::ostringstream os;
    os << std::hex;
    os.width(16);
    os.fill('0');
    os << hash;
    return os.str();
  }
};

}  // namespace

std::string path_truth_fingerprint(const PathScene& scene, const PathSettings& settings, int width, int height) {
  const Scene& s = scene.scene();
  Fingerprint f;
  for (const Material& m : s.materials) {
    for (const Color& c : {m.diffuse, m.mirror, m.transmission, m.emission, m.checker_diffuse}) f.add(c);
    f.add(m.ior), f.add(m.checker_size);
    if (is_glossy(m)) f.add(m.specular), f.add(m.shininess);  // only then is the highlight seen
  }
  for (const Sphere& x : s.spheres) f.add(x.center), f.add(x.radius), f.add(double(x.material));
  for (const Plane& x : s.planes) f.add(x.point), f.add(x.normal), f.add(double(x.material));
  for (const Quad& x : s.quads) f.add(x.corner), f.add(x.edge_u), f.add(x.edge_v), f.add(double(x.material));
  for (const Triangle& x : s.triangles) f.add(x.a), f.add(x.b), f.add(x.c), f.add(double(x.material));
  f.add(s.background);
  f.add(s.camera.eye), f.add(s.camera.look_at), f.add(s.camera.up), f.add(s.camera.vertical_fov);
  f.add(double(width)), f.add(double(height)), f.add(double(settings.max_depth));
  return f.hex();
}

TruthKey path_truth_key(const PathScene& scene, const PathSettings& settings, int width, int height,
                        const std::string& code) {
  return {path_truth_fingerprint(scene, settings, width, height), code, width, height};
}

std::vector<std::pair<std::string, std::string>> path_truth_about(const std::string& scene,
                                                                  const PathSettings& settings) {
  return {{"scene", scene},
          {"strategy", name(settings.strategy)},
          {"max_depth", std::to_string(settings.max_depth)},
          {"roulette_depth", std::to_string(settings.roulette_depth)}};
}

std::optional<int> stored_truth_side(const std::string& scene) {
  if (scene == "cornell") return 256;
  if (scene == "cornell-spheres") return 128;
  return std::nullopt;
}

Truth stored_truth(const std::filesystem::path& folder, const std::string& scene, int width, int height) {
  const std::optional<int> side = stored_truth_side(scene);
  if (!side) throw std::invalid_argument("no stored truth of " + scene + " is kept");
  const std::string size = std::to_string(*side);
  return stored_truth_at(folder / (scene + "_" + size + "x" + size), scene, *side, width, height);
}

Truth stored_truth_at(const std::filesystem::path& stem, const std::string& scene, int side, int width, int height) {
  if (width != height || side % width != 0)
    throw std::invalid_argument("the stored truth of " + scene + " is " + std::to_string(side) + " x " +
                                std::to_string(side) + ": a square size that divides it is scored");
  std::string why;
  const PathScene path_scene = make_path_scene(make_path_scene_by_name(scene));
  const std::optional<Truth> truth = load_truth(stem, path_truth_key(path_scene, {}, side, side), &why);
  if (!truth)
    throw std::runtime_error("the stored truth of " + scene + " cannot be used: " + why +
                             " (bin/14_make_reference makes it; see its opening comment)");
  return side == width ? *truth : downsample(*truth, side / width);
}

}  // namespace gi
