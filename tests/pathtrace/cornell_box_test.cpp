// Radiosity and the path tracer read the same Cornell box: the data moved from
// radiosity to the scene floor with every number unchanged, and the path tracer's
// triangles are the quadrilaterals radiosity meshes.
#include "gi/scene/cornell_box.hpp"

#include <gtest/gtest.h>

#include "gi/pathtrace/path_scenes.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"

using gi::vec3;

namespace {

// The published geometry as radiosity had it before the move (lib/gi/radiosity/mesh/cornell_box.cpp
// at c8cac31), typed out again: corners of each surface. The colours are the palette's
// (tests/scene/cornell_palette_test.cpp checks them against the published spectra).
struct Published {
  const char* name;
  std::array<vec3, 4> corners;
  gi::Color rho, e;
};
const gi::CornellPalette palette = gi::cornell_palette();
const gi::Color white = palette.white, red = palette.red, green = palette.green, none(0.0);
const double y = 548.8;
const Published published[] = {
    {"floor", {{{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}}}, white, none},
    {"back wall", {{{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}}, white, none},
    {"red wall", {{{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}}}, red, none},
    {"green wall", {{{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}}}, green, none},
    {"ceiling front", {{{556, y, 0}, {556, y, 227}, {0, y, 227}, {0, y, 0}}}, white, none},
    {"ceiling back", {{{556, y, 332}, {556, y, 559.2}, {0, y, 559.2}, {0, y, 332}}}, white, none},
    {"ceiling red side", {{{556, y, 227}, {556, y, 332}, {343, y, 332}, {343, y, 227}}}, white, none},
    {"ceiling green side", {{{213, y, 227}, {213, y, 332}, {0, y, 332}, {0, y, 227}}}, white, none},
    {"light",
     {{{343, y, 227}, {343, y, 332}, {213, y, 332}, {213, y, 227}}},
     palette.light_reflectance,
     palette.light_exitance},
    {"short block top", {{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}, white, none},
    {"short block 1", {{{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}}, white, none},
    {"short block 2", {{{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}}, white, none},
    {"short block 3", {{{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}}, white, none},
    {"short block 4", {{{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}}, white, none},
    {"tall block top", {{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}, white, none},
    {"tall block 1", {{{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}}, white, none},
    {"tall block 2", {{{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}}, white, none},
    {"tall block 3", {{{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}}, white, none},
    {"tall block 4", {{{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}}, white, none},
};

}  // namespace

TEST(CornellBox, RadiosityGetsThePublishedSurfacesBitForBit) {
  for (bool closed : {false, true}) {
    const gi::RadiosityScene scene = gi::cornell_box(closed);
    ASSERT_EQ(scene.surfaces.size(), std::size(published) + (closed ? 1 : 0));
    for (std::size_t i = 0; i < std::size(published); ++i) {
      const gi::Surface& s = scene.surfaces[i];
      EXPECT_EQ(s.name, published[i].name);
      for (int k = 0; k < 4; ++k) EXPECT_EQ(s.corners[k], published[i].corners[k]) << s.name << " corner " << k;
      EXPECT_EQ(s.reflectance, published[i].rho) << s.name;
      EXPECT_EQ(s.emission, published[i].e) << s.name;
    }
    if (closed) {
      EXPECT_EQ(scene.surfaces.back().name, "front (black)");
      EXPECT_EQ(scene.surfaces.back().reflectance, gi::Color(0.0));
    }
    EXPECT_EQ(scene.camera.eye, vec3(278, 273, -800));
    EXPECT_EQ(scene.camera.vertical_fov, 2 * std::atan(12.5 / 35) * 180 / gi::pi);
  }
}

TEST(CornellBox, ThePathTracerRendersTheSameQuadrilaterals) {
  // Each surface is the two triangles radiosity casts its rays into, with rho as the
  // Lambertian reflectance and the light's radiance L = E / pi.
  const gi::RadiosityScene radiosity = gi::cornell_box();
  const gi::Scene scene = gi::make_path_scene_by_name("cornell");
  ASSERT_EQ(scene.triangles.size(), 2 * radiosity.surfaces.size());
  EXPECT_TRUE(scene.spheres.empty() && scene.quads.empty() && scene.planes.empty() && scene.lights.empty());
  for (std::size_t i = 0; i < radiosity.surfaces.size(); ++i) {
    const gi::Surface& s = radiosity.surfaces[i];
    const gi::Triangle &t1 = scene.triangles[2 * i], &t2 = scene.triangles[2 * i + 1];
    EXPECT_TRUE(t1.a == s.corners[0] && t1.b == s.corners[1] && t1.c == s.corners[2]) << s.name;
    EXPECT_TRUE(t2.a == s.corners[0] && t2.b == s.corners[2] && t2.c == s.corners[3]) << s.name;
    const gi::Material& m = scene.materials[t1.material];
    EXPECT_EQ(t2.material, t1.material);
    EXPECT_EQ(m.diffuse, s.reflectance) << s.name;
    EXPECT_EQ(m.emission, s.emission / gi::pi) << s.name;
    EXPECT_EQ(m.mirror, gi::Color(0.0));
    EXPECT_FALSE(m.is_dielectric());
  }
  EXPECT_EQ(scene.background, gi::Color(0.0));
  EXPECT_EQ(scene.camera.eye, radiosity.camera.eye);
  EXPECT_EQ(scene.camera.look_at, radiosity.camera.look_at);
  EXPECT_EQ(scene.camera.vertical_fov, radiosity.camera.vertical_fov);
}

TEST(CornellBox, TheRedWallIsTheTwistedOne) {
  // The reason the scene is triangles: one wall's corners are not in one plane, and the
  // renderers must agree on the surface between them.
  for (const gi::QuadSurface& s : gi::cornell_box_data().surfaces) {
    const auto& c = s.corners;
    const double twist = std::abs(gi::dot(c[3] - c[0], gi::normalize(gi::cross(c[1] - c[0], c[2] - c[0]))));
    if (s.name == "red wall")
      EXPECT_GT(twist, 1.0) << "mm off the plane of the other three corners";
    else
      EXPECT_LT(twist, 1e-9) << s.name;
  }
}

TEST(CornellBox, TheSpheresVariantSwapsTheBlocksForAMirrorAndAGlassBall) {
  const gi::CornellBox box = gi::cornell_box_data(gi::CornellContents::Spheres);
  for (const gi::QuadSurface& s : box.surfaces) EXPECT_EQ(s.name.find("block"), std::string::npos) << s.name;
  ASSERT_EQ(box.spheres.size(), 2u);
  const gi::Scene scene = gi::cornell_box_scene(box);
  ASSERT_EQ(scene.spheres.size(), 2u);
  const gi::Material &mirror = scene.materials[scene.spheres[0].material],
                     &glass = scene.materials[scene.spheres[1].material];
  EXPECT_GT(gi::max_component(mirror.mirror), 0.9);
  EXPECT_TRUE(glass.is_dielectric());
  EXPECT_EQ(glass.ior, 1.5);
  for (const gi::CornellSphere& s : box.spheres) {
    EXPECT_NEAR(s.centre.y, s.radius, 1e-12) << s.name << " rests on the floor";
    EXPECT_GT(s.centre.x - s.radius, 0) << s.name;
    EXPECT_LT(s.centre.x + s.radius, 549.6) << s.name;
  }
}
