#include "gi/radiosity/display/display.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/display/element_values.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"

TEST(Display, AUniformRoomShowsItsRadianceEverywhere) {
  // Inside a closed box whose every element has B = 2: every pixel is L = 2 / pi, flat
  // or smooth (the vertex colours of a constant field are that constant).
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.25, 2});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const std::vector<gi::Color> B(mesh.elements.size(), gi::Color(2.0));
  const gi::Camera inside{{0.5, 0.5, 0.9}, {0.4, 0.3, 0.0}, {0, 1, 0}, 70};
  for (gi::Shading shading : {gi::Shading::Flat, gi::Shading::Smooth}) {
    gi::DisplaySettings settings;
    settings.width = 24;
    settings.height = 16;
    settings.shading = shading;
    const gi::Image image = gi::render_radiosity_picture(scene, mesh, B, inside, settings, 1, 0).shown;
    for (const gi::Pixel& p : image.pixels) ASSERT_NEAR(p.y, 2.0 / gi::pi, 1e-5);
    settings.white = 0.25;  // each sample clamped before the average
    for (const gi::Pixel& p : gi::render_radiosity_picture(scene, mesh, B, inside, settings, 1, 0).shown.pixels) ASSERT_NEAR(p.y, 0.25, 1e-6);
  }
}

TEST(Display, SmoothShadingInterpolatesAcrossAnElement) {
  // One wall of two elements, B = 0 and 1: flat shading shows two tiles, smooth shading
  // a ramp whose middle (the shared edge) is the mean.
  gi::RadiosityScene wall = gi::perpendicular_squares(1.0);
  wall.surfaces.erase(wall.surfaces.begin());  // keep the wall at z = 0, facing +z
  const gi::Mesh mesh = gi::make_mesh(wall.surfaces, {0.5, 1});
  ASSERT_EQ(mesh.elements.size(), 4u);
  std::vector<gi::Color> B;
  for (const gi::Element& e : mesh.elements) B.push_back(gi::Color(e.shape.centre.x < 0.5 ? 0.0 : 1.0));
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const gi::Camera front{{0.5, 0.5, 2.0}, {0.5, 0.5, 0.0}, {0, 1, 0}, 20};
  gi::DisplaySettings settings;
  settings.width = 40;
  settings.height = 40;
  settings.samples = 1;
  const gi::Image smooth = gi::render_radiosity_picture(scene, mesh, B, front, settings, 1, 0).shown;
  settings.shading = gi::Shading::Flat;
  const gi::Image flat = gi::render_radiosity_picture(scene, mesh, B, front, settings, 1, 0).shown;
  // Looking along -z with +y up, +x is to the right: B = 0 on the left half.
  EXPECT_NEAR(flat.at(5, 20).x, 0.0, 1e-6);
  EXPECT_NEAR(flat.at(34, 20).x, 1.0 / gi::pi, 1e-6);
  EXPECT_GT(smooth.at(21, 20).x, 0.2 / gi::pi);
  EXPECT_LT(smooth.at(21, 20).x, 0.8 / gi::pi);
  EXPECT_LT(smooth.at(5, 20).x, smooth.at(15, 20).x) << "a ramp, not tiles";
}

TEST(Display, TheLinearPictureIsNotClampedAndTheShownOneIs) {
  // A uniform room at L = 2 / pi, shown with white = 0.25: the PNG's picture is 0.25
  // everywhere, the radiance for the PFM stays 2 / pi, from the same eye rays.
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.25, 2});
  const gi::FormFactorScene scene(gi::element_shapes(mesh));
  const std::vector<gi::Color> B(mesh.elements.size(), gi::Color(2.0));
  const gi::Camera inside{{0.5, 0.5, 0.9}, {0.4, 0.3, 0.0}, {0, 1, 0}, 70};
  gi::DisplaySettings settings;
  settings.width = 20;
  settings.height = 12;
  settings.white = 0.25;
  const gi::RadiosityPicture picture = gi::render_radiosity_picture(scene, mesh, B, inside, settings, 1, 0);
  for (const gi::Pixel& p : picture.radiance.pixels) ASSERT_NEAR(p.y, 2.0 / gi::pi, 1e-5);
  for (const gi::Pixel& p : picture.shown.pixels) ASSERT_NEAR(p.y, 0.25, 1e-6);
  settings.white = 0;
  const gi::RadiosityPicture plain = gi::render_radiosity_picture(scene, mesh, B, inside, settings, 1, 0);
  EXPECT_EQ(plain.shown.pixels, plain.radiance.pixels);
  EXPECT_EQ(gi::describe_pixel_samples(settings), "2 x 2 jittered eye rays, box filter");
}

TEST(Display, ASolutionsGridHoldsEachPictureWhereItsRowAndColumnSay) {
  // Three uniform rooms, B = 1, 2, 4, two to a row: picture k is L = B / pi, shown
  // clamped to white = 1, at column k % 2 and row k / 2, with white gaps between.
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.5, 1});
  std::vector<std::vector<gi::Color>> solutions;
  for (double B : {1.0, 2.0, 4.0}) solutions.emplace_back(mesh.elements.size(), gi::Color(B));
  const gi::Camera inside{{0.5, 0.5, 0.9}, {0.4, 0.3, 0.0}, {0, 1, 0}, 70};
  const gi::Image grid = gi::solutions_grid(mesh, solutions, 2, inside, 8, 1, 0);
  ASSERT_EQ(grid.width, 2 * 8 + 4);
  ASSERT_EQ(grid.height, 2 * 8 + 4);
  const auto shown = [](double B) { return std::min(B / gi::pi, 1.0); };  // L = B / pi, white at 1
  EXPECT_NEAR(grid.at(4, 4).y, shown(1), 1e-5);
  EXPECT_NEAR(grid.at(12 + 4, 4).y, shown(2), 1e-5);
  EXPECT_NEAR(grid.at(4, 12 + 4).y, shown(4), 1e-6);
  EXPECT_EQ(grid.at(12 + 4, 12 + 4), gi::Pixel(1));  // no fourth picture: the gap's white
  EXPECT_EQ(grid.at(9, 4), gi::Pixel(1));             // between the columns
}

TEST(Display, ElementSizesColourEachElementByItsQuarterings) {
  // A unit box cut into 2 x 2 elements a wall: every element is a quarter of the largest
  // surface, log4(4) = 1. With top 0 (the mesh's largest) it shows red, the ramp's top;
  // with top 2 green, the ramp's middle. Only the outlines differ.
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.5, 1});
  const gi::Camera inside{{0.5, 0.5, 0.9}, {0.4, 0.3, 0.0}, {0, 1, 0}, 70};
  for (const auto& [top, colour] : {std::pair{0.0, gi::Pixel(1, 0, 0)}, std::pair{2.0, gi::Pixel(0, 1, 0)}}) {
    const gi::ElementSizes sizes = gi::render_element_sizes(mesh, inside, 40, 30, top, 1);
    EXPECT_DOUBLE_EQ(sizes.top, top == 0 ? 1.0 : top);
    int coloured = 0;
    for (const gi::Pixel& p : sizes.image.pixels) {
      if (p == colour) ++coloured;
      else EXPECT_LT(p.x + p.y + p.z, 1.0) << "every other pixel is an outline, darkened";
    }
    EXPECT_GT(coloured, 40 * 30 / 2);
  }
}

TEST(Display, ElementValuesPaintEachElementAndWhitenTheHighlightedOne) {
  // Values 10^-k on a log scale from 1e-4 to 1: the element of value 1 red, of 1e-4 (and
  // of 0, clamped to lo) black but for its outline; the highlighted element white.
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.5, 1});
  const gi::Camera inside{{0.5, 0.5, 0.9}, {0.4, 0.3, 0.0}, {0, 1, 0}, 70};
  std::vector<double> values(mesh.elements.size(), 1.0);
  const gi::Image red = gi::render_element_values(mesh, values, inside, 40, 30, 1e-4, 1, true, 1);
  const gi::Image marked = gi::render_element_values(mesh, values, inside, 40, 30, 1e-4, 1, true, 1, 0);
  int reds = 0, whites = 0;
  for (std::size_t k = 0; k < red.pixels.size(); ++k) {
    reds += red.pixels[k] == gi::Pixel(1, 0, 0);
    whites += marked.pixels[k] == gi::Pixel(1);
    const gi::Pixel& p = marked.pixels[k];
    if (p != red.pixels[k]) {
      EXPECT_TRUE(p.x == p.y && p.y == p.z) << "only the highlighted element turns (white, or grey on its outline)";
    }
  }
  EXPECT_GT(reds, 40 * 30 / 2);
  EXPECT_GT(whites, 0) << "element 0 is in view";
  std::fill(values.begin(), values.end(), 0.0);
  for (const gi::Pixel& p : gi::render_element_values(mesh, values, inside, 40, 30, 1e-4, 1, true, 1).pixels)
    EXPECT_EQ(p, gi::Pixel(0)) << "0 on a log scale is shown as lo, black";
  EXPECT_THROW(gi::render_element_values(mesh, values, inside, 40, 30, 0, 1, true, 1), std::invalid_argument);
  values.pop_back();
  EXPECT_THROW(gi::render_element_values(mesh, values, inside, 40, 30, 1e-4, 1, true, 1), std::invalid_argument);
}

TEST(Display, PlyHoldsEveryVertexAndFaceAndRefusesNan) {
  const gi::RadiosityScene box = gi::closed_box(1.0);
  const gi::Mesh mesh = gi::make_mesh(box.surfaces, {0.5, 1});
  std::vector<gi::Color> vertex_B(mesh.vertices.size(), gi::Color(gi::pi));  // L = 1: white
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "gi_display_test" / "box.ply";
  gi::write_ply(mesh, vertex_B, 1.0, file);
  std::ifstream in(file);
  std::string line;
  int lines = 0, white = 0, quads = 0;
  while (std::getline(in, line)) {
    ++lines;
    white += line.size() > 12 && line.compare(line.size() - 12, 12, " 255 255 255") == 0;
    quads += line.rfind("4 ", 0) == 0;
  }
  EXPECT_EQ(white, static_cast<int>(mesh.vertices.size()));
  EXPECT_EQ(quads, static_cast<int>(mesh.elements.size()));
  EXPECT_EQ(lines, 13 + white + quads) << "a header of 13 lines, then a line per vertex and per face";
  const std::uintmax_t size = std::filesystem::file_size(file);
  vertex_B[3].y = NAN;
  EXPECT_THROW(gi::write_ply(mesh, vertex_B, 1.0, file), std::runtime_error);
  EXPECT_EQ(std::filesystem::file_size(file), size) << "the earlier file is left whole";
}
