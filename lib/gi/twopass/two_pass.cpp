#include "gi/twopass/two_pass.hpp"

#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/rng.hpp"
#include "gi/twopass/final_gather.hpp"
#include "gi/twopass/shadow_rays.hpp"
#include "gi/twopass/specular.hpp"

namespace gi {

std::string name(IndirectLight indirect) {
  switch (indirect) {
    case IndirectLight::Ambient: return "ambient";
    case IndirectLight::Mesh: return "mesh";
    case IndirectLight::FinalGather: return "final gather";
  }
  return "?";
}

void check(const TwoPassSettings& s) {
  const auto in = [](int v, int lo, int hi) { return v >= lo && v <= hi; };
  if (!in(s.width, 1, 8192) || !in(s.height, 1, 8192))
    throw std::invalid_argument("two-pass: width and height must lie in [1, 8192]");
  if (!in(s.samples, 1, 16)) throw std::invalid_argument("two-pass: samples must lie in [1, 16]");
  if (!in(s.light_cells, 1, 64)) throw std::invalid_argument("two-pass: light cells must lie in [1, 64]");
  if (!in(s.gather_strata, 1, 64)) throw std::invalid_argument("two-pass: gather strata must lie in [1, 64]");
  if (!in(s.max_depth, 0, 64)) throw std::invalid_argument("two-pass: max depth must lie in [0, 64]");
}

Color ambient_irradiance(const Mesh& mesh) {
  double area = 0;
  Color emitted(0.0), reflecting(0.0);
  for (const Element& e : mesh.elements) {
    area += e.shape.area;
    emitted += mesh.emission(e) * e.shape.area;
    reflecting += mesh.reflectance(e) * e.shape.area;
  }
  const Color rho_avg = reflecting / area;
  return rho_avg / (Color(1.0) - rho_avg) * emitted / area;
}

namespace {

struct EyePass {
  const RadiosityHandoff& handoff;
  const TwoPassSettings& settings;
  EyeWorld eye;
  ShadowRayLights lights;
  Color ambient;

  // The radiance arriving along `ray`, after `depth` specular bounces.
  Color radiance(const Ray& ray, int depth, Rng& rng) const {
    const auto hit = first_hit(eye, ray);
    if (!hit) return Color(0.0);
    if (hit->element < 0) return specular(ray, *hit, depth, rng);
    if (dot(ray.direction, hit->hit.normal) >= 0) return Color(0.0);  // the back of a surface
    const Element& e = handoff.mesh.elements[hit->element];
    const Color rho = handoff.mesh.reflectance(e), E = handoff.mesh.emission(e);
    const vec3& n = e.shape.normal;
    const vec3 x = hit->hit.point + 1e-7 * length(e.shape.corners[2] - e.shape.corners[0]) * n;
    const Color H = irradiance_by_shadow_rays(eye, lights, x, n, rng);
    Color L = (E + rho * H) / pi;
    switch (settings.indirect) {
      case IndirectLight::Ambient: return L + rho * ambient / pi;
      case IndirectLight::Mesh: return L + indirect_radiosity_at(handoff, hit->element, hit->hit.point) / pi;
      case IndirectLight::FinalGather:
        return L + rho * final_gather(eye, handoff, x, n, settings.gather_strata, rng) / pi;
    }
    return L;
  }

  // Mirror and glass: the light of the one or two rays they send on (specular.hpp).
  Color specular(const Ray& ray, const EyeHit& hit, int depth, Rng& rng) const {
    if (depth >= settings.max_depth) return Color(0.0);
    const SpecularRays next = specular_rays(eye.world.scene.materials[hit.hit.material], ray, hit.hit, eye.world.scale);
    Color L(0.0);
    for (int i = 0; i < next.count; ++i) L += next.rays[i].weight * radiance(next.rays[i].ray, depth + 1, rng);
    return L;
  }
};

}  // namespace

Image render_two_pass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings) {
  check(settings);
  if (handoff.mesh.surfaces.size() != scene.surfaces.size())
    throw std::invalid_argument("two-pass: the hand-off is not of this scene's surfaces");
  const EyePass pass{handoff, settings, make_eye_world(handoff.mesh, scene.spheres),
                     shadow_ray_lights(handoff.mesh, settings.light_cells), ambient_irradiance(handoff.mesh)};
  const CameraFrame frame = camera_frame(scene.camera, settings.width, settings.height);
  Image picture(settings.width, settings.height);
  const int n = settings.samples;
  parallel_for(settings.height, settings.threads, [&](int y) {
    for (int x = 0; x < settings.width; ++x) {
      Rng rng(settings.seed, static_cast<std::uint64_t>(y) * settings.width + x);
      Color sum(0.0);
      for (int k = 0; k < n * n; ++k) {
        const double px = x + (k % n + rng.uniform()) / n, py = y + (k / n + rng.uniform()) / n;
        sum += pass.radiance(primary_ray(frame, px, py), 0, rng);
      }
      picture.at(x, y) = Pixel(sum / double(n * n));
    }
  });
  return picture;
}

}  // namespace gi
