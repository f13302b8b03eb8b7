#include "gi/pathtrace/veach_plates.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "gi/raytrace/optics.hpp"

namespace gi {

namespace {

const vec3 eye(0, 2, 15), look_at(0, -2, 2.5);
const double light_x[plate_light_count] = {-3.75, -1.25, 1.25, 3.75};
// The plates' centres, back to front: on the eye rays 13.5, 18.5, 23.5 and 28.5 degrees
// below the horizon (the lights are at 7.6, the picture spans 2.7 to 32.7), z = 1.0, 2.3,
// 3.6, 4.9, so that each has a band of the picture to itself. Each is tilted to mirror the lights' centre to the eye.
const vec3 plate_centres[plate_count] = {{0, -1.361, 1.0}, {0, -2.249, 2.3}, {0, -2.957, 3.6}, {0, -3.484, 4.9}};
const vec3 lights_centre(0, 0, 0);
constexpr double plate_width = 9, plate_depth = 1.6;

// The normal that mirrors the lights' centre into the eye at p: the half vector.
vec3 plate_normal(const vec3& p) { return normalize(normalize(eye - p) + normalize(lights_centre - p)); }

}  // namespace

Scene veach_plates_scene() {
  Scene s;
  s.name = "veach-plates";
  for (int j = 0; j < plate_count; ++j) {
    Material plate;
    plate.name = "plate " + std::to_string(j);
    plate.diffuse = Color(0.0);
    plate.specular = Color(0.8);  // k_s: a Phong lobe and nothing else (bsdf_at's Glossy)
    plate.shininess = plate_exponents[j];
    s.add(plate);
  }
  for (int j = 0; j < plate_count; ++j) {
    const vec3 n = plate_normal(plate_centres[j]);
    const vec3 across(plate_width, 0, 0);
    const vec3 along = plate_depth * normalize(cross(n, vec3(1, 0, 0)));  // up the slope, in the plate
    s.add(Quad{plate_centres[j] - 0.5 * across - 0.5 * along, across, along, j});
  }
  for (int k = 0; k < plate_light_count; ++k) {
    const double r = plate_light_radii[k];
    Material light;
    light.name = "light " + std::to_string(k);
    light.diffuse = Color(0.0);
    light.emission = Color(1 / (r * r));  // the same power pi (4 pi r^2) L_e for every light
    s.add(Sphere{vec3(light_x[k], 0, 0), r, s.add(light)});
  }
  s.background = Color(0.02);
  s.camera = Camera{eye, look_at, vec3(0, 1, 0), 30};
  return s;
}

namespace {

// What the eye ray through each pixel's point (x + dx, y + dy) meets first, and where:
// the hits, row-major.
std::vector<std::optional<Hit>> first_hits(const PathScene& scene, int width, int height, double dx = 0.5,
                                           double dy = 0.5) {
  const CameraFrame frame = camera_frame(scene.scene().camera, width, height);
  std::vector<std::optional<Hit>> hits;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) hits.push_back(closest_hit(scene.world, primary_ray(frame, x + dx, y + dy)));
  return hits;
}

}  // namespace

std::vector<char> plates_mask(const PathScene& scene, int width, int height) {
  std::vector<char> mask;
  for (const std::optional<Hit>& hit : first_hits(scene, width, height))
    mask.push_back(hit && hit->material < plate_count);
  return mask;
}

std::vector<char> highlight_mask(const PathScene& scene, int width, int height, int plate, int light) {
  const Scene& s = scene.scene();
  const Sphere& sphere = s.spheres.at(light);
  const int material = s.quads.at(plate).material;
  const double exponent = s.materials[material].shininess;
  const double lobe = std::acos(std::pow(0.1, 1 / exponent));  // cos^n(lobe) = 1/10
  std::vector<char> mask(std::size_t(width) * height, 0);
  for (int k = 0; k < 16; ++k) {  // 4 x 4 points of each pixel
    const std::vector<std::optional<Hit>> hits = first_hits(scene, width, height, (k % 4 + 0.5) / 4, (k / 4 + 0.5) / 4);
    for (std::size_t i = 0; i < hits.size(); ++i) {
      const std::optional<Hit>& hit = hits[i];
      if (!hit || hit->material != material) continue;
      const vec3 view = normalize(hit->point - s.camera.eye);
      const vec3 mirror = reflect(view, dot(hit->normal, view) < 0 ? hit->normal : -hit->normal);
      const vec3 to_light = sphere.center - hit->point;
      const double distance = length(to_light);
      const double angle = std::acos(std::clamp(dot(mirror, to_light / distance), -1.0, 1.0));
      if (angle < lobe + std::asin(std::min(1.0, sphere.radius / distance))) mask[i] = 1;
    }
  }
  return mask;
}

std::vector<double> relative_error_map(const Image& test, const Image& reference, double epsilon) {
  if (test.width != reference.width || test.height != reference.height)
    throw std::invalid_argument("relative error: pictures of different sizes");
  const auto grey = [](const Pixel& p) { return (double(p.x) + p.y + p.z) / 3; };
  std::vector<double> errors;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i)
    errors.push_back(std::abs(grey(test.pixels[i]) - grey(reference.pixels[i])) / (grey(reference.pixels[i]) + epsilon));
  return errors;
}

double rms_over(const std::vector<double>& errors, const std::vector<char>& mask) {
  if (!mask.empty() && mask.size() != errors.size())
    throw std::invalid_argument("RMS over a mask: the mask has another size than the picture");
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < errors.size(); ++i)
    if (mask.empty() || mask[i]) sum += errors[i] * errors[i], ++count;
  if (count == 0) throw std::invalid_argument("RMS over a mask: the mask holds no pixel");
  return std::sqrt(sum / double(count));
}

}  // namespace gi
