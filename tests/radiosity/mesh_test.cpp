#include "gi/radiosity/mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"

using gi::vec3;

TEST(Polygon, AreaNormalCentreOfARectangleAndATrapezoid) {
  const gi::Polygon r = gi::make_polygon({vec3(0, 0, 0), vec3(2, 0, 0), vec3(2, 1, 0), vec3(0, 1, 0)});
  EXPECT_DOUBLE_EQ(r.area, 2.0);
  EXPECT_EQ(r.normal, vec3(0, 0, 1));
  EXPECT_EQ(r.centre, vec3(1, 0.5, 0));
  // Trapezoid with parallel sides 4 (y = 0) and 2 (y = 1): area 3, centroid y = (4 + 2*2) / (3 (4 + 2)) = 4/9.
  const gi::Polygon t = gi::make_polygon({vec3(0, 0, 0), vec3(4, 0, 0), vec3(3, 1, 0), vec3(1, 1, 0)});
  EXPECT_DOUBLE_EQ(t.area, 3.0);
  EXPECT_NEAR(t.centre.y, 4.0 / 9.0, 1e-12);
  EXPECT_NEAR(t.centre.x, 2.0, 1e-12);
}

TEST(Polygon, BadShapesAreRejected) {
  EXPECT_THROW(gi::make_polygon({vec3(0), vec3(1, 0, 0), vec3(2, 0, 0), vec3(3, 0, 0)}), std::invalid_argument);
  EXPECT_THROW(gi::make_polygon({vec3(0), vec3(1, 0, 0), vec3(1, 1, 0.5), vec3(0, 1, 0)}), std::invalid_argument);
  EXPECT_THROW(gi::make_polygon({vec3(0), vec3(1, 0, 0), vec3(0.2, 0.2, 0), vec3(0, 1, 0)}), std::invalid_argument);
  EXPECT_THROW(gi::make_polygon({vec3(NAN), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}), std::invalid_argument);
}

TEST(CornellBox, WallsFaceInAndBlocksFaceOut) {
  const gi::RadiosityScene scene = gi::cornell_box();
  ASSERT_EQ(scene.surfaces.size(), 19u);
  const vec3 room_centre(278, 274, 280), short_centre(186, 82, 169), tall_centre(368, 165, 351);
  double emitting = 0;
  for (const gi::Surface& s : scene.surfaces) {
    const gi::Polygon p = gi::make_polygon(s.corners);
    const bool block = s.name.find("block") != std::string::npos;
    const vec3 inside = s.name.find("short") != std::string::npos ? short_centre : tall_centre;
    if (block)
      EXPECT_GT(gi::dot(p.normal, p.centre - inside), 0) << s.name << " must face out of its block";
    else
      EXPECT_GT(gi::dot(p.normal, room_centre - p.centre), 0) << s.name << " must face into the room";
    if (gi::max_component(s.emission) > 0) emitting += p.area;
  }
  EXPECT_NEAR(emitting, 130.0 * 105.0, 1e-9);
}

TEST(CornellBox, RedWallIsOnTheLeftOfTheImage) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const gi::CameraFrame frame = gi::camera_frame(scene.camera, 100, 100);
  EXPECT_LT(frame.right.x, 0) << "image right is -x, so the red wall at x = 556 is on the left";
}

TEST(Mesh, PatchesAndElementsTileEverySurface) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {100.0, 3});
  std::vector<double> area(mesh.surfaces.size(), 0.0), patch_area(mesh.surfaces.size(), 0.0);
  for (const gi::Element& e : mesh.elements) {
    area[e.surface] += e.shape.area;
    EXPECT_EQ(mesh.patches[e.patch].surface, e.surface);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.vertices[e.vertices[k]], e.shape.corners[k]);
  }
  for (const gi::Patch& p : mesh.patches) {
    patch_area[p.surface] += p.shape.area;
    EXPECT_EQ(p.element_count, 9);
    for (int i = p.first_element; i < p.first_element + p.element_count; ++i)
      EXPECT_EQ(&mesh.patches[mesh.elements[i].patch], &p);
  }
  for (std::size_t s = 0; s < mesh.surfaces.size(); ++s) {
    const double exact = gi::make_polygon(mesh.surfaces[s].corners).area;
    // Exact for planar quads; the red wall is twisted by 3 mm, and its pieces' mean
    // planes add up to 3e-6 more than the whole's.
    EXPECT_NEAR(area[s], exact, 1e-5 * exact) << mesh.surfaces[s].name;
    EXPECT_NEAR(patch_area[s], exact, 1e-5 * exact) << mesh.surfaces[s].name;
  }
  // The floor (553 x 559) with patches of at most 100: 6 x 6 patches, 18 x 18 elements,
  // 19 x 19 shared vertices.
  int floor_elements = 0;
  for (const gi::Element& e : mesh.elements) floor_elements += e.surface == 0;
  EXPECT_EQ(floor_elements, 18 * 18);
}

TEST(Mesh, VerticesAreSharedWithinASurfaceOnly) {
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 2});
  // 6 faces, 4 x 4 elements each, 5 x 5 vertices each: shared inside, not across faces.
  EXPECT_EQ(mesh.elements.size(), 6u * 16);
  EXPECT_EQ(mesh.vertices.size(), 6u * 25);
}

TEST(Mesh, ElementCountTargetAndBadSettings) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const double size = gi::patch_size_for(scene.surfaces, 10000, 2);
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {size, 2});
  EXPECT_GT(mesh.elements.size(), 8000u);
  EXPECT_LT(mesh.elements.size(), 14000u);
  EXPECT_THROW(gi::make_mesh(scene.surfaces, {0.0, 1}), std::invalid_argument);
  EXPECT_THROW(gi::make_mesh(scene.surfaces, {10.0, 0}), std::invalid_argument);
  EXPECT_THROW(gi::make_mesh(scene.surfaces, {0.01, 1}), std::invalid_argument);  // far too many elements
  std::vector<gi::Surface> bad = scene.surfaces;
  bad[0].reflectance = gi::Color(-0.1);
  EXPECT_THROW(gi::make_mesh(bad, {100.0, 1}), std::invalid_argument);
  EXPECT_THROW(gi::make_radiosity_scene("cornel"), std::invalid_argument);
  for (const std::string& name : gi::radiosity_scene_names())
    EXPECT_EQ(gi::make_radiosity_scene(name).name, name);
}

// element_count is make_mesh's own arithmetic: the count a lesson checks before any
// work is the count it gets.
TEST(Mesh, ElementCountPredictsTheMesh) {
  const gi::RadiosityScene scene = gi::cornell_box();
  for (const int elements : {20, 400, 1000, 5000})
    for (const int m : {1, 3}) {
      const gi::MeshSettings settings{gi::patch_size_for(scene.surfaces, elements, m), m};
      EXPECT_EQ(gi::element_count(scene.surfaces, settings), double(gi::make_mesh(scene.surfaces, settings).elements.size()))
          << elements << " elements, " << m << " a side";
    }
}

// "About n elements" rounds every surface's patches up: 20 707 for the Cornell box at
// 20 000, past the stored matrix's limit. patch_size_at_most reaches a limit and never
// passes it, from both ends of the lessons' ranges, and leaves every mesh that was
// already within it as it was (the lessons' pictures keep their bytes).
TEST(Mesh, AMeshReachesItsLimitAndNeverPassesIt) {
  const gi::RadiosityScene scene = gi::cornell_box();
  const int most = 20000;
  EXPECT_GT(gi::element_count(scene.surfaces, {gi::patch_size_for(scene.surfaces, most, 1), 1}), most);
  for (int elements = 20; elements <= most; elements += elements < 19000 ? 997 : 37) {
    const double about = gi::patch_size_for(scene.surfaces, elements, 1);
    const double size = gi::patch_size_at_most(scene.surfaces, elements, 1, most);
    const double n = gi::element_count(scene.surfaces, {size, 1});
    EXPECT_LE(n, most) << elements;
    if (gi::element_count(scene.surfaces, {about, 1}) <= most) EXPECT_EQ(size, about) << elements;
    else EXPECT_GT(n, 0.97 * most) << elements << ": the finest mesh within the limit";
  }
  EXPECT_EQ(gi::make_mesh(scene.surfaces, {gi::patch_size_at_most(scene.surfaces, most, 1, most), 1}).elements.size(),
            gi::element_count(scene.surfaces, {gi::patch_size_at_most(scene.surfaces, most, 1, most), 1}));
  EXPECT_THROW((void)gi::patch_size_at_most(scene.surfaces, 100, 4, 100), std::invalid_argument)
      << "fewer than one patch of 4 x 4 elements per surface";
}
