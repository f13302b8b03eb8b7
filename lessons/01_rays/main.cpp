// Lesson 01 -- rays: where does a ray meet a sphere, where a plane?
// Prints worked cases (tangent rays, rays starting inside, parallel rays ...)
// and draws what eye rays see: which surface each hits first, the surface normal,
// the distance.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "gi/core/parallel.hpp"
#include "gi/geometry/plane.hpp"
#include "gi/geometry/sphere.hpp"
#include "gi/image/diff.hpp"
#include "gi/image/image_io.hpp"
#include "gi/raytrace/render.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/table.hpp"

namespace {

struct Case {
  std::string name;
  gi::Ray ray;
};

std::string text(const gi::vec3& v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "(%.3g, %.3g, %.3g)", v.x, v.y, v.z);
  return buffer;
}

// One flat colour per material, so that the picture shows which surface each eye ray
// meets first (an item buffer): the Okabe-Ito colours, told apart with any colour
// vision, as linear values that the PNG's sRGB encoding turns back into them.
gi::Pixel surface_colour(int material) {
  static const int palette[] = {0xE69F00, 0x56B4E9, 0x009E73, 0xF0E442, 0x0072B2, 0xD55E00, 0xCC79A7, 0x999999};
  const int rgb = palette[material % 8];
  const auto channel = [&](int shift) { return gi::from_srgb8(static_cast<std::uint8_t>((rgb >> shift) & 0xFF)); };
  return gi::Pixel(channel(16), channel(8), channel(0));
}

// One row per case: the ray, and what the intersection routine answers.
template <class Shape>
gi::Table worked_cases(const std::string& title, const Shape& shape, const std::vector<Case>& cases) {
  gi::Table table(title, {{"case"}, {"origin"}, {"direction"}, {"t", 4}, {"hit point"}, {"normal"}});
  for (const Case& c : cases) {
    const auto hit = gi::intersect(c.ray, shape);
    if (hit)
      table.add_row({c.name, text(c.ray.origin), text(c.ray.direction), hit->t, text(hit->point), text(hit->normal)});
    else
      table.add_row({c.name, text(c.ray.origin), text(c.ray.direction), "miss", "-", "-"});
  }
  return table;
}

// The three pictures of what the eye rays hit.
void draw_eye_rays(const gi::World& world, int width, int height, gi::Lesson& lesson) {
  const gi::CameraFrame frame = gi::camera_frame(world.scene.camera, width, height);
  gi::Image first_hit(width, height), normals(width, height);
  std::vector<double> distance(static_cast<std::size_t>(width) * height, 0.0);
  // Depth in false colour: red near the eye through yellow, green and blue to black
  // at twice the distance to the point the camera looks at, and for misses.
  const double far = 2.0 * gi::length(world.scene.camera.look_at - world.scene.camera.eye);
  gi::parallel_for(height, lesson.threads(), [&](int y) {
    for (int x = 0; x < width; ++x) {
      const auto hit = gi::closest_hit(world, gi::primary_ray(frame, x + 0.5, y + 0.5));
      if (!hit) continue;
      first_hit.at(x, y) = surface_colour(hit->material);
      normals.at(x, y) = gi::Pixel(0.5 * hit->normal + 0.5);  // [-1, 1] -> [0, 1] per axis
      distance[static_cast<std::size_t>(y) * width + x] = std::max(0.0, 1.0 - hit->t / far);
    }
  });
  const gi::View view{world.scene.camera, width, height, gi::describe_pixel_samples({})};
  lesson.diagram(first_hit, "first_hit",
                 "the surface each eye ray hits first, one colour per material; black where it misses");
  lesson.picture(normals, "normals", "the surface normal n as the colour 0.5 n + 0.5", view);
  lesson.diagram(gi::false_colour(distance, width, height, 0.0, 1.0), "depth",
                 "distance to the hit in false colour, red near, black at twice the distance to look_at",
                 gi::ColourScale{far, 0, "distance t along the eye ray (misses black)"});
}

}  // namespace

int main(int argc, char** argv) {
  gi::Lesson lesson("01_rays", "Ray-sphere and ray-plane intersection: worked cases and eye-ray images.",
                    {.seed = false});
  std::string accel = "bvh";  // a kit without lab 5 done can still render by brute force
  int width = 480, height = 360;
  std::string scene_name = "spheres";
  gi::Scene scene;
  lesson.add_image_size(width, height);
  lesson.options().add("--accel", accel, "how rays find what they hit (lesson 05)", gi::acceleration_names());
  lesson.add_scene(scene_name, scene);
  return lesson.run(argc, argv, [&] {
    const gi::Sphere sphere{{0, 0, -5}, 1, 0};
    const gi::Table spheres = worked_cases("Ray-sphere: sphere at (0, 0, -5), radius 1", sphere,
        {{"head-on", {{0, 0, 0}, {0, 0, -1}}},
         {"off-centre", {{0.5, 0, 0}, {0, 0, -1}}},
         {"tangent", {{1, 0, 0}, {0, 0, -1}}},
         {"miss", {{1.5, 0, 0}, {0, 0, -1}}},
         {"origin inside", {{0, 0, -5}, {0, 0, -1}}},
         {"sphere behind", {{0, 0, 0}, {0, 0, 1}}},
         {"direction length 2", {{0, 0, 0}, {0, 0, -2}}}});
    const gi::Plane plane{{0, 0, 0}, {0, 1, 0}, 0};
    const gi::Table planes = worked_cases("Ray-plane: the floor y = 0, normal +y", plane,
        {{"oblique", {{0, 2, 0}, gi::normalize(gi::vec3(1, -1, 0))}},
         {"straight down", {{0, 2, 0}, {0, -1, 0}}},
         {"from below", {{0, -1, 0}, {0, 1, 0}}},
         {"parallel", {{0, 1, 0}, {1, 0, 0}}},
         {"in the plane", {{0, 0, 0}, {1, 0, 0}}},
         {"pointing away", {{0, 1, 0}, {0, 1, 0}}},
         {"grazing", {{0, 1, 0}, gi::normalize(gi::vec3(1, -1e-4, 0))}}});
    lesson.table(spheres, "ray_sphere");
    std::cout << '\n';
    lesson.table(planes, "ray_plane");

    const gi::World world = gi::make_world(scene, gi::acceleration_from_name(accel));
    draw_eye_rays(world, width, height, lesson);
    lesson.say("\nimages: " + lesson.out().string() + "/{first_hit,normals,depth}.png");
  });
}
