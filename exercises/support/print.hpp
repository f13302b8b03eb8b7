#pragma once
// How GoogleTest shows the library's values when a test fails: "(0.5, 0.25, 1)" and
// "converged" instead of "24-byte object <00-00 ...>". gtest looks PrintTo up by
// argument-dependent lookup, so each one lives in its type's namespace: GLM's vectors
// (vec2, vec3, Color) in glm, the library's types in gi.
//
// It lives here, above the library, because it names types of every topic (core to
// radiosity) and a header in lib/ may only include the floors below it. The graded
// tests include it; the unit tests get it from tests/CMakeLists.txt.
#include <array>
#include <charconv>
#include <ostream>

#include "gi/accel/bvh.hpp"
#include "gi/accel/world.hpp"
#include "gi/core/math.hpp"
#include "gi/core/ray.hpp"
#include "gi/core/samplers/sample_stream.hpp"
#include "gi/geometry/aabb.hpp"
#include "gi/radiosity/form_factors/hemicube.hpp"
#include "gi/radiosity/hierarchical/oracle.hpp"
#include "gi/radiosity/system/solver.hpp"
#include "gi/render/pixel_samplers.hpp"
#include "gi/raytrace/soft_shadows.hpp"

namespace gi::print {

// The shortest decimal that reads back as the same double: 0.1, not 0.10000000000000001,
// and two values that differ always print differently.
inline void number(double x, std::ostream* os) {
  std::array<char, 32> text{};
  const auto end = std::to_chars(text.data(), text.data() + text.size(), x).ptr;
  os->write(text.data(), end - text.data());
}

template <class Vector>
void vector(const Vector& v, int size, std::ostream* os) {
  *os << '(';
  for (int k = 0; k < size; ++k) {
    if (k > 0) *os << ", ";
    number(static_cast<double>(v[k]), os);
  }
  *os << ')';
}

template <class Enum, std::size_t N>
void name(Enum value, const char* const (&names)[N], std::ostream* os) {
  const auto k = static_cast<std::size_t>(value);
  *os << (k < N ? names[k] : "(out of range)");
}

}  // namespace gi::print

namespace glm {

inline void PrintTo(const dvec2& v, std::ostream* os) { gi::print::vector(v, 2, os); }
inline void PrintTo(const dvec3& v, std::ostream* os) { gi::print::vector(v, 3, os); }
inline void PrintTo(const vec3& v, std::ostream* os) { gi::print::vector(v, 3, os); }

}  // namespace glm

namespace gi {

inline void PrintTo(SolveStatus s, std::ostream* os) { *os << status_name(s); }
inline void PrintTo(Refinement r, std::ostream* os) { *os << name(r); }
inline void PrintTo(HemicubeFace f, std::ostream* os) { print::name(f, {"Top", "PlusX", "MinusX", "PlusY", "MinusY"}, os); }
inline void PrintTo(PrimitiveKind k, std::ostream* os) { print::name(k, {"Sphere", "Quad", "Triangle"}, os); }
inline void PrintTo(Split s, std::ostream* os) { print::name(s, {"Sah", "Median"}, os); }
inline void PrintTo(Acceleration a, std::ostream* os) { print::name(a, {"BruteForce", "BoundingBoxes", "Bvh"}, os); }
inline void PrintTo(Sampler s, std::ostream* os) { print::name(s, {"centre", "grid", "random", "jittered", "adaptive"}, os); }
inline void PrintTo(LightSampling s, std::ostream* os) { print::name(s, {"centre", "random", "jittered"}, os); }
inline void PrintTo(SamplerKind k, std::ostream* os) { *os << sequence_name(k); }

inline void PrintTo(const HemicubeCell& c, std::ostream* os) {
  *os << "{face ";
  PrintTo(c.face, os);
  *os << ", column " << c.column << ", row " << c.row << '}';
}

inline void PrintTo(const Hit& h, std::ostream* os) {
  *os << "Hit{t = ";
  print::number(h.t, os);
  *os << ", point = ";
  print::vector(h.point, 3, os);
  *os << ", normal = ";
  print::vector(h.normal, 3, os);
  *os << ", material " << h.material << ", object " << h.object << '}';
}

inline void PrintTo(const Ray& r, std::ostream* os) {
  *os << "Ray{origin = ";
  print::vector(r.origin, 3, os);
  *os << ", direction = ";
  print::vector(r.direction, 3, os);
  *os << ", t in [";
  print::number(r.t_min, os);
  *os << ", ";
  print::number(r.t_max, os);
  *os << "]}";
}

inline void PrintTo(const Aabb& b, std::ostream* os) {
  *os << "Aabb{";
  print::vector(b.lo, 3, os);
  *os << " to ";
  print::vector(b.hi, 3, os);
  *os << '}';
}

}  // namespace gi
