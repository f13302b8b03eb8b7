// Monte Carlo form factors: Nusselt's analogue by sampling. A ray leaving a uniformly
// chosen point of patch i in a direction drawn with density p(w) = cos(theta) / pi
// hits patch j first with probability F_ij (occlusion included), so
//   F_ij ~ (rays that hit the front of j first) / N.
#include <cmath>

#include "gi/core/onb.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"

namespace gi {

namespace {

// The square root of n rounded down, exactly (no floating-point doubt near squares).
int whole_root(int n) {
  int r = static_cast<int>(std::sqrt(static_cast<double>(n)));
  while (static_cast<long long>(r + 1) * (r + 1) <= n) ++r;
  while (static_cast<long long>(r) * r > n) --r;
  return r;
}

// Sample k of N in the unit square, stratified for any N: with n = floor(sqrt(N)),
// samples 0 .. n^2 - 1 take one jittered point in each cell of an n x n grid, and the
// N - n^2 left over are uniform over the whole square. Each sample is then uniform
// over its own region, the regions of the grid cover the square equally, and the
// estimate is unbiased; wrapping the leftovers into the first cells instead (as this
// code once did) counts those cells twice.
// The two numbers are drawn one at a time, v first: as one call's arguments they would
// come in an order of the compiler's choosing (GCC's was v, u), and so would the form
// factors.
vec2 stratified(int k, int n, Rng& rng) {
  const double v = rng.uniform(), u = rng.uniform();
  if (k < n * n) return vec2(((k % n) + u) / n, ((k / n) + v) / n);
  return vec2(u, v);
}

// A uniformly distributed point of the convex quadrilateral q (flat): one of its two
// triangles, chosen by area, and a uniform point in that (the square-root warp).
vec3 point_on(const std::array<vec3, 4>& q, Rng& rng) {
  const double a1 = length(cross(q[1] - q[0], q[2] - q[0]));
  const double a2 = length(cross(q[2] - q[0], q[3] - q[0]));
  const bool first = rng.uniform() * (a1 + a2) < a1;
  const vec3 &b = first ? q[1] : q[2], &d = first ? q[2] : q[3];
  const double r = std::sqrt(rng.uniform()), s = rng.uniform();
  return (1 - r) * q[0] + r * (1 - s) * b + r * s * d;
}

}  // namespace

std::vector<double> form_factor_row_monte_carlo(const FormFactorScene& scene, const Polygon& from, int row, int rays,
                                                std::uint64_t seed) {
  std::vector<double> f(scene.polygons().size(), 0.0);
  Rng rng(seed, static_cast<std::uint64_t>(row));
  const Onb frame(from.normal);
  // Rays start on the sender's outline projected onto the plane through its lifted
  // centre, a hair above it: nothing of the sender, flat or twisted (nor the elements
  // a patch was cut into) rises above that plane to catch its own rays.
  std::array<vec3, 4> top = from.corners;
  const vec3 lifted = lifted_centre(from);
  for (vec3& c : top) c += dot(lifted - c, from.normal) * from.normal;
  const vec3 offset = 1e-7 * std::sqrt(from.area) * from.normal;
  const int n = whole_root(rays);
  for (int k = 0; k < rays; ++k) {
    // Malley's method: uniform on the disc, lifted to the hemisphere: p(w) = cos(theta) / pi.
    const vec2 u = stratified(k, n, rng);
    const double r = std::sqrt(u.x), phi = 2 * pi * u.y;
    const vec3 d = frame.to_world(vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u.x))));
    if (const auto hit = scene.first_hit(Ray{point_on(top, rng) + offset, d}); hit && hit->front) f[hit->polygon] += 1;
  }
  for (double& x : f) x /= rays;
  return f;
}

}  // namespace gi
