// Radiosity's view of scene files: the polygon check it shares with make_polygon,
// triangles cut into three quadrilaterals, emission from radiance, refusals, and the
// command line's changes (a new light keeps the form factors).
#include "gi/radiosity/mesh/radiosity_scene_file.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "../scene/scene_file_support.hpp"
#include "gi/core/rng.hpp"
#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/scene/cornell_box.hpp"

namespace {

using gi::vec3;

bool make_polygon_accepts(const std::array<vec3, 4>& c) {
  try {
    (void)gi::make_polygon(c);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

gi::RadiosityScene radiosity_of(const std::string& name, const std::string& text,
                                std::vector<std::string>* warnings = nullptr) {
  const auto folder = gi_test::scratch_folder(name);
  std::vector<std::string> ignored;
  return gi::radiosity_scene(gi::read_scene_file(gi_test::write_text(folder / (name + ".json"), text)),
                             warnings ? *warnings : ignored);
}

std::string radiosity_error(const std::string& text) {
  try {
    (void)radiosity_of("refused", text);
  } catch (const gi::SceneError& e) {
    const std::string what = e.what();
    return what.substr(what.find("refused.json"));
  }
  return "";
}

// A closed unit cube of 12 triangles, normals inwards, every face lit and grey.
const char* const cube_obj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 2 3\nf 1 3 4\nf 6 5 8\nf 6 8 7\nf 5 1 4\nf 5 4 8\nf 2 6 7\nf 2 7 3\nf 4 3 7\nf 4 7 8\nf 5 6 2\nf 5 2 1\n";

}  // namespace

// The scene reader checks polygons in the scene layer, below radiosity; its check
// must accept exactly what make_polygon accepts, so a file that reads also meshes.
// Random quadrilaterals around the flatness tolerance and around convexity.
TEST(RadiosityFromFile, ThePolygonCheckAgreesWithMakePolygon) {
  EXPECT_EQ(gi::flatness_tolerance, gi::planarity_tolerance) << "flat_polygon.hpp must follow polygon.hpp";
  gi::Rng rng(18);
  int accepted = 0, refused = 0;
  for (int i = 0; i < 20000; ++i) {
    // A unit square in z = 0, each corner moved in the plane by up to 0.45 (some
    // quadrilaterals turn concave) and off it by up to 0.04 (a corner 0.014 off is 1%
    // of the diagonal, the tolerance).
    std::array<vec3, 4> c = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)};
    for (vec3& p : c) p += vec3(0.9 * (rng.uniform() - 0.5), 0.9 * (rng.uniform() - 0.5), 0.08 * (rng.uniform() - 0.5));
    const bool ours = gi::polygon_problem({c, 4}).empty();
    EXPECT_EQ(ours, make_polygon_accepts(c)) << gi::polygon_problem({c, 4});
    (ours ? accepted : refused) += 1;
  }
  // Both answers are common, so the agreement is tested on each side.
  EXPECT_GT(accepted, 2000);
  EXPECT_GT(refused, 2000);
}

TEST(RadiosityFromFile, ATriangleIsThreeQuadrilateralsThatTileIt) {
  const gi::FlatPolygon t{{vec3(0, 0, 0), vec3(4, 0, 1), vec3(1, 3, 2)}, 3};
  std::array<std::array<vec3, 4>, 3> pieces;
  ASSERT_EQ(gi::flat_pieces(t, pieces), 3);
  const vec3 n = cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
  double area = 0;
  for (const auto& piece : pieces) {
    const gi::Polygon p = gi::make_polygon(piece);
    EXPECT_NEAR(dot(p.normal, gi::normalize(n)), 1.0, 1e-12) << "a piece faces another way than its triangle";
    area += p.area;
  }
  EXPECT_NEAR(area, 0.5 * gi::length(n), 1e-12 * gi::length(n));
  // A sliver too thin for its pieces is refused as a whole.
  EXPECT_EQ(gi::polygon_problem({{vec3(0, 0, 0), vec3(1, 0, 0), vec3(0.5, 1e-13, 0)}, 3}),
            "the corners are on one line, so it has no area");
}

TEST(RadiosityFromFile, SurfacesTakeRhoFromDiffuseAndEFromPiTimesEmission) {
  const gi::RadiosityScene s = radiosity_of("surfaces", "{" + gi_test::camera + R"(,
    "materials": [{"name": "lamp", "diffuse": 0.2, "emission": [1, 2, 3]}, {"name": "wall", "diffuse": [0.5, 0.6, 0.7]}],
    "quads": [{"corner": [0, 2, 0], "edge_u": [0, 0, 1], "edge_v": [1, 0, 0], "material": "lamp", "name": "lamp"}],
    "polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0, 0, -1]], "material": "wall"}]})");
  ASSERT_EQ(s.surfaces.size(), 4u);  // the quad, and three pieces of the triangle
  EXPECT_EQ(s.surfaces[0].name, "lamp");
  EXPECT_EQ(s.surfaces[0].corners[2], vec3(1, 2, 1));
  EXPECT_EQ(s.surfaces[0].emission, gi::pi * vec3(1, 2, 3));
  EXPECT_EQ(s.surfaces[0].reflectance, vec3(0.2));
  for (int i = 1; i < 4; ++i) {
    EXPECT_EQ(s.surfaces[i].name, "polygons[0]");
    EXPECT_EQ(s.surfaces[i].reflectance, vec3(0.5, 0.6, 0.7));
    EXPECT_EQ(s.surfaces[i].emission, vec3(0));
  }
}

TEST(RadiosityFromFile, WhatRadiosityCannotMeshIsRefusedWhereItStands) {
  const std::string top = "{" + gi_test::camera + ", " + R"("materials": [{"name": "lamp", "emission": 1}])";
  EXPECT_EQ(radiosity_error(top + R"(, "spheres": [{"center": [0, 1, 0], "radius": 1, "material": "lamp"}]})"),
            "refused.json:1:114: spheres[0]: radiosity meshes flat polygons only (quads, polygons and meshes); this "
            "scene is for the ray-tracing lessons 01-04");
  EXPECT_EQ(radiosity_error(top + R"(, "planes": [{"point": [0, 0, 0], "normal": [0, 1, 0], "material": "lamp"}]})"),
            "refused.json:1:113: planes[0]: radiosity meshes flat polygons only (quads, polygons and meshes); this "
            "scene is for the ray-tracing lessons 01-04");
  EXPECT_EQ(radiosity_error("{" + gi_test::camera + ", " + gi_test::matte +
                            R"(, "polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0, 0, -1]], "material": "white"}]})"),
            "refused.json:1:1: no quad, polygon or mesh face emits light, and radiosity is lit by those alone (point "
            "and quad lights are the ray tracer's): give one a material with an \"emission\"");
  std::vector<std::string> warnings;
  (void)radiosity_of("bright", top.substr(0, top.size() - 2) + R"(, "diffuse": 1.2}],
      "polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0, 0, -1]], "material": "lamp"}]})", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("material 'lamp' reflects more than it receives (diffuse above 1)"), std::string::npos)
      << warnings[0];
}

// A closed cube of OBJ triangles (each cut into three quadrilaterals), every face
// with E = 1 and rho = 0.5: in a closed room, B = E / (1 - rho) = 2 everywhere, the
// series E (1 + rho + rho^2 + ...), whatever the mesh -- if the form factors of every
// element sum to 1. Analytic form factors (no occlusion in a convex room): the rows
// sum to 1 within 1e-3, which bounds B's error by rho / (1 - rho)^2 x 1e-3 = 2e-3.
TEST(RadiosityFromFile, AClosedCubeOfTrianglesIsAFurnace) {
  const auto folder = gi_test::scratch_folder("cube");
  gi_test::write_text(folder / "cube.obj", cube_obj);
  gi_test::write_text(folder / "cube.json", "{" + gi_test::camera + R"(,
    "materials": [{"name": "glow", "diffuse": 0.5, "emission": 0.3183098861837907}],
    "meshes": [{"file": "cube.obj", "material": "glow"}]})");
  std::vector<std::string> warnings;
  const gi::RadiosityScene scene = gi::radiosity_scene(gi::read_scene_file(folder / "cube.json"), warnings);
  ASSERT_EQ(scene.surfaces.size(), 36u);
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 150, 1), 1});
  gi::FormFactorSettings analytic;
  analytic.method = gi::FormFactorMethod::Analytic;
  analytic.quadrature_order = 6;
  const gi::RadiositySystem system =
      gi::make_system(mesh, gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), analytic, 2));
  for (int i = 0; i < system.size(); ++i) {
    double row = 0;
    for (int j = 0; j < system.size(); ++j) row += system.F(i, j);
    ASSERT_NEAR(row, 1.0, 1e-3) << "row " << i << " of F";
  }
  for (const gi::Color& b : gi::solve_direct(system).B) EXPECT_NEAR(b.x, 2.0, 2e-3);
}

TEST(RadiosityFromFile, ALightScaleScalesBAndKeepsTheFormFactors) {
  gi::RadiosityScene scene = gi::cornell_box();
  const gi::Mesh mesh = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 60, 1), 1});
  gi::FormFactorSettings hemicube;
  hemicube.hemicube_resolution = 20;
  const gi::FormFactorMatrix F = gi::form_factor_matrix(gi::FormFactorScene(gi::element_shapes(mesh)), hemicube, 2);
  const std::vector<gi::Color> B = gi::solve_direct(gi::make_system(mesh, F)).B;
  gi::scale_lights(scene, {{"light", 2}});
  // The same mesh, the same F: only E doubles, and (I - RF) B = E is linear, so B
  // doubles -- exactly, as doubling is exact in floating point.
  const gi::Mesh brighter = gi::make_mesh(scene.surfaces, {gi::patch_size_for(scene.surfaces, 60, 1), 1});
  const std::vector<gi::Color> B2 = gi::solve_direct(gi::make_system(brighter, F)).B;
  for (std::size_t i = 0; i < B.size(); ++i) EXPECT_EQ(B2[i], 2.0 * B[i]) << "element " << i;
  try {
    gi::scale_lights(scene, {{"lihgt", 2}});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "light scale: no light is named 'lihgt' (did you mean 'light'?); the lights of cornell: light");
  }
  EXPECT_THROW(gi::scale_lights(scene, {{"light", 0}}), std::invalid_argument);  // nothing left to see
}

TEST(RadiosityFromFile, ChoicesNameABuiltInSceneOrAFileAndChangesApply) {
  std::vector<std::string> warnings;
  gi::SceneChanges changes;
  changes.camera = gi::CameraChange{vec3(278, 2000, 280), vec3(278, 0, 280), 30.0};  // from straight above
  const gi::RadiosityScene top = gi::load_radiosity_scene("cornell", changes, 100, warnings);
  EXPECT_EQ(top.camera.eye, vec3(278, 2000, 280));
  EXPECT_EQ(top.camera.vertical_fov, 30.0);
  EXPECT_EQ(top.camera.up, vec3(0, 0, 1));  // up would run along the view
  const std::pair<std::string, std::string> refusals[] = {
      {"whitted", "'whitted' is a scene for the ray tracer, not radiosity; radiosity scenes: cornell, parallel, "
                  "perpendicular, closed-box, open-box, occluded; or a scene file ending in .json"},
      {"cornel", "unknown scene 'cornel' (did you mean 'cornell'?); radiosity scenes: cornell, parallel, "
                 "perpendicular, closed-box, open-box, occluded; or a scene file ending in .json"},
  };
  for (const auto& [choice, message] : refusals) {
    try {
      (void)gi::load_radiosity_scene(choice, {}, 100, warnings);
      FAIL() << choice;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
  const std::string cornell = std::string(GI_SOURCE_DIR) + "/lessons/scenes/cornell.json";
  try {
    (void)gi::load_radiosity_scene(cornell, {}, 10, warnings);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    // Its 19 polygons are counted as they are read: the reading stops at the 11th.
    EXPECT_EQ(std::string(e.what()), cornell + ":65:18: polygons[10].corners: more than 10 polygons (quads, boxes' "
                                               "faces, polygons and mesh faces together), the most this lesson takes");
  }
  // Four triangles pass the reading's count, and make twelve surfaces.
  const auto triangles = gi_test::write_text(gi_test::scratch_folder("triangles") / "triangles.json",
                                             "{" + gi_test::camera + R"(,
    "materials": [{"name": "lamp", "emission": 1}],
    "polygons": [{"corners": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "lamp"},
                 {"corners": [[0, 0, 1], [1, 0, 1], [0, 1, 1]], "material": "lamp"},
                 {"corners": [[0, 0, 2], [1, 0, 2], [0, 1, 2]], "material": "lamp"},
                 {"corners": [[0, 0, 3], [1, 0, 3], [0, 1, 3]], "material": "lamp"}]})");
  try {
    (void)gi::load_radiosity_scene(triangles.string(), {}, 10, warnings);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), triangles.string() + ": 12 surfaces (a triangle makes three), more than the 10 "
                                                          "patches this lesson solves for in seconds");
  }
}

TEST(RadiosityFromFile, SurfacesThatOverlapInAPlaneAreRefusedBeforeAnyWork) {
  const auto folder = gi_test::scratch_folder("overlap");
  const auto file = gi_test::write_text(folder / "overlap.json", "{" + gi_test::camera + R"(,
    "materials": [{"name": "lamp", "emission": 1}],
    "quads": [{"corner": [0, 0, 0], "edge_u": [0, 0, 1], "edge_v": [1, 0, 0], "material": "lamp", "name": "a"},
              {"corner": [0.5, 0, 0.5], "edge_u": [0, 0, 1], "edge_v": [1, 0, 0], "material": "lamp", "name": "b"}]})");
  std::vector<std::string> warnings;
  try {
    (void)gi::load_radiosity_scene(file.string(), {}, 100, warnings);
    FAIL() << "no exception";
  } catch (const gi::SceneError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": surfaces 'a' and 'b' lie in one plane and overlap; remove "
                                                     "one, or move it off the other");
  }
}

// The Cornell box's palette choices (cornell_box.hpp) are scene files too, so that any
// lesson can switch them with --scene: each file holds the built-in box's surfaces with
// that choice's reflectances and exitances.
TEST(RadiosityFromFile, TheCornellBoxVariantsAreTheBuiltInPaletteChoices) {
  gi::CornellPaletteChoice mcguire, white_light, light_reflects;
  mcguire.reflectances = gi::CornellReflectances::McGuire;
  white_light.light = gi::CornellLight::WhiteUnitExitance;
  light_reflects.light_reflects = true;
  const std::pair<const char*, gi::CornellPaletteChoice> variants[] = {
      {"cornell", {}}, {"cornell_mcguire", mcguire}, {"cornell_white_light", white_light},
      {"cornell_light_reflects", light_reflects}};
  std::vector<std::string> warnings;
  for (const auto& [name, choice] : variants) {
    const std::string file = std::string(GI_SOURCE_DIR) + "/lessons/scenes/" + name + ".json";
    const gi::RadiosityScene scene = gi::load_radiosity_scene(file, {}, 100, warnings);
    const gi::CornellBox box = gi::cornell_box_data(gi::CornellContents::Blocks, false, gi::cornell_palette(choice));
    ASSERT_EQ(scene.surfaces.size(), box.surfaces.size()) << name;
    for (std::size_t i = 0; i < box.surfaces.size(); ++i) {
      const gi::Surface& s = scene.surfaces[i];
      EXPECT_EQ(s.name, box.surfaces[i].name) << name;
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(s.reflectance[k], box.surfaces[i].reflectance[k]) << name << ", " << s.name;
        // The file holds the radiance L, the box the exitance pi L: one rounding apart.
        EXPECT_NEAR(s.emission[k], box.surfaces[i].exitance[k], 1e-14 * box.surfaces[i].exitance[k])
            << name << ", " << s.name;
      }
    }
  }
}
