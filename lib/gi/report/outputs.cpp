#include "gi/report/outputs.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "gi/image/diff.hpp"

namespace gi {

std::string kind_name(OutputKind kind) {
  switch (kind) {
    case OutputKind::Text: return "text";
    case OutputKind::Table: return "table";
    case OutputKind::Picture: return "picture";
    case OutputKind::Diagram: return "diagram";
    case OutputKind::Chart: return "chart";
    case OutputKind::Mesh: return "mesh";
    case OutputKind::Cache: return "cache";
    case OutputKind::Viewer: return "viewer";
    case OutputKind::Data: return "data";
    case OutputKind::Page: return "page";
  }
  return "?";
}

// A JSON string: quotes, backslashes and control characters escaped.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += static_cast<char>(c);
    else if (c == '\n') out += "\\n";
    else if (c < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else out += static_cast<char>(c);
  }
  return out + "\"";
}

// Shortest text that reads back as the same double (JSON has no NaN: null).
std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

namespace {

std::string vector_text(const vec3& v) {
  return "[" + json_number(v.x) + ", " + json_number(v.y) + ", " + json_number(v.z) + "]";
}

std::string view_json(const View& view) {
  return "{\"eye\": " + vector_text(view.camera.eye) + ", \"look_at\": " + vector_text(view.camera.look_at) +
         ", \"up\": " + vector_text(view.camera.up) + ", \"vertical_fov_degrees\": " +
         json_number(view.camera.vertical_fov) + ", \"width\": " + std::to_string(view.width) +
         ", \"height\": " + std::to_string(view.height) + ", \"pixel_samples\": " + json_string(view.pixel_samples) +
         ", \"projection\": \"pinhole; pixel (x, y) spans [x, x+1] x [y, y+1] of the image plane, row 0 at the top\"}";
}

std::string scale_json(const ColourScale& s) {
  return "{\"map\": " + json_string(false_colour_map_name) + ", \"lo\": " + json_number(s.lo) +
         ", \"hi\": " + json_number(s.hi) + ", \"log10\": " + (s.log10 ? "true" : "false") + ", \"quantity\": " + json_string(s.quantity) + "}";
}

}  // namespace

std::string outputs_json(const std::string& lesson, const std::vector<std::string>& command, const std::string& status,
                         const std::vector<Output>& outputs, const RunProcess& process) {
  std::ostringstream os;
  os << "{\n  \"lesson\": " << json_string(lesson) << ",\n  \"command\": [";
  for (std::size_t i = 0; i < command.size(); ++i) os << (i ? ", " : "") << json_string(command[i]);
  os << "],\n  \"status\": " << json_string(status) << ",\n";
  if (process.id != 0)
    os << "  \"process\": {\"id\": " << process.id << ", \"started\": " << json_string(process.started) << "},\n";
  os << "  \"outputs\": [";
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const Output& o = outputs[i];
    os << (i ? "," : "") << "\n    {\"kind\": " << json_string(kind_name(o.kind))
       << ", \"caption\": " << json_string(o.caption);
    if (!o.file.empty()) os << ", \"file\": " << json_string(o.file.generic_string()) << ", \"bytes\": " << o.bytes;
    if (o.kind == OutputKind::Picture)
      os << ", \"linear\": " << json_string(o.linear.generic_string()) << ", \"exposure\": " << json_number(o.exposure)
         << ", \"view\": " << view_json(o.view);
    if (o.kind == OutputKind::Diagram && o.width > 0)
      os << ", \"width\": " << o.width << ", \"height\": " << o.height;
    if (o.colour_scale) os << ", \"colour_scale\": " << scale_json(*o.colour_scale);
    os << "}";
  }
  os << "\n  ]\n}\n";
  return os.str();
}

}  // namespace gi
