#include "gi/twopass/two_pass.hpp"

#include <stdexcept>

#include "gi/twopass/final_gather.hpp"
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

EyePass::EyePass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings)
    : handoff_(handoff),
      settings_(settings),
      eye_(make_eye_world(handoff.mesh, scene.spheres)),
      lights_(shadow_ray_lights(handoff.mesh, settings.light_cells)),
      ambient_(ambient_irradiance(handoff.mesh)) {
  check(settings);
  if (handoff.mesh.surfaces.size() != scene.surfaces.size())
    throw std::invalid_argument("two-pass: the hand-off is not of this scene's surfaces");
}

// The radiance arriving along `ray`, after `depth` specular bounces.
Color EyePass::radiance(const Ray& ray, int depth, PixelSample& sample) const {
  const auto hit = first_hit(eye_, ray);
  if (!hit) return Color(0.0);
  if (hit->element < 0) return specular(ray, *hit, depth, sample);
  if (dot(ray.direction, hit->hit.normal) >= 0) return Color(0.0);  // the back of a surface
  const Element& e = handoff_.mesh.elements[hit->element];
  const Color rho = handoff_.mesh.reflectance(e), E = handoff_.mesh.emission(e);
  const vec3& n = e.shape.normal;
  const vec3 x = hit->hit.point + 1e-7 * length(e.shape.corners[2] - e.shape.corners[0]) * n;
  const Color H = irradiance_by_shadow_rays(eye_, lights_, x, n, sample, depth);
  Color L = (E + rho * H) / pi;
  switch (settings_.indirect) {
    case IndirectLight::Ambient: return L + rho * ambient_ / pi;
    case IndirectLight::Mesh: return L + indirect_radiosity_at(handoff_, hit->element, hit->hit.point) / pi;
    case IndirectLight::FinalGather:
      return L + rho * final_gather(eye_, handoff_, x, n, settings_.gather_strata, sample.rng) / pi;
  }
  return L;
}

// Mirror and glass: the light of the one or two rays they send on (specular.hpp).
Color EyePass::specular(const Ray& ray, const EyeHit& hit, int depth, PixelSample& sample) const {
  if (depth >= settings_.max_depth) return Color(0.0);
  const SpecularRays next = specular_rays(eye_.world.scene.materials[hit.hit.material], ray, hit.hit, eye_.world.scale);
  Color L(0.0);
  for (int i = 0; i < next.count; ++i) L += next.rays[i].weight * radiance(next.rays[i].ray, depth + 1, sample);
  return L;
}

Image render_two_pass(const TwoPassScene& scene, const RadiosityHandoff& handoff, const TwoPassSettings& settings,
                      std::uint64_t seed, int threads) {
  const EyePass eye(scene, handoff, settings);
  const auto eye_rays = static_cast<std::uint32_t>(settings.samples * settings.samples);
  Film film = make_film(settings.width, settings.height, seed, settings.sequence, eye_rays);
  render_pass(film, scene.camera, {Sampler::Jittered, settings.samples}, eye, threads);
  return film_mean(film);
}

}  // namespace gi
