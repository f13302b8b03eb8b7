#include "gi/radiosity/display/reference_picture.hpp"

#include <cmath>
#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/radiosity/hierarchical/mesh_lines.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

namespace gi {

namespace {

struct Emitter {
  Polygon shape;
  Color E;
};

// F(x -> e) with visibility, as the header says, for each emitter, times its E.
Color direct_light(const FormFactorScene& blockers, const std::vector<Emitter>& emitters, const vec3& x,
                   const vec3& n, int rays_per_side, Rng& rng) {
  Color sum(0.0);
  for (const Emitter& e : emitters) {
    const std::array<vec3, 4>& c = e.shape.corners;
    int through = 0;
    double sampled = 0;
    for (int k = 0; k < rays_per_side * rays_per_side; ++k) {
      const double u = (k % rays_per_side + rng.uniform()) / rays_per_side;
      const double v = (k / rays_per_side + rng.uniform()) / rays_per_side;
      const vec3 y = bilinear(c, u, v);
      const vec3 d = y - x;
      const double r2 = dot(d, d), cos_x = dot(n, d), cos_y = -dot(e.shape.normal, d);
      if (cos_x <= 0 || cos_y <= 0 || !blockers.visible(x, y)) continue;
      ++through;
      // |J|: the area the unit square's cell maps to, per unit of (u, v).
      const vec3 du = (1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]), dv = (1 - u) * (c[3] - c[0]) + u * (c[2] - c[1]);
      sampled += length(cross(du, dv)) * cos_x * cos_y / (pi * r2 * r2);
    }
    const int rays = rays_per_side * rays_per_side;
    const double F = through == rays ? form_factor_point_to_polygon(x, n, e.shape) : sampled / rays;
    sum += F * e.E;
  }
  return sum;
}

}  // namespace

void check(const ReferenceSettings& s) {
  if (s.elements < 10 || s.elements > 20000) throw std::invalid_argument("reference: elements must lie in [10, 20000]");
  if (s.shadow_rays_per_side < 1 || s.shadow_rays_per_side > 64 || s.element_points_per_side < 1 ||
      s.element_points_per_side > 16)
    throw std::invalid_argument("reference: shadow rays per side in [1, 64], element points per side in [1, 16]");
}

ReferencePicture render_reference_picture(const RadiosityScene& scene, const ReferenceSettings& s) {
  check(s);
  const Mesh mesh = make_mesh(scene.surfaces, {patch_size_for(scene.surfaces, s.elements, 1), 1});
  const FormFactorScene receivers(element_shapes(mesh));
  std::vector<Polygon> surfaces;
  std::vector<Emitter> emitters;
  for (const Surface& surface : scene.surfaces) {
    surfaces.push_back(make_polygon(surface.corners));
    if (max_component(surface.emission) > 0) emitters.push_back({surfaces.back(), surface.emission});
  }
  const FormFactorScene blockers(surfaces);
  const int n = static_cast<int>(mesh.elements.size()), m = s.element_points_per_side;

  // The indirect part on the mesh: direct light per element, then B' and I.
  RadiositySystem system = make_system(mesh, {});
  parallel_for(n, s.display.threads, [&](int i) {
    const Element& e = mesh.elements[i];
    Rng rng(s.display.seed ^ 0x9e3779b97f4a7c15ULL, static_cast<std::uint64_t>(i));
    Color D(0.0);
    for (int k = 0; k < m * m; ++k)
      D += direct_light(blockers, emitters, bilinear(e.shape.corners, (k % m + 0.5) / m, (k / m + 0.5) / m),
                        e.shape.normal, s.shadow_rays_per_side, rng);
    system.emission[i] = system.rho[i] * D / static_cast<double>(m * m);  // rho_i D_i: B' before any bounce
  });
  FormFactorSettings hemicube;
  hemicube.hemicube_resolution = s.hemicube_resolution;
  system.F = form_factor_matrix(receivers, hemicube, s.display.threads);
  SolverOptions options;
  options.tolerance = 1e-9;
  const SolverResult bounced = solve_gauss_seidel(system, options);
  if (bounced.status != SolveStatus::Converged)
    throw std::runtime_error("reference: the indirect light did not converge (" + stop_reason(bounced, "iteration") + ")");
  std::vector<Color> I(n, Color(0.0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) I[i] += system.F(i, j) * bounced.B[j];
  const std::vector<Color> vertex_I = vertex_radiosity(mesh, I);

  // The picture: per eye ray, E + rho (D + I) at the point hit.
  const DisplaySettings& d = s.display;
  const CameraFrame frame = camera_frame(scene.camera, d.width, d.height);
  ReferencePicture out;
  out.picture = {Image(d.width, d.height), Image(d.width, d.height)};
  out.elements = n;
  std::vector<double> direct_sum(d.height, 0.0), indirect_sum(d.height, 0.0);
  parallel_for(d.height, d.threads, [&](int y) {
    for (int x = 0; x < d.width; ++x) {
      Rng rng(d.seed, static_cast<std::uint64_t>(y) * d.width + x);
      Color sum(0.0), shown(0.0);
      for (int k = 0; k < d.samples * d.samples; ++k) {
        const double px = x + (k % d.samples + rng.uniform()) / d.samples;
        const double py = y + (k / d.samples + rng.uniform()) / d.samples;
        const Ray ray = primary_ray(frame, px, py);
        const auto hit = receivers.first_hit(ray);
        if (!hit || !hit->front) continue;
        const Element& e = mesh.elements[hit->polygon];
        const vec3 p = ray.at(hit->t);
        const vec2 st = unbilinear(e.shape.corners, e.shape.normal, p);
        const auto& v = e.vertices;
        const Color indirect = (1 - st.x) * (1 - st.y) * vertex_I[v[0]] + st.x * (1 - st.y) * vertex_I[v[1]] +
                               st.x * st.y * vertex_I[v[2]] + (1 - st.x) * st.y * vertex_I[v[3]];
        const Color direct = direct_light(blockers, emitters, p, e.shape.normal, s.shadow_rays_per_side, rng);
        const Color rho = mesh.reflectance(e), E = mesh.emission(e);
        const Color radiance = (E + rho * (direct + indirect)) / pi;  // L = B / pi
        sum += radiance;
        shown += d.white > 0 ? glm::min(radiance, Color(d.white)) : radiance;
        if (max_component(E) == 0) {
          direct_sum[y] += luminance(rho * direct);
          indirect_sum[y] += luminance(rho * indirect);
        }
      }
      out.picture.radiance.at(x, y) = Pixel(sum / static_cast<double>(d.samples * d.samples));
      out.picture.shown.at(x, y) = Pixel(shown / static_cast<double>(d.samples * d.samples));
    }
  });
  out.surface = visible_polygons(blockers, scene.camera, d.width, d.height, d.threads);
  double direct = 0, indirect = 0;
  for (int y = 0; y < d.height; ++y) direct += direct_sum[y], indirect += indirect_sum[y];
  out.indirect_share = direct + indirect > 0 ? indirect / (direct + indirect) : 0;
  return out;
}

double relative_block_error(const Image& test, const Image& reference, int block, const std::vector<int>& surface) {
  if (!test.same_size(reference)) throw std::invalid_argument("relative block error: pictures of different sizes");
  if (block < 1 || test.width % block || test.height % block)
    throw std::invalid_argument("relative block error: the block must divide the picture's width and height");
  if (surface.size() != reference.pixels.size()) throw std::invalid_argument("relative block error: one id per pixel");
  const int w = test.width, h = test.height;
  // One surface over the block and the ring of pixels around it.
  const auto whole = [&](int bx, int by) {
    const int id = surface[static_cast<std::size_t>(by * block) * w + bx * block];
    for (int y = std::max(0, by * block - 1); y < std::min(h, (by + 1) * block + 1); ++y)
      for (int x = std::max(0, bx * block - 1); x < std::min(w, (bx + 1) * block + 1); ++x)
        if (surface[static_cast<std::size_t>(y) * w + x] != id) return false;
    return id >= 0;
  };
  const auto block_mean = [&](const Image& image, int bx, int by) {
    Color sum(0.0);
    for (int y = by * block; y < (by + 1) * block; ++y)
      for (int x = bx * block; x < (bx + 1) * block; ++x) sum += Color(image.at(x, y));
    return sum / static_cast<double>(block * block);
  };
  double mean = 0;
  for (const Pixel& p : reference.pixels) mean += (p.x + p.y + p.z) / 3.0;
  mean /= static_cast<double>(reference.pixels.size());
  double sum = 0;
  long long count = 0;
  for (int by = 0; by < h / block; ++by)
    for (int bx = 0; bx < w / block; ++bx) {
      if (!whole(bx, by)) continue;
      const Color t = block_mean(test, bx, by), r = block_mean(reference, bx, by);
      for (int c = 0; c < 3; ++c)
        if (r[c] >= 1e-3 * mean) sum += (t[c] - r[c]) * (t[c] - r[c]) / (r[c] * r[c]), ++count;
    }
  return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0;
}

}  // namespace gi
