// Lesson 05, step 5: what a bounding volume hierarchy is and what it saves, as pictures
// (studies.hpp). The tree's boxes, level by level, drawn over the spheres they hold,
// and the work each eye ray does, pixel by pixel, for brute force, a box per object
// and the BVH.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gi/accel/world.hpp"
#include "gi/image/diff.hpp"
#include "gi/render/scene_lines.hpp"
#include "gi/scene/benchmark_scenes.hpp"
#include "studies.hpp"

namespace lesson05 {
namespace {

// The twelve edges of a box.
void draw_box(gi::Image& image, const gi::CameraFrame& frame, const gi::Aabb& box, gi::Pixel colour) {
  const gi::vec3 corner[2] = {box.lo, box.hi};
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 4; ++k) {
      gi::vec3 a, b;
      for (int i = 0, bit = 0; i < 3; ++i) {
        const int side = i == axis ? 0 : (k >> bit++) & 1;
        a[i] = corner[side][i];
        b[i] = i == axis ? corner[1][i] : a[i];
      }
      gi::draw_segment(image, frame, a, b, colour);
    }
}

// The spheres lit from the eye, |n . d|, each in the colour of the group it belongs to.
gi::Image shaded(const gi::World& world, const gi::CameraFrame& frame, int width, int height,
                 const std::vector<gi::Pixel>& sphere_colour) {
  gi::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const gi::Ray ray = gi::primary_ray(frame, x + 0.5, y + 0.5);
      if (const auto hit = gi::closest_hit(world, ray))
        image.at(x, y) = static_cast<float>(std::abs(glm::dot(hit->normal, ray.direction))) * sphere_colour[hit->object];
    }
  return image;
}

// The nodes `level` steps below the root (a leaf above that level stands for itself).
std::vector<int> nodes_at(const gi::Bvh& bvh, int level) {
  std::vector<int> found;
  std::vector<std::pair<int, int>> stack{{0, 0}};  // (node, its level)
  while (!stack.empty()) {
    const auto [node, at] = stack.back();
    stack.pop_back();
    const gi::BvhNode& n = bvh.nodes[node];
    if (at == level || n.count > 0)
      found.push_back(node);
    else
      stack.insert(stack.end(), {{n.offset, at + 1}, {node + 1, at + 1}});  // left child first off the stack
  }
  return found;
}

// Marks every sphere below `node` with `colour`.
void colour_spheres(const gi::Bvh& bvh, int node, gi::Pixel colour, std::vector<gi::Pixel>& sphere_colour) {
  const gi::BvhNode& n = bvh.nodes[node];
  if (n.count == 0) {
    colour_spheres(bvh, node + 1, colour, sphere_colour);
    colour_spheres(bvh, n.offset, colour, sphere_colour);
    return;
  }
  for (int k = n.offset; k < n.offset + n.count; ++k)
    if (bvh.refs[k].kind == gi::PrimitiveKind::Sphere) sphere_colour[bvh.refs[k].index] = colour;
}

// log10 of the box and primitive tests of each pixel's eye ray.
std::vector<double> work_per_pixel(const gi::World& world, const gi::CameraFrame& frame, int width, int height) {
  std::vector<double> tests;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      gi::TraversalCounts counts;
      gi::closest_hit(world, gi::primary_ray(frame, x + 0.5, y + 0.5), &counts);
      tests.push_back(std::log10(std::max<double>(1, counts.box_tests + counts.primitive_tests)));
    }
  return tests;
}

}  // namespace

void pictures(int spheres, int width, int height, gi::Lesson& lesson) {
  const gi::Scene scene = gi::random_spheres(spheres, lesson.seed());
  const gi::CameraFrame frame = gi::camera_frame(scene.camera, width, height);
  const gi::World bvh = gi::make_world(scene, gi::Acceleration::Bvh);

  // Levels 1, 2 and 3 of the tree, one picture each, seen from farther than the scene's
  // camera so that the root's box is whole: each node's box and the spheres it holds
  // in a colour of its own.
  gi::Camera far = scene.camera;
  far.eye = far.look_at + 1.35 * (far.eye - far.look_at);
  const gi::CameraFrame far_frame = gi::camera_frame(far, width, height);
  const gi::Pixel palette[] = {{1, 0.3f, 0.2f}, {0.2f, 0.6f, 1},   {1, 0.85f, 0.1f}, {0.3f, 0.9f, 0.3f},
                               {0.9f, 0.3f, 1}, {0.1f, 0.9f, 0.9f}, {1, 0.55f, 0.1f}, {0.85f, 0.85f, 0.85f}};
  std::vector<gi::Image> levels;
  for (int level = 1; level <= 3; ++level) {
    const std::vector<int> nodes = nodes_at(bvh.bvh, level);
    std::vector<gi::Pixel> sphere_colour(scene.spheres.size(), gi::Pixel(0.5f));
    for (std::size_t k = 0; k < nodes.size(); ++k) colour_spheres(bvh.bvh, nodes[k], palette[k % 8], sphere_colour);
    gi::Image picture = shaded(bvh, far_frame, width, height, sphere_colour);
    for (std::size_t k = 0; k < nodes.size(); ++k) draw_box(picture, far_frame, gi::box(bvh.bvh.nodes[nodes[k]]), palette[k % 8]);
    levels.push_back(picture);
  }
  lesson.diagram(gi::side_by_side(levels), "bvh_levels",
                 "the BVH (SAH) over " + std::to_string(spheres) + " random spheres, levels 1, 2 and 3 below the root "
                 "(left to right): each node's box, and the spheres it holds, in a colour of its own; each box holds "
                 "about half of its parent's spheres, and boxes of one level may overlap");

  // Tests per eye ray, pixel by pixel, on one logarithmic scale.
  std::vector<gi::Image> maps;
  for (gi::Acceleration a : {gi::Acceleration::BruteForce, gi::Acceleration::BoundingBoxes, gi::Acceleration::Bvh})
    maps.push_back(gi::false_colour(work_per_pixel(a == gi::Acceleration::Bvh ? bvh : gi::make_world(scene, a), frame,
                                                   width, height),
                                    width, height, 0, std::log10(2.0 * spheres)));
  lesson.diagram(gi::side_by_side(maps), "tests_per_pixel",
                 "box and sphere tests of each pixel's eye ray among " + std::to_string(spheres) +
                     " spheres: brute force, a box per object, the BVH (left to right); brute force tests every "
                     "sphere, a box per object every box, the BVH a few dozen boxes, most along the spheres' edges",
                 gi::ColourScale{1, 2.0 * spheres, "tests per eye ray", true});
}

}  // namespace lesson05
