// Graded tests of exercise 8.1: vertex colours from element radiosities. One point per test.
#include <gtest/gtest.h>

#include <string>

#include "gi/radiosity/mesh/radiosity_scenes.hpp"
#include "gi/radiosity/display/vertex_colours.hpp"
#include "support/print.hpp"

using gi::Color;
using gi::vec3;

namespace {
// Two elements sharing the edge x = 1: [0,1] x [0,1] (area 1) and [1,4] x [0,1] (area 3).
gi::Mesh two_elements() {
  gi::Mesh mesh;
  mesh.surfaces = {gi::Surface{"strip", {vec3(0, 0, 0), vec3(4, 0, 0), vec3(4, 1, 0), vec3(0, 1, 0)}, Color(0.5)}};
  mesh.vertices = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(4, 0, 0), vec3(0, 1, 0), vec3(1, 1, 0), vec3(4, 1, 0)};
  const auto element = [&](std::array<int, 4> v) {
    return gi::Element{gi::make_polygon({mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]],
                                         mesh.vertices[v[3]]}),
                       0, 0, v};
  };
  mesh.elements = {element({0, 1, 4, 3}), element({1, 2, 5, 4})};
  return mesh;
}
}  // namespace

TEST(Ex8_1_VertexColours, OneValuePerVertex) {
  const gi::Mesh mesh = two_elements();
  EXPECT_EQ(gi::vertex_radiosity(mesh, {Color(1), Color(2)}).size(), mesh.vertices.size())
      << "return one radiosity per mesh vertex, indexed like mesh.vertices";
}

TEST(Ex8_1_VertexColours, UnsharedVerticesKeepTheirElementsValue) {
  const std::vector<Color> v = gi::vertex_radiosity(two_elements(), {Color(1), Color(2)});
  ASSERT_EQ(v.size(), 6u) << "return one radiosity per mesh vertex, indexed like mesh.vertices";
  EXPECT_EQ(v[0], Color(1)) << "vertex 0 belongs to element 0 only: it takes that element's radiosity";
  EXPECT_EQ(v[2], Color(2)) << "a vertex of one element only takes that element's radiosity";
}

TEST(Ex8_1_VertexColours, SharedVerticesAreAreaWeighted) {
  const std::vector<Color> v = gi::vertex_radiosity(two_elements(), {Color(1), Color(2)});
  ASSERT_EQ(v.size(), 6u) << "return one radiosity per mesh vertex, indexed like mesh.vertices";
  EXPECT_NEAR(v[1].x, (1 * 1.0 + 3 * 2.0) / 4, 1e-12)
      << "weight each element by its area: (A_1 B_1 + A_2 B_2) / (A_1 + A_2), not the plain mean 1.5";
  EXPECT_NEAR(v[4].x, 1.75, 1e-12) << "vertex 4 is shared like vertex 1: (1 * 1 + 3 * 2) / 4";
}

TEST(Ex8_1_VertexColours, ChannelsAreAveragedSeparately) {
  const std::vector<Color> v = gi::vertex_radiosity(two_elements(), {Color(1, 0, 0), Color(0, 0, 4)});
  ASSERT_EQ(v.size(), 6u) << "return one radiosity per mesh vertex, indexed like mesh.vertices";
  const Color want((1 * 1.0) / 4, 0.0, (3 * 4.0) / 4);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(v[1][c], want[c], 1e-12) << "channel " << c << ": each colour channel is averaged on its own";
}

TEST(Ex8_1_VertexColours, AVertexOfNoElementStaysBlack) {
  gi::Mesh mesh = two_elements();
  mesh.vertices.push_back(vec3(9, 9, 0));  // listed, but no element uses it
  const std::vector<Color> v = gi::vertex_radiosity(mesh, {Color(1), Color(2)});
  ASSERT_EQ(v.size(), 7u) << "return one radiosity per mesh vertex, indexed like mesh.vertices";
  EXPECT_EQ(v[6], Color(0)) << "no element touches vertex 6: its weights sum to 0, so leave it at 0 instead of "
                               "dividing 0 by 0 (NaN)";
}

TEST(Ex8_1_VertexColours, AConstantFieldStaysConstant) {
  const gi::Mesh mesh = gi::make_mesh(gi::cornell_box().surfaces, {150.0, 2});
  const std::vector<Color> v = gi::vertex_radiosity(mesh, std::vector<Color>(mesh.elements.size(), Color(0.7)));
  ASSERT_EQ(v.size(), mesh.vertices.size()) << "return one radiosity per mesh vertex, indexed like mesh.vertices";
  for (std::size_t k = 0; k < v.size(); ++k) {
    // An element that lists vertex k, if any.
    int owner = -1;
    for (std::size_t e = 0; e < mesh.elements.size() && owner < 0; ++e)
      for (int i : mesh.elements[e].vertices)
        if (i == static_cast<int>(k)) owner = static_cast<int>(e);
    ASSERT_NEAR(v[k].y, 0.7, 1e-12)
        << "every element has B = 0.7, so every vertex must be 0.7; vertex " << k << " got " << v[k].y << ". "
        << (v[k].y == 0 && owner >= 0
                ? "Element " + std::to_string(owner) + " lists it as a corner, yet nothing reached it: add each "
                      "element into the vertices it lists (element.vertices), not into another vertex found at "
                      "the same position"
                : std::string("Divide by the summed weights"));
  }
}

TEST(Ex8_1_VertexColours, SurfacesDoNotBleedIntoEachOther) {
  // Each face of the box its own radiosity: its vertices -- shared only within the face
  // -- must all have the face's value, even on the box's edges.
  const gi::Mesh mesh = gi::make_mesh(gi::closed_box(1.0).surfaces, {0.5, 1});
  std::vector<Color> B;
  for (const gi::Element& e : mesh.elements) B.push_back(Color(e.surface + 1.0));
  const std::vector<Color> v = gi::vertex_radiosity(mesh, B);
  for (const gi::Element& e : mesh.elements)
    for (int k : e.vertices)
      ASSERT_EQ(v[k], Color(e.surface + 1.0)) << "use the mesh's vertex indices (shared within a surface only); "
                                                  "merging vertices by position blurs the corners between walls";
}
