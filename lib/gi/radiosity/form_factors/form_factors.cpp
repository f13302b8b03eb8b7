#include "gi/radiosity/form_factors/form_factors.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/radiosity/form_factors/form_factor_adaptive.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/mesh/overlaps.hpp"

namespace gi {

namespace {

const char* const method_names[] = {"differential", "analytic", "monte-carlo", "hemicube"};

// Checked before the World is built: an infinite corner would break the BVH builder.
std::vector<Polygon> checked(std::vector<Polygon> polygons) {
  for (std::size_t i = 0; i < polygons.size(); ++i) try {
      check(polygons[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("form-factor scene: polygon " + std::to_string(i) + ": " + e.what());
    }
  return polygons;
}

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

FormFactorRow row_differential(const FormFactorScene& scene, const Polygon& from, bool occlusion) {
  const std::vector<Polygon>& to = scene.polygons();
  FormFactorRow row{std::vector<double>(to.size(), 0.0), {}};
  // From lifted centre to lifted centre, a hair off the surfaces: no polygon's own
  // triangles lie in the way of the ray between them.
  const vec3 x_i = lifted_centre(from) + 1e-7 * size_of(from) * from.normal;
  double sum = 0;
  for (std::size_t j = 0; j < to.size(); ++j) {
    const vec3 x_j = lifted_centre(to[j]) + 1e-7 * size_of(to[j]) * to[j].normal;
    if (!(length(x_j - x_i) > 0)) continue;  // the sender itself: F_ii = 0, not 0 / 0
    const double f = form_factor_differential(x_i, from.normal, x_j, to[j].normal, to[j].area, 1.0);
    row.F[j] = f > 0 && occlusion && !scene.visible(x_i, x_j) ? 0.0 : f;
    sum += row.F[j];
  }
  // The formula overestimates receivers that are close against their size, without
  // bound (10.5 for unit squares 1/5 apart): a row that would send out more than all
  // of the sender's energy is scaled to send out exactly all of it.
  if (sum > 1)
    for (double& f : row.F) f /= sum;
  return row;
}

FormFactorRow row_analytic(const FormFactorScene& scene, const Polygon& from, const FormFactorSettings& settings) {
  const std::vector<Polygon>& to = scene.polygons();
  FormFactorRow row{std::vector<double>(to.size(), 0.0), std::vector<double>(to.size(), 0.0)};
  for (std::size_t j = 0; j < to.size(); ++j) {
    const Estimate f = form_factor_analytic_adaptive(from, to[j], settings.tolerance, settings.quadrature_order);
    row.F[j] = f.value, row.error[j] = f.error;
  }
  return row;
}

FormFactorRow row_hemicube(const FormFactorScene& scene, const Polygon& from, int resolution) {
  // Kept per thread and reused: the weights depend only on the resolution, and the
  // item buffer's memory on nothing.
  thread_local HemicubeWeights weights{0, {}, {}};
  thread_local ItemBuffer buffer;
  if (weights.resolution != resolution) weights = hemicube_weights(resolution);
  const HemicubeRow row = hemicube_row(scene.polygons(), from, weights, buffer);
  return {row.F, {}, row.sub_cell_receivers, row.sub_cell_missed, row.sub_cell_share};
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
  if (!(s.tolerance >= 1e-14 && s.tolerance <= 0.1))
    throw std::invalid_argument("form factors: the analytic tolerance must lie in [1e-14, 0.1]");
}

FormFactorScene::FormFactorScene(std::vector<Polygon> polygons)
    : polygons_(checked(std::move(polygons))), world_(world_of(polygons_)) {
  if (const auto pair = find_overlap(polygons_, world_.bvh))
    throw std::invalid_argument("form-factor scene: polygons " + std::to_string(pair->first) + " and " +
                                std::to_string(pair->second) +
                                " lie in one plane and overlap; remove one, or move it off the other");
}

std::optional<FormFactorScene::RayHit> FormFactorScene::first_hit(const Ray& ray) const {
  const std::optional<Hit> hit = closest_hit(world_, ray);
  if (!hit) return std::nullopt;
  // Which side by the triangle hit, not the polygon's mean normal: on a twisted
  // polygon the two differ, and a ray grazing it must not count its back as its front.
  return RayHit{hit->object / 2, dot(ray.direction, hit->normal) < 0, hit->t};
}

std::optional<Ray> segment_between(const vec3& from, const vec3& to) {
  const vec3 d = to - from;
  const double distance = length(d);
  if (!(distance > 0)) return std::nullopt;
  const double margin = 1e-7 * distance;
  return Ray{from, d / distance, margin, distance - margin};
}

bool FormFactorScene::visible(const vec3& from, const vec3& to) const {
  const std::optional<Ray> segment = segment_between(from, to);
  return !segment || !any_hit(world_, *segment);
}

FormFactorRow form_factor_row_with_diagnostics(const FormFactorScene& scene, const Polygon& from, int row,
                                               const FormFactorSettings& settings) {
  check(settings);
  check(from);
  switch (settings.method) {
    case FormFactorMethod::Differential: return row_differential(scene, from, settings.occlusion);
    case FormFactorMethod::Analytic: return row_analytic(scene, from, settings);
    case FormFactorMethod::MonteCarlo: {
      FormFactorRow r{form_factor_row_monte_carlo(scene, from, row, settings.rays, settings.seed), {}};
      for (double f : r.F) r.error.push_back(std::sqrt(f * (1 - f) / settings.rays));
      return r;
    }
    case FormFactorMethod::Hemicube: return row_hemicube(scene, from, settings.hemicube_resolution);
  }
  return {};
}

std::vector<double> form_factor_row(const FormFactorScene& scene, const Polygon& from, int row,
                                    const FormFactorSettings& settings) {
  return form_factor_row_with_diagnostics(scene, from, row, settings).F;
}

FormFactorMatrix form_factor_matrix(const FormFactorScene& scene, const FormFactorSettings& settings, int threads,
                                    HemicubeMatrixStats* hemicube) {
  check(settings);
  if (settings.method == FormFactorMethod::Hemicube)  // one set of weights, buffers reused per block of rows
    return form_factor_matrix_hemicube(scene.polygons(), settings.hemicube_resolution, threads, hemicube);
  const int n = static_cast<int>(scene.polygons().size());
  FormFactorMatrix F{n, std::vector<double>(static_cast<std::size_t>(n) * n)};
  parallel_for(n, threads, [&](int i) {
    const std::vector<double> row = form_factor_row(scene, scene.polygons()[i], i, settings);
    std::copy(row.begin(), row.end(), F.values.begin() + static_cast<std::ptrdiff_t>(i) * n);
  });
  return F;
}

}  // namespace gi
