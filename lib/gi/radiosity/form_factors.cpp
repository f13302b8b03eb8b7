#include "gi/radiosity/form_factors.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/core/onb.hpp"
#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/form_factor_formulas.hpp"
#include "gi/radiosity/form_factor_hemicube.hpp"

namespace gi {

namespace {

const char* const method_names[] = {"differential", "analytic", "monte-carlo", "hemicube"};

World world_of(const std::vector<Polygon>& polygons) {
  Scene scene;
  scene.name = "form-factor polygons";
  const int material = scene.add(Material{});
  for (const Polygon& p : polygons) {  // polygon k is triangles 2k and 2k + 1
    const auto& c = p.corners;
    scene.triangles.push_back(Triangle{c[0], c[1], c[2], material});
    scene.triangles.push_back(Triangle{c[0], c[2], c[3], material});
  }
  return make_world(std::move(scene));
}

double size_of(const Polygon& p) { return std::sqrt(p.area); }

// A uniformly distributed point of the polygon: one of its two triangles, chosen by
// area, and a uniform point in that.
vec3 point_on(const Polygon& p, Rng& rng) {
  const auto& c = p.corners;
  const double a1 = length(cross(c[1] - c[0], c[2] - c[0]));
  const double a2 = length(cross(c[2] - c[0], c[3] - c[0]));
  const bool first = rng.uniform() * (a1 + a2) < a1;
  const vec3 &b = first ? c[1] : c[2], &d = first ? c[2] : c[3];
  const double r = std::sqrt(rng.uniform()), s = rng.uniform();
  return (1 - r) * c[0] + r * (1 - s) * b + r * s * d;
}

std::vector<double> row_monte_carlo(const FormFactorScene& scene, const Polygon& from, int row,
                                    const FormFactorSettings& settings) {
  std::vector<double> f(scene.polygons().size(), 0.0);
  Rng rng(settings.seed, static_cast<std::uint64_t>(row));
  const Onb frame(from.normal);
  const double offset = 1e-7 * size_of(from);
  // Jittered directions: n x n strata of the unit square, mapped to the hemisphere
  // with p(w) = cos(theta) / pi (Malley: uniform on the disc, lifted).
  const int n = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(settings.rays))));
  for (int k = 0; k < settings.rays; ++k) {
    const double u = ((k % n) + rng.uniform()) / n, v = (((k / n) % n) + rng.uniform()) / n;
    const double r = std::sqrt(u), phi = 2 * pi * v;
    const vec3 d = r * std::cos(phi) * frame.u + r * std::sin(phi) * frame.v + std::sqrt(std::max(0.0, 1 - u)) * frame.w;
    const Ray ray{point_on(from, rng) + offset * from.normal, d};
    if (const auto hit = scene.first_hit(ray); hit && hit->front) f[hit->polygon] += 1.0;
  }
  for (double& x : f) x /= settings.rays;
  return f;
}

std::vector<double> row_hemicube(const FormFactorScene& scene, const Polygon& from, int resolution) {
  // Kept per thread and reused: the weights depend only on the resolution, and the
  // item buffer's memory on nothing.
  thread_local HemicubeWeights weights{0, {}, {}};
  thread_local ItemBuffer buffer;
  if (weights.resolution != resolution) weights = hemicube_weights(resolution);
  return form_factor_row_hemicube(scene.polygons(), from, weights, buffer);
}

}  // namespace

std::string name(FormFactorMethod method) { return method_names[static_cast<int>(method)]; }

std::vector<std::string> form_factor_method_names() { return {std::begin(method_names), std::end(method_names)}; }

FormFactorMethod form_factor_method_from_name(const std::string& text) {
  for (int i = 0; i < 4; ++i)
    if (text == method_names[i]) return static_cast<FormFactorMethod>(i);
  throw std::invalid_argument("unknown form-factor method '" + text +
                              "' (differential, analytic, monte-carlo, hemicube)");
}

void check(const FormFactorSettings& s) {
  if (s.hemicube_resolution < 2 || s.hemicube_resolution > 2000 || s.hemicube_resolution % 2)
    throw std::invalid_argument("form factors: the hemicube resolution must be even and lie in [2, 2000]");
  if (s.quadrature_order < 1 || s.quadrature_order > 16)
    throw std::invalid_argument("form factors: the quadrature order must lie in [1, 16]");
  if (s.rays < 1 || s.rays > 100'000'000) throw std::invalid_argument("form factors: rays must lie in [1, 10^8]");
}

FormFactorScene::FormFactorScene(std::vector<Polygon> polygons)
    : polygons_(std::move(polygons)), world_(world_of(polygons_)) {}

std::optional<FormFactorScene::RayHit> FormFactorScene::first_hit(const Ray& ray) const {
  const std::optional<Hit> hit = closest_hit(world_, ray);
  if (!hit) return std::nullopt;
  const int polygon = hit->object / 2;
  return RayHit{polygon, dot(ray.direction, polygons_[polygon].normal) < 0, hit->t};
}

bool FormFactorScene::visible(const vec3& from, const vec3& to) const {
  const vec3 d = to - from;
  const double distance = length(d);
  const double margin = 1e-7 * distance;
  return !any_hit(world_, Ray{from, d / distance, margin, distance - margin});
}

std::vector<double> form_factor_row(const FormFactorScene& scene, const Polygon& from, int row,
                                    const FormFactorSettings& settings) {
  check(settings);
  const std::vector<Polygon>& to = scene.polygons();
  std::vector<double> f(to.size(), 0.0);
  switch (settings.method) {
    case FormFactorMethod::Differential: {
      const double lift = 1e-7 * size_of(from);  // off the surfaces, so they do not block themselves
      for (std::size_t j = 0; j < to.size(); ++j) {
        const double h = !settings.occlusion || scene.visible(from.centre + lift * from.normal,
                                                              to[j].centre + lift * to[j].normal);
        f[j] = form_factor_differential(from.centre, from.normal, to[j].centre, to[j].normal, to[j].area, h);
      }
      return f;
    }
    case FormFactorMethod::Analytic:
      for (std::size_t j = 0; j < to.size(); ++j) f[j] = form_factor_analytic(from, to[j], settings.quadrature_order);
      return f;
    case FormFactorMethod::MonteCarlo: return row_monte_carlo(scene, from, row, settings);
    case FormFactorMethod::Hemicube: return row_hemicube(scene, from, settings.hemicube_resolution);
  }
  return f;
}

FormFactorMatrix form_factor_matrix(const FormFactorScene& scene, const FormFactorSettings& settings, int threads) {
  check(settings);
  if (settings.method == FormFactorMethod::Hemicube)  // one set of weights, buffers reused per block of rows
    return form_factor_matrix_hemicube(scene.polygons(), settings.hemicube_resolution, threads);
  const int n = static_cast<int>(scene.polygons().size());
  FormFactorMatrix F{n, std::vector<double>(static_cast<std::size_t>(n) * n)};
  parallel_for(n, threads, [&](int i) {
    const std::vector<double> row = form_factor_row(scene, scene.polygons()[i], i, settings);
    std::copy(row.begin(), row.end(), F.values.begin() + static_cast<std::ptrdiff_t>(i) * n);
  });
  return F;
}

}  // namespace gi
