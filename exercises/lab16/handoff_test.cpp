// Graded tests of exercise 16.1: the hand-off from the radiosity pass to the eye pass.
// One point per test.
#include <gtest/gtest.h>

#include "gi/radiosity/display/vertex_colours.hpp"
#include "room.hpp"
#include "support/print.hpp"

using gi::Color;
using gi::vec3;
using lab16::constant;

namespace {

// B = 5, E = 1 on the floor (a light), 0 elsewhere; D = 1.5 on every element.
gi::RadiosityHandoff lit_room() {
  const gi::Mesh mesh = lab16::room_mesh();
  return lab16::room_handoff(
      mesh, [](int, const vec3&) { return constant(5); }, [](int, const vec3&) { return constant(1.5); },
      [](int surface, const vec3&) { return constant(surface == 0 ? 1 : 0); });
}

}  // namespace

TEST(Ex16_1_Handoff, EyeReadsBMinusEMinusD) {
  const gi::RadiosityHandoff h = lit_room();
  const int wall = h.mesh.patches[2 * 16].first_element;  // an element of surface 2, a wall
  const Color got = gi::indirect_radiosity_at(h, wall, h.mesh.elements[wall].shape.centre);
  EXPECT_NEAR(got.x, 3.5, 1e-9) << "on a wall (E = 0) the eye pass must read B - D = 5 - 1.5: its shadow rays "
                                   "already give the direct light D; reading B counts it twice";
}

TEST(Ex16_1_Handoff, EyeReadsNeitherEmissionNorDirectOnALight) {
  const gi::RadiosityHandoff h = lit_room();
  const int floor = h.mesh.patches[0].first_element;
  const Color got = gi::indirect_radiosity_at(h, floor, h.mesh.elements[floor].shape.centre);
  EXPECT_NEAR(got.x, 2.5, 1e-9) << "on the light (E = 1) the eye pass reads B - E - D = 5 - 1 - 1.5: the eye "
                                   "pass shows E / pi itself, and D by its shadow rays";
}

TEST(Ex16_1_Handoff, GatherReadsBMinusE) {
  const gi::RadiosityHandoff h = lit_room();
  const int floor = h.mesh.patches[0].first_element, wall = h.mesh.patches[2 * 16].first_element;
  EXPECT_NEAR(gi::reflected_radiosity_at(h, floor, h.mesh.elements[floor].shape.centre).x, 4.0, 1e-9)
      << "a gather ray that lands on the light reads B - E = 5 - 1: its emission is the shadow rays' to count";
  EXPECT_NEAR(gi::reflected_radiosity_at(h, wall, h.mesh.elements[wall].shape.centre).x, 5.0, 1e-9)
      << "a gather ray that lands on a wall reads all it reflects, B - E = 5, its direct light D included: that "
         "light has bounced once before it reaches the gathering point";
}

TEST(Ex16_1_Handoff, EveryChannelAndEveryElement) {
  const gi::Mesh mesh = lab16::room_mesh();
  const auto B = [](int s, const vec3& c) { return Color(2 + s + c.x, 3 + c.y, 4 + c.z); };
  const auto D = [](int s, const vec3& c) { return Color(0.5 + 0.1 * s, c.x, 0.2); };
  const auto E = [](int s, const vec3&) { return s == 1 ? Color(0.7, 0.3, 0.1) : Color(0.0); };
  const gi::RadiosityHandoff h = lab16::room_handoff(mesh, B, D, E);
  // What each vertex must hold: the area-weighted mean of B - E - D of its elements.
  std::vector<Color> indirect;
  for (const gi::Element& e : mesh.elements)
    indirect.push_back(B(e.surface, e.shape.centre) - E(e.surface, e.shape.centre) - D(e.surface, e.shape.centre));
  const std::vector<Color> expected = gi::vertex_radiosity(h.mesh, indirect);
  for (std::size_t v = 0; v < expected.size(); ++v)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(h.vertex_indirect[v][c], expected[v][c], 1e-9)
          << "vertex " << v << ", channel " << c << ": indirect_i = B_i - E_i - D_i for every element i and every "
          << "colour channel, E_i being the emission of element i's own surface";
}
