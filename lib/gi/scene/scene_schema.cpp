#include "gi/scene/scene_schema.hpp"

#include <cstdio>

#include "gi/core/did_you_mean.hpp"

namespace gi {

namespace {

// "2 items" or "a string": what a value that should be a triple is.
std::string got(const JsonValue& v) {
  return v.kind == JsonValue::Kind::Array ? std::to_string(v.items.size()) + " items" : kind_name(v.kind);
}

}  // namespace

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

const JsonValue* SchemaReader::Fields::operator[](std::string_view key) const {
  for (const auto& [name, value] : members_)
    if (name == key) return value;
  return nullptr;
}

SchemaReader::Fields SchemaReader::object(const JsonValue& v, const std::string& path,
                                          const std::vector<Key>& keys) const {
  if (v.kind != JsonValue::Kind::Object) fail(v, path, "expected an object {...}, got " + kind_name(v.kind));
  Fields fields;
  for (const JsonMember& m : v.members) {
    const Key* key = nullptr;
    for (const Key& k : keys)
      if (k.name == m.key) key = &k;
    if (!key && m.key != "about") {
      std::vector<std::string> names;
      for (const Key& k : keys) names.emplace_back(k.name);
      throw SceneError({file_, m.line, m.column, path},
                       "unknown key \"" + m.key.substr(0, 64) + "\"" + did_you_mean(m.key, names, "\""));
    }
    if (fields[m.key])
      throw SceneError({file_, m.line, m.column, path}, "the key \"" + m.key + "\" is given twice");
    fields.members_.emplace_back(key ? key->name : std::string_view("about"), &m.value);
  }
  for (const Key& k : keys)
    if (k.required && !fields[k.name]) fail(v, path, "missing the key \"" + std::string(k.name) + "\"");
  if (const JsonValue* about = fields["about"]) (void)text(*about, member_path(path, "about"));
  return fields;
}

const std::vector<JsonValue>& SchemaReader::array(const JsonValue& v, const std::string& path) const {
  if (v.kind != JsonValue::Kind::Array) fail(v, path, "expected an array [...], got " + kind_name(v.kind));
  return v.items;
}

std::string SchemaReader::text(const JsonValue& v, const std::string& path) const {
  if (v.kind != JsonValue::Kind::String) fail(v, path, "expected a string in double quotes, got " + kind_name(v.kind));
  if (v.text.empty()) fail(v, path, "must not be empty");
  return v.text;
}

double SchemaReader::number(const JsonValue& v, const std::string& path, double min, double max,
                            bool above_min) const {
  if (v.kind != JsonValue::Kind::Number) fail(v, path, "expected a number, got " + kind_name(v.kind));
  const double x = v.number;
  if (above_min && !(x > min)) fail(v, path, "must be > " + number_text(min) + ", got " + number_text(x));
  if (x < min) fail(v, path, "must be >= " + number_text(min) + ", got " + number_text(x));
  if (x > max) fail(v, path, "must be at most " + number_text(max) + ", got " + number_text(x));
  return x;
}

vec3 SchemaReader::point(const JsonValue& v, const std::string& path) const {
  if (v.kind != JsonValue::Kind::Array || v.items.size() != 3)
    fail(v, path, "expected three numbers [x, y, z], got " + got(v));
  vec3 p;
  for (int i = 0; i < 3; ++i) p[i] = number(v.items[i], item_path(path, i), -max_coordinate, max_coordinate);
  return p;
}

Color SchemaReader::colour(const JsonValue& v, const std::string& path) const {
  if (v.kind == JsonValue::Kind::Number) return Color(number(v, path, 0, 1e6));
  if (v.kind != JsonValue::Kind::Array || v.items.size() != 3)
    fail(v, path, "expected a colour [r, g, b] or one number for a grey, got " + got(v));
  Color c;
  for (int i = 0; i < 3; ++i) c[i] = number(v.items[i], item_path(path, i), 0, 1e6);
  return c;
}

}  // namespace gi
