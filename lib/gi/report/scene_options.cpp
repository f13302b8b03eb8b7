#include "gi/report/scene_options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "gi/core/decimal.hpp"
#include "gi/core/number_text.hpp"
#include "gi/report/options.hpp"

namespace gi {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == separator) parts.emplace_back();
    else parts.back().push_back(c);
  }
  return parts;
}

// Decimal text first (number_text.hpp): the grammar, not the converter, says what is a number.
double number(const std::string& text, const std::string& what) {
  double v = 0;
  const auto [end, error] = read_decimal(text.data(), text.data() + text.size(), v);
  if (!is_real_number_text(text) || error != std::errc() || end != text.data() + text.size())
    throw OptionError(what + ": expected a decimal number such as 2, -0.5 or 1e-3, got '" + quoted_text(text) + "'");
  if (const RealProblem problem = real_problem(v); problem != RealProblem::None)
    throw OptionError(what + ": the number " + real_problem_text(problem) + ", got '" + quoted_text(text) + "'");
  return v == 0 ? 0.0 : v;
}

vec3 point(const std::string& text, const std::string& what) {
  const std::vector<std::string> xyz = split(text, ',');
  if (xyz.size() != 3) throw OptionError(what + ": expected three numbers x,y,z, got '" + quoted_text(text) + "'");
  const vec3 p(number(xyz[0], what), number(xyz[1], what), number(xyz[2], what));
  if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > 1e6)
    throw OptionError(what + ": each coordinate must lie in [-1e6, 1e6], got '" + quoted_text(text) + "'");
  return p;
}

}  // namespace

CameraChange parse_camera_change(const std::string& text) {
  const std::vector<std::string> parts = split(text, ':');
  if (parts.size() != 2 && parts.size() != 3)
    throw OptionError("--camera expects EYE:LOOK_AT[:FOV] such as 278,273,-800:278,273,0:40, got '" + quoted_text(text) + "'");
  CameraChange change{point(parts[0], "--camera eye"), point(parts[1], "--camera look-at"), std::nullopt};
  if (change.eye == change.look_at) throw OptionError("--camera: the eye and the point looked at must differ");
  if (parts.size() == 3) {
    const double fov = number(parts[2], "--camera field of view");
    if (!(fov > 0 && fov < 180))
      throw OptionError("--camera: the field of view must lie in (0, 180) degrees, got " + parts[2]);
    change.fov = fov;
  }
  return change;
}

std::vector<LightScale> parse_light_scales(const std::string& text) {
  std::vector<LightScale> scales;
  for (const std::string& part : split(text, ',')) {
    const std::size_t eq = part.rfind('=');
    if (eq == std::string::npos || eq == 0)
      throw OptionError("--light-scale expects NAME=FACTOR[,NAME=FACTOR ...] such as light=2, got '" + quoted_text(part) + "'");
    LightScale s{part.substr(0, eq), number(part.substr(eq + 1), "--light-scale " + quoted_text(part.substr(0, eq)))};
    if (!(s.factor >= 0 && s.factor <= 1e6))
      throw OptionError("--light-scale " + quoted_text(s.light) + ": the factor must lie in [0, 1e6], got " + part.substr(eq + 1));
    for (const LightScale& earlier : scales)
      if (earlier.light == s.light) throw OptionError("--light-scale names '" + quoted_text(s.light) + "' twice");
    scales.push_back(std::move(s));
  }
  return scales;
}

std::string file_stem(const std::string& name) {
  std::string stem = name.substr(0, 64);
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return stem.empty() ? "scene" : stem;
}

}  // namespace gi
