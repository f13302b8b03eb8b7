#include "gi/viewer/data.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "gi/core/atomic_file.hpp"
#include "gi/core/base64.hpp"

namespace gi {

namespace {

using nlohmann::json;

// Little-endian bytes of 32-bit values, base64-encoded (RFC 4648, with padding).
class TypedArray {
 public:
  explicit TypedArray(const char* type) : type_(type) {}
  void add(std::uint32_t bits) {
    for (int k = 0; k < 4; ++k) bytes_.push_back(static_cast<unsigned char>(bits >> (8 * k)));
  }
  void add_float(double v) {
    const float f = static_cast<float>(v);
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    add(bits);
  }
  void add_int(int v) { add(static_cast<std::uint32_t>(v)); }  // two's complement, as int32 reads it
  json finish() const {
    const std::string_view bytes(reinterpret_cast<const char*>(bytes_.data()), bytes_.size());
    return {{"type", type_}, {"count", bytes_.size() / 4}, {"base64", base64(bytes)}};
  }

 private:
  const char* type_;
  std::vector<unsigned char> bytes_;
};

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("viewer data: " + what);
}

// Values that must be finite also as float32, and must be finite to be drawn.
bool finite_float(double v) { return std::isfinite(static_cast<float>(v)); }

// One colour per element, appended to `a` after the checks.
void add_colours(TypedArray& a, const std::vector<Color>& values, std::size_t count, const std::string& what) {
  require(values.size() == count, what + " has " + std::to_string(values.size()) + " values for " +
                                       std::to_string(count) + " elements");
  for (const Color& c : values)
    for (int k = 0; k < 3; ++k) {
      require(finite_float(c[k]), what + " holds a value that is not finite (" + std::to_string(c[k]) + ")");
      a.add_float(c[k]);
    }
}

json colours(const std::vector<Color>& values, std::size_t count, const std::string& what) {
  TypedArray a("float32");
  add_colours(a, values, count, what);
  return a.finish();
}

json mesh_json(const ViewerData& d) {
  const std::size_t n = d.elements.size();
  TypedArray vertices("float32"), elements("uint32"), patch("int32"), surface("int32"), area("float32");
  for (const vec3& v : d.vertices)
    for (int k = 0; k < 3; ++k) {
      require(finite_float(v[k]), "a vertex is not finite");
      vertices.add_float(v[k]);
    }
  for (const auto& corners : d.elements)
    for (int c : corners) {
      require(c >= 0 && static_cast<std::size_t>(c) < d.vertices.size(), "an element's corner is not a vertex");
      elements.add_int(c);
    }
  require(d.element_patch.size() == n && d.element_surface.size() == n && d.area.size() == n,
          "element_patch, element_surface and area need one value per element");
  for (std::size_t i = 0; i < n; ++i) {
    require(d.element_patch[i] >= 0 && d.element_patch[i] < d.patches, "an element's patch is out of range");
    require(d.element_surface[i] >= 0 && static_cast<std::size_t>(d.element_surface[i]) < d.surfaces.size(),
            "an element's surface is out of range");
    require(finite_float(d.area[i]) && d.area[i] > 0, "an element's area is not positive");
    patch.add_int(d.element_patch[i]);
    surface.add_int(d.element_surface[i]);
    area.add_float(d.area[i]);
  }
  return {{"vertices", vertices.finish()},          {"elements", elements.finish()},
          {"element_patch", patch.finish()},        {"element_surface", surface.finish()},
          {"area", area.finish()},                  {"reflectance", colours(d.reflectance, n, "reflectance")},
          {"emission", colours(d.emission, n, "emission")}, {"surfaces", d.surfaces},
          {"patches", d.patches}};
}

json history_json(const std::vector<SolverStep>& history) {
  TypedArray step("int32"), r2("float32"), rinf("float32"), unshot("float32"), error("float32"), seconds("float32");
  bool with_error = !history.empty();
  for (const SolverStep& s : history) {
    step.add_int(s.step);
    r2.add_float(s.residual_2), rinf.add_float(s.residual_inf), unshot.add_float(s.unshot);
    error.add_float(s.error), seconds.add_float(s.seconds);
    with_error = with_error && s.error >= 0;  // -1: measured without a reference
  }
  json h = {{"step", step.finish()},     {"residual_2", r2.finish()}, {"residual_inf", rinf.finish()},
            {"unshot", unshot.finish()}, {"seconds", seconds.finish()}};
  if (with_error) h["error"] = error.finish();
  return h;
}

json run_json(const ViewerRun& run, std::size_t n, int patches) {
  const std::string what = "run '" + run.name + "'";
  require(std::isfinite(run.work_per_step) && run.work_per_step > 0, what + ": work per step must be positive");
  TypedArray step("int32"), B("float32"), shooter("int32"), ambient("float32");
  for (const ViewerFrame& f : run.frames) {
    const std::string frame = what + ", frame of step " + std::to_string(f.step);
    step.add_int(f.step);
    add_colours(B, f.B, n, frame);
    if (!run.shooters) continue;
    require(f.shooter >= -1 && f.shooter < patches, frame + ": the shooter is not a patch");
    shooter.add_int(f.shooter);
    for (int k = 0; k < 3; ++k) {
      require(finite_float(f.ambient[k]), frame + ": the ambient term is not finite");
      ambient.add_float(f.ambient[k]);
    }
  }
  json frames = {{"step", step.finish()}, {"B", B.finish()}};
  if (run.shooters) frames["shooter"] = shooter.finish(), frames["ambient"] = ambient.finish();
  return {{"name", run.name},
          {"unit", run.unit},
          {"status", run.status},
          {"work_per_step", run.work_per_step},
          {"history", history_json(run.history)},
          {"frames", std::move(frames)}};
}

json vector_json(const vec3& v) { return json::array({v.x, v.y, v.z}); }

bool index_in(int i, std::size_t size) { return i >= 0 && static_cast<std::size_t>(i) < size; }

json nodes_json(const ViewerHierarchy& h, std::size_t surfaces) {
  const std::size_t nodes = h.node_surface.size();
  require(h.node_level.size() == nodes && h.node_parent.size() == nodes && h.node_corners.size() == nodes,
          "hierarchy: surface, level, parent and corners need one value per node");
  TypedArray surface("int32"), level("int32"), parent("int32"), corners("float32");
  for (std::size_t n = 0; n < nodes; ++n) {
    const std::string what = "hierarchy: node " + std::to_string(n);
    require(index_in(h.node_surface[n], surfaces), what + ": its surface is out of range");
    require(h.node_level[n] >= 0, what + ": its level is negative");
    // Parents come first: a node is split before its children exist.
    require(h.node_parent[n] == -1 || (h.node_parent[n] >= 0 && static_cast<std::size_t>(h.node_parent[n]) < n),
            what + ": its parent is out of range");
    surface.add_int(h.node_surface[n]), level.add_int(h.node_level[n]), parent.add_int(h.node_parent[n]);
    for (const vec3& c : h.node_corners[n])
      for (int k = 0; k < 3; ++k) {
        require(finite_float(c[k]), what + ": a corner is not finite");
        corners.add_float(c[k]);
      }
  }
  return {{"surface", surface.finish()}, {"level", level.finish()}, {"parent", parent.finish()},
          {"corners", corners.finish()}};
}

json links_json(const ViewerHierarchy& h) {
  TypedArray receiver("int32"), source("int32"), F("float32"), visibility("float32"), light("float32");
  for (const ViewerLink& l : h.links) {
    require(index_in(l.receiver, h.node_surface.size()) && index_in(l.source, h.node_surface.size()),
            "hierarchy: a link's receiver or source is not a node");
    require(finite_float(l.F), "hierarchy: a link's F is not finite");
    require(l.visibility >= 0 && l.visibility <= 1, "hierarchy: a link's visibility is outside [0, 1]");
    receiver.add_int(l.receiver), source.add_int(l.source), F.add_float(l.F), visibility.add_float(l.visibility);
    for (int k = 0; k < 3; ++k) {
      require(finite_float(l.light[k]), "hierarchy: a link's light is not finite");
      light.add_float(l.light[k]);
    }
  }
  return {{"receiver", receiver.finish()}, {"source", source.finish()}, {"F", F.finish()},
          {"visibility", visibility.finish()}, {"light", light.finish()}};
}

json hierarchy_json(const ViewerHierarchy& h, const ViewerData& d) {
  const std::size_t n = d.elements.size();
  require(h.element_node.size() == n, "hierarchy: element_node needs one node per element");
  TypedArray element_node("int32"), a("int32"), b("int32"), vertex("int32"), t("float32");
  for (int node : h.element_node) {
    require(index_in(node, h.node_surface.size()), "hierarchy: an element's node is out of range");
    element_node.add_int(node);
  }
  for (const ViewerTVertex& tv : h.t_vertices) {
    require(index_in(tv.vertex, d.vertices.size()) && index_in(tv.a, d.vertices.size()) &&
                index_in(tv.b, d.vertices.size()),
            "hierarchy: a T-vertex names a vertex out of range");
    require(tv.t >= 0 && tv.t <= 1, "hierarchy: a T-vertex's t is outside [0, 1]");
    vertex.add_int(tv.vertex), a.add_int(tv.a), b.add_int(tv.b), t.add_float(tv.t);
  }
  return {{"links_carry", h.links_carry},
          {"nodes", nodes_json(h, d.surfaces.size())},
          {"element_node", element_node.finish()},
          {"element_gathered", colours(h.element_gathered, n, "hierarchy: element_gathered")},
          {"links", links_json(h)},
          {"t_vertices", {{"vertex", vertex.finish()}, {"a", a.finish()}, {"b", b.finish()}, {"t", t.finish()}}}};
}

}  // namespace

ViewerData viewer_data(const std::string& lesson, const std::string& title, const Mesh& mesh, const Camera& camera,
                       double exposure) {
  ViewerData d;
  d.lesson = lesson, d.title = title, d.exposure = exposure, d.camera = camera;
  d.vertices = mesh.vertices;
  for (const Element& e : mesh.elements) {
    d.elements.push_back(e.vertices);
    d.element_patch.push_back(e.patch);
    d.element_surface.push_back(e.surface);
    d.area.push_back(e.shape.area);
    d.reflectance.push_back(mesh.reflectance(e));
    d.emission.push_back(mesh.emission(e));
  }
  for (const Surface& s : mesh.surfaces) d.surfaces.push_back(s.name);
  d.patches = static_cast<int>(mesh.patches.size());
  return d;
}

std::string viewer_data_text(const ViewerData& d) {
  require(std::isfinite(d.exposure) && d.exposure > 0, "the exposure must be positive");
  const std::size_t n = d.elements.size();
  json runs = json::array(), lights = json::array();
  for (const ViewerRun& run : d.runs) runs.push_back(run_json(run, n, d.patches));
  for (const ViewerLight& light : d.lights) {
    require(std::isfinite(light.weight), "light '" + light.name + "': the weight is not finite");
    lights.push_back({{"name", light.name},
                      {"weight", light.weight},
                      {"emission", colours(light.emission, n, "light '" + light.name + "' emission")},
                      {"B", colours(light.B, n, "light '" + light.name + "' B")}});
  }
  const json camera = {{"eye", vector_json(d.camera.eye)},
                       {"look_at", vector_json(d.camera.look_at)},
                       {"up", vector_json(d.camera.up)},
                       {"vertical_fov_degrees", d.camera.vertical_fov}};
  json data = {{"format", "gi-workbench viewer"}, {"version", 1},     {"lesson", d.lesson},
               {"title", d.title},                 {"exposure", d.exposure}, {"camera", camera},
               {"mesh", mesh_json(d)},             {"runs", std::move(runs)}, {"lights", std::move(lights)}};
  if (d.hierarchy) data["hierarchy"] = hierarchy_json(*d.hierarchy, d);
  // ASCII only, bytes that are not UTF-8 replaced: names cannot break the script.
  return "// The data viewer.html shows (format: lib/gi/viewer/data.hpp).\nwindow.GI_VIEWER_DATA = " +
         data.dump(-1, ' ', true, json::error_handler_t::replace) + ";\n";
}

void write_viewer_data(const ViewerData& data, const std::filesystem::path& file) {
  const std::string text = viewer_data_text(data);
  write_atomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace gi
