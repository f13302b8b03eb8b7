// The viewer's data file (viewer_data.hpp): read back, it gives the values written
// (as float32); the lessons' files stay within their stated size; bad data is
// refused before a byte is written; relighting is linear in E; a hierarchical run's
// links, summed over a leaf and its ancestors, give what the solver gathers for it.
#include "gi/viewer/data.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>

#include "../support/files.hpp"
#include "gi/core/atomic_file.hpp"
#include "gi/radiosity/form_factors/form_factor_hemicube.hpp"
#include "gi/radiosity/system/progressive.hpp"
#include "gi/radiosity/system/solvers.hpp"
#include "gi/viewer/demos.hpp"
#include "gi/viewer/hierarchical.hpp"
#include "gi/scene/json.hpp"

using gi::Color;

namespace {

namespace fs = std::filesystem;

struct Cornell {
  gi::RadiosityScene scene = gi::cornell_box();
  gi::Mesh mesh;
  gi::RadiositySystem system;
};
const Cornell& cornell() {
  static const Cornell c = [] {
    Cornell box;
    box.mesh = gi::make_mesh(box.scene.surfaces, {gi::patch_size_for(box.scene.surfaces, 60, 1), 1});
    box.system = gi::make_system(box.mesh, gi::form_factor_matrix_hemicube(gi::element_shapes(box.mesh), 30, 2));
    return box;
  }();
  return c;
}

// The file's JSON, read with the scene reader's parser (limits raised to the viewer's size).
gi::JsonValue read_back(const std::string& text) {
  const std::string head = "window.GI_VIEWER_DATA = ";
  const std::size_t start = text.find(head);
  EXPECT_NE(start, std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 2), ";\n");
  gi::JsonLimits limits;
  limits.max_bytes = 64u << 20;
  return gi::parse_json(text.substr(start + head.size(), text.size() - 2 - start - head.size()), "viewer_data.js",
                        limits);
}

const gi::JsonValue& member(const gi::JsonValue& object, const std::string& key) {
  for (const gi::JsonMember& m : object.members)
    if (m.key == key) return m.value;
  ADD_FAILURE() << "no key " << key;
  static const gi::JsonValue none;
  return none;
}

bool has(const gi::JsonValue& object, const std::string& key) {
  for (const gi::JsonMember& m : object.members)
    if (m.key == key) return true;
  return false;
}

// A typed array's values: base64, then little-endian 32-bit words.
std::vector<std::uint32_t> words(const gi::JsonValue& array) {
  const std::string& text = member(array, "base64").text;
  std::vector<unsigned char> bytes;
  std::uint32_t group = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    group = group << 6 | static_cast<std::uint32_t>(std::strchr(digits, c) - digits);
    bits += 6;
    if (bits >= 8) bytes.push_back(static_cast<unsigned char>(group >> (bits -= 8)));
  }
  std::vector<std::uint32_t> out(bytes.size() / 4);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int k = 0; k < 4; ++k) out[i] |= std::uint32_t(bytes[4 * i + k]) << (8 * k);
  EXPECT_EQ(out.size(), static_cast<std::size_t>(member(array, "count").number));
  return out;
}

std::vector<float> floats(const gi::JsonValue& array) {
  EXPECT_EQ(member(array, "type").text, "float32");
  std::vector<float> out;
  for (std::uint32_t w : words(array)) {
    float f;
    std::memcpy(&f, &w, 4);
    out.push_back(f);
  }
  return out;
}

std::vector<int> ints(const gi::JsonValue& array) {
  std::vector<int> out;
  for (std::uint32_t w : words(array)) out.push_back(static_cast<int>(w));
  return out;
}

}  // namespace

TEST(ViewerData, ReadsBackAsWritten) {
  const Cornell& c = cornell();
  gi::ViewerData d = gi::viewer_data("08_x", "a \"quoted\" title", c.mesh, c.scene.camera, 1.5);
  gi::ViewerRun run;
  run.name = "Jacobi", run.unit = "iteration", run.status = "stopped after 2 iterations";
  run.history = {{1, 0.5, 0.25, 0.125, 0.1, 0.01}, {2, 0.25, 0.125, 0.0625, 0.05, 0.02}};
  run.frames = {{0, c.system.emission}, {2, std::vector<Color>(c.system.size(), Color(0.1, 0.2, 0.3))}};
  d.runs.push_back(run);
  const gi::JsonValue json = read_back(gi::viewer_data_text(d));

  EXPECT_EQ(member(json, "format").text, "gi-workbench viewer");
  EXPECT_EQ(member(json, "version").number, 1);
  EXPECT_EQ(member(json, "title").text, "a \"quoted\" title");
  EXPECT_EQ(member(json, "exposure").number, 1.5);
  const gi::JsonValue& mesh = member(json, "mesh");
  const std::vector<float> vertices = floats(member(mesh, "vertices"));
  ASSERT_EQ(vertices.size(), 3 * c.mesh.vertices.size());
  for (std::size_t v = 0; v < c.mesh.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(vertices[3 * v + k], static_cast<float>(c.mesh.vertices[v][k]));
  const std::vector<int> elements = ints(member(mesh, "elements"));
  ASSERT_EQ(elements.size(), 4 * c.mesh.elements.size());
  for (std::size_t e = 0; e < c.mesh.elements.size(); ++e)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(elements[4 * e + k], c.mesh.elements[e].vertices[k]);
  EXPECT_EQ(member(mesh, "patches").number, static_cast<double>(c.mesh.patches.size()));
  EXPECT_EQ(member(mesh, "surfaces").items.size(), c.mesh.surfaces.size());

  const gi::JsonValue& r = member(json, "runs").items.at(0);
  EXPECT_EQ(member(r, "status").text, "stopped after 2 iterations");
  const gi::JsonValue& history = member(r, "history");
  EXPECT_EQ(ints(member(history, "step")), (std::vector<int>{1, 2}));
  EXPECT_EQ(floats(member(history, "error")), (std::vector<float>{0.1f, 0.05f}));
  EXPECT_EQ(floats(member(history, "seconds")), (std::vector<float>{0.01f, 0.02f}));
  EXPECT_EQ(floats(member(history, "residual_2")), (std::vector<float>{0.5f, 0.25f}));
  const gi::JsonValue& frames = member(r, "frames");
  EXPECT_EQ(ints(member(frames, "step")), (std::vector<int>{0, 2}));
  const std::vector<float> B = floats(member(frames, "B"));
  ASSERT_EQ(B.size(), 2 * 3 * c.mesh.elements.size());
  EXPECT_EQ(B[3 * c.mesh.elements.size() + 1], 0.2f);
  EXPECT_FALSE(has(frames, "shooter")) << "only progressive runs name their shooters";
  EXPECT_TRUE(member(json, "lights").items.empty());
}

TEST(ViewerData, RefusesBadDataAndLeavesTheOldFile) {
  const Cornell& c = cornell();
  const gi::ViewerData good = gi::viewer_data("08_x", "t", c.mesh, c.scene.camera, 1);
  const fs::path file = fs::path(testing::TempDir()) / "gi_viewer_data_test" / "viewer_data.js";
  fs::remove_all(file.parent_path());
  gi::write_viewer_data(good, file);
  const std::string before = gi_test::file_text(file);

  auto refused = [&](gi::ViewerData d, const std::string& why) {
    try {
      gi::write_viewer_data(d, file);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
    EXPECT_EQ(gi_test::file_text(file), before);
    for (const std::string& name : gi_test::files_in(file.parent_path())) EXPECT_FALSE(gi::is_partial_file(name));
  };
  gi::ViewerData d = good;
  d.elements[3][2] = static_cast<int>(d.vertices.size());
  refused(d, "an element's corner is not a vertex");
  d = good;
  d.element_patch.back() = d.patches;
  refused(d, "an element's patch is out of range");
  d = good;
  d.exposure = 0;
  refused(d, "the exposure must be positive");
  d = good;
  d.runs.push_back({"x", "iteration", "", 1, {}, {{1, std::vector<Color>(3)}}, false});
  refused(d, "run 'x', frame of step 1 has 3 values for");
  d = good;
  d.runs.push_back({"x", "iteration", "", 1, {}, {{1, std::vector<Color>(d.elements.size(), Color(1e39))}}, false});
  refused(d, "not finite");
  d = good;
  d.lights.push_back({"lamp", 1, d.emission, std::vector<Color>(d.elements.size(), Color(NAN))});
  refused(d, "light 'lamp' B holds a value that is not finite");
}

TEST(ViewerData, ANotWritableFolderIsAWriteError) {
  const Cornell& c = cornell();
  gi_test::SmallDisk disk(16, true);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  EXPECT_THROW(gi::write_viewer_data(gi::viewer_data("08_x", "t", c.mesh, c.scene.camera, 1), disk.path() / "v.js"),
               gi::WriteError);
  EXPECT_TRUE(gi_test::files_in(disk.path()).empty());
}

TEST(ViewerData, FrameStepsKeepTheFirstStepsAndTheLast) {
  EXPECT_EQ(gi::frame_steps(5, 10), (std::vector<int>{1, 2, 3, 4, 5}));
  const std::vector<int> steps = gi::frame_steps(1000, 10);
  EXPECT_EQ(steps, (std::vector<int>{1, 2, 3, 4, 5, 204, 403, 602, 801, 1000}));
  EXPECT_EQ(gi::frames_within(4 << 20, 1), 400);
  EXPECT_EQ(gi::frames_within(1200, 100), 2);
  EXPECT_EQ(gi::frames_within(12 * 1000 * 50, 1000), 50);
}

// The lessons' files stay within frame_bytes of frames (base64: 4/3 of the bytes)
// plus the mesh, even for the longest runs.
TEST(ViewerData, TheLessonsFilesAreBounded) {
  const Cornell& c = cornell();
  const std::size_t n = c.mesh.elements.size(), mesh_bytes = 4 * n * (4 + 1 + 1 + 1 + 3 + 3) + 12 * c.mesh.vertices.size();
  const std::size_t bound = (gi::frame_bytes + mesh_bytes) * 4 / 3 + (1 << 20);  // + histories and names
  const gi::SolverResult direct = gi::solve_direct(c.system);
  const std::string gathering =
      gi::viewer_data_text(gi::gathering_side_by_side("09", c.scene, c.mesh, c.system, direct.B, 3000, 1.2));
  EXPECT_LT(gathering.size(), bound);
  const std::string southwell =
      gi::viewer_data_text(gi::southwell_side_by_side("10", c.scene, c.mesh, c.system, direct.B, 40));
  EXPECT_LT(southwell.size(), bound);
  const gi::JsonValue json = read_back(southwell);
  for (const gi::JsonValue& run : member(json, "runs").items) {
    const std::vector<int> steps = ints(member(member(run, "frames"), "step"));
    EXPECT_EQ(steps.front(), 0);
    // The last step is always kept (a solver that reaches rounding level stops early).
    EXPECT_EQ(steps.back(), ints(member(member(run, "history"), "step")).back()) << member(run, "name").text;
    EXPECT_LE(steps.back(), member(run, "name").text == "Southwell" ? 40 * static_cast<int>(n) : 40);
  }
}

// Progressive refinement: frame 0 is B = E, and each frame names the patch that shot,
// the same one choose_shooter picks from the unshot radiosity before the shot.
TEST(ViewerData, ProgressiveFramesNameTheirShooters) {
  const Cornell& c = cornell();
  const gi::ShooterRow row = [&](int p) {
    std::vector<double> F;
    for (int j = 0; j < c.system.size(); ++j) F.push_back(c.system.F(c.mesh.patches[p].first_element, j));
    return F;
  };
  const gi::ViewerData d = gi::progressive_replay("11", c.scene, c.mesh, c.system, row, 30, 1.5);
  const gi::ViewerRun& run = d.runs.at(0);
  ASSERT_EQ(run.frames.size(), 31u);
  EXPECT_EQ(run.frames[0].B, c.system.emission);
  EXPECT_EQ(run.frames[0].shooter, -1);
  EXPECT_EQ(run.frames[1].shooter, gi::choose_shooter(c.mesh.patches, c.system.area, c.system.emission));
  EXPECT_NE(run.frames[2].shooter, run.frames[1].shooter) << "the light shot all it had";
  const gi::JsonValue json = read_back(gi::viewer_data_text(d));
  const gi::JsonValue& frames = member(member(json, "runs").items.at(0), "frames");
  EXPECT_EQ(ints(member(frames, "shooter"))[1], run.frames[1].shooter);
  EXPECT_EQ(floats(member(frames, "ambient")).size(), 3 * run.frames.size());
}

// Relighting: the system is linear in E, so the weighted sum of the per-light
// solutions solves the system for the weighted sum of their emissions.
TEST(ViewerData, PerLightSolutionsAddUp) {
  const Cornell& c = cornell();
  const std::vector<gi::ViewerLight> lights = gi::solve_per_light(c.system, c.mesh, {"short block top"});
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].weight, 1);
  EXPECT_EQ(lights[1].weight, 0);
  EXPECT_EQ(lights[1].name, "short block top as a lamp");
  gi::RadiositySystem both = c.system;
  for (int i = 0; i < both.size(); ++i) both.emission[i] = 0.5 * lights[0].emission[i] + 2.0 * lights[1].emission[i];
  const gi::SolverResult direct = gi::solve_direct(both);
  double worst = 0, largest = 0;
  for (int i = 0; i < both.size(); ++i) {
    const Color sum = 0.5 * lights[0].B[i] + 2.0 * lights[1].B[i];
    worst = std::max(worst, gi::max_component(glm::abs(sum - direct.B[i])));
    largest = std::max(largest, gi::max_component(direct.B[i]));
  }
  EXPECT_LT(worst, 1e-8 * largest);
  EXPECT_THROW(gi::solve_per_light(c.system, c.mesh, {"no such surface"}), std::invalid_argument);
}

// Lesson 08 names the Cornell box's block tops as lamps; another scene (--scene) has
// no such surfaces, and its viewer shows its own lights only.
TEST(ViewerData, LampsTheSceneLacksAreLeftOut) {
  const Cornell& c = cornell();
  const gi::ViewerData d = gi::neumann_and_relighting("08", c.scene, c.mesh, c.system, 3, 1.5,
                                                      {"short block top", "a lamp elsewhere"});
  ASSERT_EQ(d.lights.size(), 2u);
  EXPECT_EQ(d.lights[1].name, "short block top as a lamp");
  EXPECT_EQ(d.runs.at(0).frames.size(), 4u) << "B = E and three terms";
}

namespace {

// A hierarchical run on the Cornell box, coarse enough for a unit test (all light by links).
const gi::HierarchicalRun& hierarchical_box() {
  static const gi::HierarchicalRun run = [] {
    gi::HierarchicalSettings s;
    s.refinement.threshold = 1e-2;
    s.refinement.min_area = 1e-3;
    return gi::run_hierarchical(gi::cornell_box(), s, 2);
  }();
  return run;
}

}  // namespace

TEST(ViewerData, HierarchyReadsBackAsWritten) {
  const gi::HierarchicalRun& run = hierarchical_box();
  const gi::Hierarchy& h = run.hierarchy;
  const gi::ViewerData d = gi::hierarchical_viewer_data("13_x", "t", run, gi::cornell_box().camera, 1.5);
  ASSERT_TRUE(d.hierarchy);
  const gi::JsonValue json = read_back(gi::viewer_data_text(d));
  const gi::JsonValue& hierarchy = member(json, "hierarchy");
  const gi::JsonValue& nodes = member(hierarchy, "nodes");
  const std::vector<int> parent = ints(member(nodes, "parent")), level = ints(member(nodes, "level"));
  ASSERT_EQ(parent.size(), h.nodes.size());
  const std::vector<float> corners = floats(member(nodes, "corners"));
  ASSERT_EQ(corners.size(), 12 * h.nodes.size());
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    EXPECT_EQ(parent[n], h.nodes[n].parent);
    EXPECT_EQ(level[n], h.nodes[n].level);
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(corners[12 * n + 3 * c + k], static_cast<float>(h.nodes[n].shape.corners[c][k]));
  }
  EXPECT_EQ(ints(member(nodes, "surface")), d.hierarchy->node_surface);
  EXPECT_EQ(ints(member(hierarchy, "element_node")), gi::leaves(h)) << "the elements are the leaves, in order";
  const gi::JsonValue& links = member(hierarchy, "links");
  const std::vector<int> receiver = ints(member(links, "receiver")), source = ints(member(links, "source"));
  const std::vector<float> F = floats(member(links, "F")), V = floats(member(links, "visibility"));
  ASSERT_EQ(receiver.size(), gi::link_count(h));
  std::size_t l = 0;
  for (const gi::Node& node : h.nodes)
    for (const gi::Link& link : node.links) {
      EXPECT_EQ(receiver[l], link.receiver);
      EXPECT_EQ(source[l], link.source);
      EXPECT_EQ(F[l], static_cast<float>(link.F));
      EXPECT_EQ(V[l], static_cast<float>(link.visibility));
      ++l;
    }
  const gi::LeafMesh leaves = gi::leaf_mesh(h);
  ASSERT_FALSE(leaves.t_vertices.empty()) << "a mesh with T-vertices, or the test below is empty";
  const gi::JsonValue& t = member(hierarchy, "t_vertices");
  const std::vector<int> vertex = ints(member(t, "vertex")), a = ints(member(t, "a"));
  const std::vector<float> at = floats(member(t, "t"));
  ASSERT_EQ(vertex.size(), leaves.t_vertices.size());
  for (std::size_t i = 0; i < vertex.size(); ++i) {
    EXPECT_EQ(vertex[i], leaves.t_vertices[i].vertex);
    EXPECT_EQ(a[i], leaves.t_vertices[i].a);
    EXPECT_EQ(at[i], static_cast<float>(leaves.t_vertices[i].t));
  }
  EXPECT_EQ(member(hierarchy, "links_carry").text, "all the light: B = E + what the links bring");
  const gi::JsonValue& frames = member(member(json, "runs").items.at(0), "frames");
  EXPECT_EQ(floats(member(frames, "B")).size(), 3 * leaves.node.size()) << "one frame: the answer on the leaves";
}

TEST(ViewerData, HierarchyRefusesBadIndices) {
  const gi::HierarchicalRun& run = hierarchical_box();
  const gi::ViewerData good = gi::hierarchical_viewer_data("13_x", "t", run, gi::cornell_box().camera, 1.5);
  const auto refused = [&](const std::function<void(gi::ViewerHierarchy&)>& spoil, const std::string& why) {
    gi::ViewerData d = good;
    spoil(*d.hierarchy);
    try {
      gi::viewer_data_text(d);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  const int nodes = static_cast<int>(good.hierarchy->node_parent.size());
  refused([&](gi::ViewerHierarchy& h) { h.element_node[5] = nodes; }, "an element's node is out of range");
  refused([](gi::ViewerHierarchy& h) { h.element_node.pop_back(); }, "element_node needs one node per element");
  refused([&](gi::ViewerHierarchy& h) { h.links[7].source = nodes; }, "a link's receiver or source is not a node");
  refused([](gi::ViewerHierarchy& h) { h.links[7].receiver = -1; }, "a link's receiver or source is not a node");
  refused([&](gi::ViewerHierarchy& h) { h.node_parent[nodes - 1] = nodes - 1; }, "its parent is out of range");
  refused([](gi::ViewerHierarchy& h) { h.node_surface[0] = 99; }, "its surface is out of range");
  refused([](gi::ViewerHierarchy& h) { h.node_level.pop_back(); }, "one value per node");
  refused([](gi::ViewerHierarchy& h) { h.links[0].visibility = 1.5; }, "visibility is outside [0, 1]");
  refused([](gi::ViewerHierarchy& h) { h.links[0].light.y = NAN; }, "a link's light is not finite");
  refused([](gi::ViewerHierarchy& h) { h.links[0].F = INFINITY; }, "a link's F is not finite");
  refused([](gi::ViewerHierarchy& h) { h.element_gathered[2] = gi::Color(1e39); }, "element_gathered holds a value");
  refused([&](gi::ViewerHierarchy& h) { h.t_vertices[0].b = static_cast<int>(good.vertices.size()); },
          "a T-vertex names a vertex out of range");
  refused([](gi::ViewerHierarchy& h) { h.node_corners[3][1].z = NAN; }, "a corner is not finite");
}

// What the page sums when a leaf is picked -- the light of the links of the leaf and
// of its ancestors -- recomputed here from the file's own arrays (the parent chain,
// the receivers), against the solver run on: one more gather and push-pull from the
// B the file was written with hands every leaf B_new - source = gather_scale * rho *
// sum of those lights, to float32 rounding. And, for every link from a leaf, light = F V
// sent_source (its B times its send_scale, balance.hpp).
TEST(ViewerData, ALeafsLinksAndItsAncestorsAddUpToWhatTheSolverGathers) {
  const gi::HierarchicalRun& run = hierarchical_box();
  const gi::ViewerData d = gi::hierarchical_viewer_data("13_x", "t", run, gi::cornell_box().camera, 1.5);
  const gi::JsonValue json = read_back(gi::viewer_data_text(d));
  const gi::JsonValue& hierarchy = member(json, "hierarchy");
  const std::vector<int> parent = ints(member(member(hierarchy, "nodes"), "parent"));
  const std::vector<int> element_node = ints(member(hierarchy, "element_node"));
  const gi::JsonValue& links = member(hierarchy, "links");
  const std::vector<int> receiver = ints(member(links, "receiver")), source = ints(member(links, "source"));
  const std::vector<float> F = floats(member(links, "F")), V = floats(member(links, "visibility"));
  const std::vector<float> light = floats(member(links, "light"));
  const std::vector<float> handed = floats(member(hierarchy, "element_gathered"));
  const std::vector<float> rho = floats(member(member(json, "mesh"), "reflectance"));

  gi::Hierarchy next = run.hierarchy;
  gi::SolverOptions one;
  one.max_steps = 1;
  gi::solve_links(next, one, 2);

  std::vector<std::vector<int>> by_receiver(parent.size());
  for (std::size_t l = 0; l < receiver.size(); ++l) by_receiver[receiver[l]].push_back(static_cast<int>(l));
  double worst = 0, worst_handed = 0, largest = 0;
  std::size_t leaf_sources = 0;
  for (std::size_t e = 0; e < element_node.size(); ++e) {
    Color sum(0.0);
    for (int n = element_node[e]; n >= 0; n = parent[n])
      for (int l : by_receiver[n]) sum += Color(light[3 * l], light[3 * l + 1], light[3 * l + 2]);
    const gi::Node& leaf = next.nodes[element_node[e]];
    const Color r(rho[3 * e], rho[3 * e + 1], rho[3 * e + 2]);
    worst = std::max(worst, gi::max_component(glm::abs(leaf.gather_scale * r * sum - (leaf.B - leaf.source))));
    worst_handed = std::max(worst_handed, gi::max_component(glm::abs(r * sum - Color(handed[3 * e], handed[3 * e + 1],
                                                                                       handed[3 * e + 2]))));
    largest = std::max(largest, gi::max_component(leaf.B - leaf.source));
  }
  ASSERT_GT(largest, 0);
  EXPECT_LT(worst, 1e-5 * largest) << "the links of a leaf and its ancestors are all the light it gathers";
  // The solver's own last gather used the B before its last step: within its tolerance.
  EXPECT_LT(worst_handed, 1e-4 * largest) << "element_gathered is what the solver handed the leaf";
  for (std::size_t l = 0; l < receiver.size(); ++l) {
    const gi::Node& q = run.hierarchy.nodes[source[l]];
    if (!q.leaf()) continue;
    ++leaf_sources;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(light[3 * l + k], F[l] * V[l] * q.sent[k], 1e-6 * gi::max_component(q.sent) + 1e-30);
  }
  EXPECT_GT(leaf_sources, 0u);
  std::cout << "hierarchy: " << element_node.size() << " leaves, " << receiver.size() << " links; worst |rho sum - gathered| "
            << worst / largest << ", against element_gathered " << worst_handed / largest << " of the largest\n";
}
