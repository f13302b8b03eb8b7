#include "gi/scene/scene_file.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "gi/core/did_you_mean.hpp"
#include "gi/scene/obj_file.hpp"
#include "gi/scene/scene_schema.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;
using Fields = SchemaReader::Fields;

// The schema layer: the JSON tree (json.hpp) into a SceneFile, every value checked
// where it stands. The keys are documented in scene_file.hpp.
class SceneReader {
 public:
  SceneReader(const fs::path& file, const SceneFileRules& rules) : path_(file), rules_(rules), schema_(file.string()) {
    out_.file = file.string();
  }

  SceneFile read(const std::string& text) {
    const JsonValue root = parse_json(text, schema_.file());
    const Fields top = schema_.object(root, "",
                                      {{"name"}, {"camera", true}, {"background"}, {"ambient_light"}, {"materials"},
                                       {"spheres"}, {"planes"}, {"boxes"}, {"quads"}, {"polygons"}, {"meshes"},
                                       {"point_lights"}, {"quad_lights"}});
    Scene& s = out_.scene;
    s.name = top["name"] ? schema_.text(*top["name"], "name") : path_.stem().string();
    if (top["background"]) s.background = schema_.colour(*top["background"], "background");
    if (top["ambient_light"]) s.ambient_light = schema_.colour(*top["ambient_light"], "ambient_light");
    camera(*top["camera"]);
    each(top, "materials", [&](const JsonValue& v, const std::string& path) { material(v, path); });
    each(top, "spheres", [&](const JsonValue& v, const std::string& path) { sphere(v, path); });
    each(top, "planes", [&](const JsonValue& v, const std::string& path) { plane(v, path); });
    each(top, "boxes", [&](const JsonValue& v, const std::string& path) { box(v, path); });
    each(top, "quads", [&](const JsonValue& v, const std::string& path) { quad(v, path); });
    each(top, "polygons", [&](const JsonValue& v, const std::string& path) { polygon(v, path); });
    each(top, "meshes", [&](const JsonValue& v, const std::string& path) { mesh(v, path); });
    each(top, "point_lights", [&](const JsonValue& v, const std::string& path) { point_light(v, path); });
    each(top, "quad_lights", [&](const JsonValue& v, const std::string& path) { quad_light(v, path); });
    if (s.spheres.empty() && s.planes.empty() && out_.polygons.empty())
      schema_.fail(root, "", "the scene has nothing in it: add spheres, planes, quads, polygons or meshes");
    for (std::size_t i = 0; i < s.spheres.size(); ++i)
      if (length(s.camera.eye - s.spheres[i].center) < s.spheres[i].radius)
        out_.warnings.push_back(schema_.warning(*camera_at_, "camera.eye", "inside spheres[" + std::to_string(i) +
                                                                          "]: the picture shows its inside"));
    return std::move(out_);
  }

  std::string file_text() const {
    std::error_code error;
    const fs::file_status status = fs::status(path_, error);
    if (!fs::exists(status)) throw SceneError(schema_.file(), "no such file");
    if (!fs::is_regular_file(status)) throw SceneError(schema_.file(), "not a file one can read a scene from");
    if (fs::file_size(path_, error) > JsonLimits{}.max_bytes || error)
      throw SceneError(schema_.file(), "larger than " + size_text(JsonLimits{}.max_bytes) +
                                           "; put large meshes in an OBJ file (\"meshes\")");
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw SceneError(schema_.file(), "cannot read the file");
    return text.str();
  }

 private:
  template <class PerItem>
  void each(const Fields& top, const char* key, PerItem per_item) {
    if (const JsonValue* list = top[key]) {
      const auto& items = schema_.array(*list, key);
      for (std::size_t i = 0; i < items.size(); ++i) per_item(items[i], item_path(key, i));
    }
  }

  // Runs a library check (scene.hpp's adders, camera_frame) and rewraps what it throws
  // at the value's position, without the library's own prefix ("quad: ").
  template <class Check>
  void checked(const JsonValue& at, const std::string& path, Check check) {
    try {
      check();
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      const std::size_t colon = what.find(": ");
      schema_.fail(at, path, colon != std::string::npos && colon < 20 ? what.substr(colon + 2) : what);
    }
  }

  void camera(const JsonValue& v) {
    camera_at_ = &v;
    const Fields f = schema_.object(v, "camera", {{"eye", true}, {"look_at", true}, {"up"}, {"fov"}});
    Camera& c = out_.scene.camera;
    c.eye = schema_.point(*f["eye"], "camera.eye");
    c.look_at = schema_.point(*f["look_at"], "camera.look_at");
    if (f["up"]) c.up = schema_.point(*f["up"], "camera.up");
    if (f["fov"]) c.vertical_fov = schema_.number(*f["fov"], "camera.fov", 0, 180, true);
    if (c.vertical_fov == 180) schema_.fail(*f["fov"], "camera.fov", "must be < 180, got 180");
    checked(v, "camera", [&] { (void)camera_frame(c, 1, 1); });
  }

  void material(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"name", true}, {"diffuse"}, {"ambient"}, {"specular"}, {"shininess"},
                                              {"mirror"}, {"transmission"}, {"ior"}, {"emission"}, {"checker_size"},
                                              {"checker_diffuse"}});
    Material m;
    m.name = schema_.text(*f["name"], path + ".name");
    if (const int earlier = find_material(m.name); earlier >= 0)
      schema_.fail(*f["name"], path + ".name",
                   "'" + m.name + "' is the name of materials[" + std::to_string(earlier) + "] already");
    const auto colour = [&](const char* key, Color& c) {
      if (f[key]) c = schema_.colour(*f[key], member_path(path, key));
    };
    const auto number = [&](const char* key, double& x, double min, double max, bool above_min = false) {
      if (f[key]) x = schema_.number(*f[key], member_path(path, key), min, max, above_min);
    };
    colour("diffuse", m.diffuse), colour("specular", m.specular), colour("mirror", m.mirror);
    colour("transmission", m.transmission), colour("emission", m.emission);
    colour("checker_diffuse", m.checker_diffuse);
    number("ambient", m.ambient, 0, 1e6), number("shininess", m.shininess, 0, 1e6);
    number("ior", m.ior, 0, 100, true), number("checker_size", m.checker_size, 0, 1e6);
    checked(v, path, [&] { out_.scene.add(m); });
    material_index_.emplace(m.name, static_cast<int>(out_.scene.materials.size()) - 1);
  }

  // The index of the material named `name`, or -1; the names, for "did you mean".
  int find_material(const std::string& name) const {
    const auto found = material_index_.find(name);
    return found == material_index_.end() ? -1 : found->second;
  }
  std::vector<std::string> material_names() const {
    std::vector<std::string> names;
    for (const Material& m : out_.scene.materials) names.push_back(m.name);
    return names;
  }

  // The index of the material a shape names.
  int material_named(const std::string& name, const JsonValue& at, const std::string& path) const {
    const int found = find_material(name);
    if (found < 0)
      schema_.fail(at, path,
                   "no material is named '" + name.substr(0, 64) + "'" + did_you_mean(name, material_names()) +
                       (out_.scene.materials.empty() ? " (the file has no \"materials\")" : ""));
    return found;
  }
  int material_of(const Fields& f, const std::string& path) const {
    return material_named(schema_.text(*f["material"], path + ".material"), *f["material"], path + ".material");
  }

  void sphere(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"center", true}, {"radius", true}, {"material", true}});
    const Sphere s{schema_.point(*f["center"], path + ".center"),
                   schema_.number(*f["radius"], path + ".radius", 0, max_coordinate, true), material_of(f, path)};
    checked(v, path, [&] { out_.scene.add(s); });
    if (!out_.first_sphere) out_.first_sphere = schema_.where(v, path);
  }

  void plane(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"point", true}, {"normal", true}, {"material", true}});
    const vec3 n = schema_.point(*f["normal"], path + ".normal");
    if (!(length(n) > 0)) schema_.fail(*f["normal"], path + ".normal", "must not be [0, 0, 0]");
    const Plane p{schema_.point(*f["point"], path + ".point"), normalize(n), material_of(f, path)};
    checked(v, path, [&] { out_.scene.add(p); });
    if (!out_.first_plane) out_.first_plane = schema_.where(v, path);
  }

  Quad parallelogram(const Fields& f, const std::string& path, int material) const {
    return {schema_.point(*f["corner"], path + ".corner"), schema_.point(*f["edge_u"], path + ".edge_u"),
            schema_.point(*f["edge_v"], path + ".edge_v"), material};
  }

  void add_polygon(const FlatPolygon& shape, int material, std::string name, bool from_quads, const JsonValue& at,
                   const std::string& path) {
    if (const std::string problem = polygon_problem(shape); !problem.empty()) schema_.fail(at, path, problem);
    if (out_.polygons.size() >= rules_.max_polygons) schema_.fail(at, path, too_many_polygons());
    out_.polygons.push_back({shape, material, std::move(name), from_quads});
  }

  std::string name_or(const Fields& f, const std::string& path) const {
    return f["name"] ? schema_.text(*f["name"], path + ".name") : path;
  }

  // A quad for the ray tracer, and the same parallelogram as a polygon for radiosity.
  void add_quad(const Quad& q, const std::string& name, const JsonValue& at, const std::string& path) {
    checked(at, path, [&] { out_.scene.add(q); });
    const FlatPolygon shape{{q.corner, q.corner + q.edge_u, q.corner + q.edge_u + q.edge_v, q.corner + q.edge_v}, 4};
    add_polygon(shape, q.material, name, true, at, path);
  }

  void quad(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"corner", true}, {"edge_u", true}, {"edge_v", true},
                                              {"material", true}, {"name"}});
    add_quad(parallelogram(f, path, material_of(f, path)), name_or(f, path), v, path);
  }

  void box(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"min", true}, {"max", true}, {"material", true}, {"name"}});
    const vec3 lo = schema_.point(*f["min"], path + ".min"), hi = schema_.point(*f["max"], path + ".max");
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
      schema_.fail(*f["max"], path + ".max", "must exceed min on every axis");
    for (const Quad& q : box_quads(lo, hi, material_of(f, path))) add_quad(q, name_or(f, path), v, path);
  }

  void polygon(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"corners", true}, {"material", true}, {"name"}});
    const std::vector<JsonValue>& corners = schema_.array(*f["corners"], path + ".corners");
    if (corners.size() != 3 && corners.size() != 4)
      schema_.fail(*f["corners"], path + ".corners",
                   "a polygon has 3 or 4 corners, got " + std::to_string(corners.size()) +
                       " (cut larger polygons into triangles and quadrilaterals)");
    FlatPolygon shape{{}, static_cast<int>(corners.size())};
    for (std::size_t i = 0; i < corners.size(); ++i)
      shape.corners[i] = schema_.point(corners[i], item_path(path + ".corners", i));
    add_polygon(shape, material_of(f, path), name_or(f, path), false, *f["corners"], path + ".corners");
  }

  std::string too_many_polygons() const {
    return "more than " + std::to_string(rules_.max_polygons) +
           " polygons (quads, boxes' faces, polygons and mesh faces together), the most this lesson takes";
  }

  // The folders meshes may come from (SceneFileRules), symbolic links followed.
  std::vector<fs::path> mesh_folders() const {
    std::vector<fs::path> folders;
    std::error_code error;
    const fs::path own = fs::weakly_canonical(fs::absolute(path_, error).parent_path(), error);
    if (!error) folders.push_back(own);
    if (!rules_.mesh_folder.empty()) {
      const fs::path extra = fs::weakly_canonical(fs::absolute(rules_.mesh_folder, error), error);
      if (!error) folders.push_back(extra);
    }
    return folders;
  }

  static bool below(const fs::path& file, const fs::path& folder) {
    const fs::path rest = file.lexically_relative(folder);
    return !rest.empty() && *rest.begin() != ".." && !rest.is_absolute();
  }

  void mesh(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"file", true}, {"material"}});
    const JsonValue& at = *f["file"];
    const std::string relative = schema_.text(at, path + ".file");
    const std::string shown = (path_.parent_path() / relative).lexically_normal().string();
    const int fallback = f["material"] ? material_of(f, path) : -1;
    const fs::path file = path_.parent_path() / relative;
    // Where it really is, asked of nothing but the path (and the links on it), so
    // that a refusal says nothing about a file outside.
    std::error_code error;
    const fs::path real = fs::weakly_canonical(fs::absolute(file, error), error);
    const std::vector<fs::path> folders = mesh_folders();
    if (error || std::none_of(folders.begin(), folders.end(), [&](const fs::path& d) { return below(real, d); }))
      schema_.fail(at, path + ".file",
                   "a mesh must lie below the scene file's folder" +
                       std::string(rules_.mesh_folder.empty() ? "" : " or below " + rules_.mesh_folder.string()) +
                       " (--mesh-folder DIR allows another): " + shown);
    if (!fs::exists(real, error)) schema_.fail(at, path + ".file", "no such file: " + shown);
    // Before its size: a folder or a device has none (file_size fails, or /dev/zero never ends).
    if (!fs::is_regular_file(real, error)) schema_.fail(at, path + ".file", "not a file one can read a mesh from: " + shown);
    std::string extension = real.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension != ".obj") schema_.fail(at, path + ".file", "a mesh is an OBJ file, its name ending in .obj: " + shown);
    const ObjLimits most;
    mesh_bytes_ += fs::file_size(real, error);
    if (mesh_bytes_ > most.max_bytes)
      schema_.fail(at, path + ".file", "the meshes together are larger than " + size_text(most.max_bytes));
    // Faces are counted as they are read: the file stops at the scene's limit.
    ObjLimits limits;
    const std::size_t room = rules_.max_polygons - std::min(rules_.max_polygons, out_.polygons.size());
    limits.max_faces = std::min(most.max_faces - std::min(most.max_faces, mesh_faces_), room);
    if (limits.max_faces == room) limits.why_max_faces = too_many_polygons();
    const ObjMesh obj = read_obj(real, shown, limits);
    mesh_faces_ += obj.faces.size();
    std::vector<int> used;  // the scene's index of each usemtl name, -1 if it has none
    for (const std::string& name : obj.material_names) used.push_back(find_material(name));
    for (const ObjFace& face : obj.faces) {
      const FileLocation at{shown, face.line, 1, "f"};
      const int material = face.material < 0 ? fallback : used[face.material];
      if (face.material < 0 && fallback < 0)
        throw SceneError(at, "no material: put 'usemtl NAME' before it, or give " + path + " a \"material\"");
      if (material < 0) {
        const std::string& name = obj.material_names[face.material];
        throw SceneError(at, "its material '" + name.substr(0, 64) + "' (usemtl) is not among the materials of " +
                                 schema_.file() + did_you_mean(name, material_names()));
      }
      out_.polygons.push_back({face.polygon, material, shown + ":" + std::to_string(face.line), false});
    }
  }

  Color intensity(const Fields& f, const std::string& path) const {
    const Color i = schema_.colour(*f["intensity"], path + ".intensity");
    if (!(max_component(i) > 0)) schema_.fail(*f["intensity"], path + ".intensity", "a light must give light, got 0");
    return i;
  }

  void point_light(const JsonValue& v, const std::string& path) {
    const Fields f = schema_.object(v, path, {{"position", true}, {"intensity", true}});
    const PointLight light{schema_.point(*f["position"], path + ".position"), intensity(f, path)};
    checked(v, path, [&] { out_.scene.add(light); });
  }

  void quad_light(const JsonValue& v, const std::string& path) {
    const Fields f =
        schema_.object(v, path, {{"corner", true}, {"edge_u", true}, {"edge_v", true}, {"intensity", true}});
    const QuadLight light{parallelogram(f, path, 0), intensity(f, path)};
    checked(v, path, [&] { out_.scene.add(light); });
  }

  fs::path path_;
  SceneFileRules rules_;
  SchemaReader schema_;
  SceneFile out_;
  const JsonValue* camera_at_ = nullptr;
  // By name (a file may name many materials: no search through them all per shape).
  std::unordered_map<std::string, int> material_index_;
  // What the meshes have read so far: their limits hold for all of them together.
  std::size_t mesh_faces_ = 0;
  std::uintmax_t mesh_bytes_ = 0;
};

}  // namespace

SceneFile read_scene_file(const fs::path& file, const SceneFileRules& rules) {
  SceneReader reader(file, rules);
  return reader.read(reader.file_text());
}

SceneFile read_scene_text(const std::string& text, const fs::path& file, const SceneFileRules& rules) {
  return SceneReader(file, rules).read(text);
}

}  // namespace gi
