// Not a lesson: how far our BVH is from a production one. Builds quad_room as our
// BVH and as an Intel Embree 3 triangle mesh (two triangles per quad), casts the
// same rays into both on one thread -- camera rays (coherent) and rays from random
// points in random directions (incoherent) -- and prints build times, Mrays/s and
// how often the two agree. Built only where Embree is installed; see
// lessons/CMakeLists.txt.
#include <embree3/rtcore.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "gi/accel/ray_sets.hpp"
#include "gi/accel/world.hpp"
#include "gi/core/rng.hpp"
#include "gi/core/timer.hpp"
#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/benchmark_scenes.hpp"

namespace {

constexpr float inf = std::numeric_limits<float>::infinity();

// Embree's device and scene, released in the right order.
struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  Embree() = default;
  Embree(const Embree&) = delete;
  Embree& operator=(const Embree&) = delete;
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

// One thread for the build too, so both builds are timed alike.
void make_embree_scene(Embree& embree, const gi::Scene& scene, bool robust) {
  if (!embree.device) embree.device = rtcNewDevice("threads=1");
  if (!embree.device) throw std::runtime_error("Embree: no device (rtcNewDevice failed)");
  if (embree.scene) rtcReleaseScene(embree.scene);
  embree.scene = rtcNewScene(embree.device);
  if (robust) rtcSetSceneFlags(embree.scene, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry mesh = rtcNewGeometry(embree.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const std::size_t quads = scene.quads.size();
  auto* vertex = static_cast<float*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                             3 * sizeof(float), 4 * quads));
  auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), 2 * quads));
  for (std::size_t q = 0; q < quads; ++q) {
    const gi::Quad& quad = scene.quads[q];
    const gi::vec3 corners[4] = {quad.corner, quad.corner + quad.edge_u, quad.corner + quad.edge_u + quad.edge_v,
                                 quad.corner + quad.edge_v};
    for (std::size_t k = 0; k < 4; ++k)
      for (int axis = 0; axis < 3; ++axis) vertex[12 * q + 3 * k + axis] = static_cast<float>(corners[k][axis]);
    const auto v = static_cast<unsigned>(4 * q);
    const unsigned triangles[6] = {v, v + 1, v + 2, v, v + 2, v + 3};
    for (std::size_t k = 0; k < 6; ++k) index[6 * q + k] = triangles[k];
  }
  rtcCommitGeometry(mesh);
  rtcAttachGeometry(embree.scene, mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(embree.scene);  // the build
}

RTCRay embree_ray(const gi::Ray& ray) {
  RTCRay r{};
  r.org_x = static_cast<float>(ray.origin.x);
  r.org_y = static_cast<float>(ray.origin.y);
  r.org_z = static_cast<float>(ray.origin.z);
  r.dir_x = static_cast<float>(ray.direction.x);
  r.dir_y = static_cast<float>(ray.direction.y);
  r.dir_z = static_cast<float>(ray.direction.z);
  r.tnear = static_cast<float>(ray.t_min);
  r.tfar = std::isinf(ray.t_max) ? inf : static_cast<float>(ray.t_max);
  r.mask = ~0u;
  return r;
}

// Median milliseconds of `repeats` runs of `run`.
double time_ms(int repeats, const std::function<void()>& run) {
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    gi::Timer timer;
    run();
    ms.push_back(timer.milliseconds());
  }
  return gi::median(ms);
}

// Ours and Embree's runs alternated, A B A B ..., so that a busy moment of a shared
// machine falls on both: the medians of each, and the median of the pairs' ratios
// (ours/Embree as a ratio of speeds: Embree's time over ours).
struct Paired {
  double ours_ms, embree_ms, ratio;
};
Paired alternate(int repeats, const std::function<void()>& ours, const std::function<void()>& embree) {
  std::vector<double> a, b, ratio;
  for (int i = 0; i < repeats; ++i) {
    a.push_back(time_ms(1, ours));
    b.push_back(time_ms(1, embree));
    ratio.push_back(b.back() / a.back());
  }
  return {gi::median(a), gi::median(b), gi::median(ratio)};
}

}  // namespace

int main(int argc, char** argv) {
  return gi::run_lesson("05_embree_bench", [&] {
    int quads = 100000, width = 512, height = 512, random_rays = 262144, repeats = 5;
    double segment = 4.0;
    std::uint64_t seed = 1;
    bool robust = false;
    std::string out = "out/05_embree_bench";
    std::string accel = "bvh-fast";
    gi::BvhSettings tree;
    gi::Options options("05_embree_bench", "Our BVH against Intel Embree 3 on quad_room, one thread.");
    options.add("--quads", quads, "about how many quads the room is made of", 50, 10'000'000)
        .add("--width", width, "camera rays: image width", 1, 8192)
        .add("--height", height, "camera rays: image height", 1, 8192)
        .add("--random", random_rays, "number of random rays", 1, 100'000'000)
        .add("--segment", segment, "length of the any-hit (shadow) rays", 1e-3, 1e3)
        .add("--repeats", repeats, "timed runs of each query; the median is shown", 1, 100)
        .add("--seed", seed, "seed of the random rays")
        .add_flag("--robust", robust, "build Embree's scene with RTC_SCENE_FLAG_ROBUST (watertight, slower)")
        .add("--accel", accel, "our walk of the tree: the lab's (bvh) or the production one (bvh-fast)",
             {"bvh", "bvh-fast"})
        .add("--leaf-size", tree.max_leaf_size, "most primitives in a leaf of our tree", 1, 255)
        .add("--bins", tree.bins, "SAH bins of our tree's builder", 2, 256)
        .add("--out", out, "folder for the tables (CSV)");
    if (!options.parse(argc, argv)) return 0;

    const gi::Scene scene = gi::quad_room(quads);
    gi::World world;
    const double our_build = time_ms(repeats, [&] { world = gi::make_world(scene, gi::acceleration_from_name(accel), tree); });
    Embree embree;
    const double embree_build = time_ms(repeats, [&] { make_embree_scene(embree, scene, robust); });
    gi::Table builds("Builds of " + scene.name + ": " + std::to_string(scene.quads.size()) + " quads, one thread",
                     {{"structure"}, {"primitives"}, {"build ms", 1}});
    builds.add_row({"ours: BVH, binned SAH" + std::string(accel == "bvh-fast" ? ", made 8-wide" : ""),
                    static_cast<long long>(scene.quads.size()), our_build});
    builds.add_row({std::string("Embree ") + RTC_VERSION_STRING + ": BVH, medium quality" + (robust ? ", robust" : ""),
                    static_cast<long long>(2 * scene.quads.size()), embree_build});

    // The rays: one per pixel from the camera, and from random points in the room
    // ([-5, 5] x [0, 3.5] x [-5, 5], kept 0.1 off the walls) in uniform directions.
    gi::Rng rng(seed);
    const std::vector<gi::Ray> camera = gi::camera_rays(scene, width, height);
    const std::vector<gi::Ray> random = gi::random_rays(gi::quad_room_interior(), random_rays, rng);

    gi::Table queries("Queries, one thread, ours (" + accel + ") and Embree " + RTC_VERSION_STRING +
                          " alternated, medians of " + std::to_string(repeats) + " runs; ours/Embree: median of the pairs",
                      {{"rays"}, {"query"}, {"count"}, {"ours ms", 1}, {"ours Mrays/s", 2}, {"Embree ms", 1},
                       {"Embree Mrays/s", 2}, {"ours/Embree", 2}, {"agree %", 3}});
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (const auto& kind : {std::pair{"camera", &camera}, std::pair{"random", &random}}) {
      const auto label = kind.first;  // not a structured binding: Clang before 16 cannot capture one
      const auto rays = kind.second;
      const std::size_t n = rays->size();
      std::vector<double> our_t(n), embree_t(n);  // +inf for a miss
      const Paired closest = alternate(
          repeats,
          [&] {
            for (std::size_t i = 0; i < n; ++i) {
              const auto hit = gi::closest_hit(world, (*rays)[i]);
              our_t[i] = hit ? hit->t : std::numeric_limits<double>::infinity();
            }
          },
          [&] {
            for (std::size_t i = 0; i < n; ++i) {
              RTCRayHit rayhit{};
              rayhit.ray = embree_ray((*rays)[i]);
              rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
              rtcIntersect1(embree.scene, &context, &rayhit);
              embree_t[i] = rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<double>::infinity()
                                                                          : static_cast<double>(rayhit.ray.tfar);
            }
          });
      // Agreement: the same hit or miss, and t within 1e-4 relative -- or 1e-5 absolute,
      // as rounding a ray's origin to float alone moves it by up to 3e-7 in this room.
      std::size_t agree = 0;
      for (std::size_t i = 0; i < n; ++i)
        agree += std::isinf(our_t[i]) ? std::isinf(embree_t[i])
                                      : std::abs(our_t[i] - embree_t[i]) <= 1e-4 * our_t[i] + 1e-5;
      queries.add_row({label, "closest hit", static_cast<long long>(n), closest.ours_ms, 1e-3 * n / closest.ours_ms,
                       closest.embree_ms, 1e-3 * n / closest.embree_ms, closest.ratio, 100.0 * agree / n});

      // The same rays cut to `segment`, as shadow rays: blocked or not?
      std::vector<char> our_blocked(n), embree_blocked(n);
      const Paired any = alternate(
          repeats,
          [&] {
            for (std::size_t i = 0; i < n; ++i) {
              gi::Ray ray = (*rays)[i];
              ray.t_max = segment;
              our_blocked[i] = gi::any_hit(world, ray);
            }
          },
          [&] {
            for (std::size_t i = 0; i < n; ++i) {
              gi::Ray ray = (*rays)[i];
              ray.t_max = segment;
              RTCRay r = embree_ray(ray);
              rtcOccluded1(embree.scene, &context, &r);
              embree_blocked[i] = r.tfar == -inf;  // Embree's mark of an occluded ray
            }
          });
      agree = 0;
      for (std::size_t i = 0; i < n; ++i) agree += our_blocked[i] == embree_blocked[i];
      queries.add_row({label, "any hit", static_cast<long long>(n), any.ours_ms, 1e-3 * n / any.ours_ms, any.embree_ms,
                       1e-3 * n / any.embree_ms, any.ratio, 100.0 * agree / n});
    }
    builds.print();
    std::cout << '\n';
    queries.print();
    std::cout << "\nours/Embree is the ratio of speeds (1 = as fast as Embree). Embree's rays are float, ours double.\n";
    builds.write_csv(out + "/builds.csv");
    queries.write_csv(out + "/queries.csv");
    return 0;
  });
}
