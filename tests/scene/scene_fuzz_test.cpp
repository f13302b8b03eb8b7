// The scene reader against damaged files: every file of lessons/scenes/ (and an OBJ
// mesh) mutated at random, and cut at every byte. Each must read into a scene both
// renderers accept, or be refused with a SceneError -- never another exception, a
// crash, a hang or an allocation beyond the reader's limits (the asan preset runs this
// too, which turns any memory error into a failure). Fixed seeds: the same mutants on
// every run, so a failure can be replayed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gi/core/rng.hpp"
#include "gi/radiosity/mesh/radiosity_scene_file.hpp"
#include "gi/scene/obj_file.hpp"
#include "gi/scene/scene_file.hpp"
#include "scene_file_support.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_whole(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// What a damaged file tends to hold: JSON's punctuation, numbers at and past the
// ends of a double, words that are not JSON, bytes that are not UTF-8, deep nesting.
const char* const pieces[] = {"{", "}", "[", "]", ",", ":", "\"", "\\", "\\u", "\\ud800", "0", "-1", "1e308", "1e999",
                              "-0.0", "NaN", "Infinity", "true", "null", "\"name\"", "\"material\"", "\"radius\": -1",
                              "\xFF", "\xC3", "\xED\xA0\x80", "\n", "\t", "[[[[[[[[[[[[[[[[", "f 1 2 3\n", "v 1e9 0 0\n",
                              "usemtl nowhere\n", "f -99 1 2\n", "#", "/", "1//", "\0"};

// One random change: a byte replaced, a piece inserted, a span deleted, a span
// repeated, or the end cut off.
void mutate(std::string& text, gi::Rng& rng) {
  const auto at = [&] { return text.empty() ? std::size_t(0) : static_cast<std::size_t>(rng.below(text.size())); };
  switch (rng.below(5)) {
    case 0:
      if (!text.empty()) text[at()] = static_cast<char>(rng.below(256));
      break;
    case 1: {
      const std::size_t k = rng.below(std::size(pieces));
      text.insert(at(), std::string(pieces[k], k + 1 == std::size(pieces) ? 1 : std::strlen(pieces[k])));
      break;
    }
    case 2: {
      const std::size_t from = at();
      text.erase(from, rng.below(64));
      break;
    }
    case 3: {
      const std::size_t from = at();
      const std::string span = text.substr(from, rng.below(200));
      text.insert(at(), span);
      break;
    }
    default:
      text.resize(at());
  }
}

// Reads the scene text (as if it were `file`); a file that reads must make scenes
// both renderers take. Returns whether it read.
bool read_or_refuse(const std::string& text, const fs::path& file, const std::string& label) {
  try {
    const gi::SceneFile read = gi::read_scene_text(text, file);
    std::vector<std::string> warnings;
    const gi::Scene traced = gi::ray_tracing_scene(read, warnings);
    EXPECT_NO_THROW(gi::check(traced)) << label;
    try {
      gi::check_meshable(gi::radiosity_scene(read, warnings), file.string(), 10'000);
    } catch (const gi::SceneError&) {  // spheres, planes, no light, overlaps: refused, as they should be
    }
    return true;
  } catch (const gi::SceneError&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << label << ": not a SceneError but " << e.what();
  }
  return false;
}

}  // namespace

TEST(SceneFuzz, MutatedFilesReadOrAreRefusedWithOneError) {
  std::vector<fs::path> originals;
  for (const auto& entry : fs::directory_iterator(fs::path(GI_SOURCE_DIR) / "lessons/scenes"))
    if (entry.path().extension() == ".json") originals.push_back(entry.path());
  std::sort(originals.begin(), originals.end());
  ASSERT_GE(originals.size(), 11u);
  int refused = 0, read = 0;
  for (std::size_t f = 0; f < originals.size(); ++f) {
    const std::string original = read_whole(originals[f]);
    gi::Rng rng(2024, f);
    for (int m = 0; m < 400; ++m) {
      std::string text = original;
      for (int k = 1 + static_cast<int>(rng.below(3)); k > 0; --k) mutate(text, rng);
      const bool ok = read_or_refuse(text, originals[f], originals[f].filename().string() + " mutant " + std::to_string(m));
      (ok ? read : refused) += 1;
    }
  }
  // Both outcomes occur, so both paths were exercised.
  EXPECT_GT(refused, 500);
  EXPECT_GT(read, 20);
}

// The OBJ reader alone (in memory), and a few mutants through a scene file, which
// looks their materials up and hands their faces to both renderers.
TEST(SceneFuzz, MutatedMeshesReadOrAreRefusedWithOneError) {
  const fs::path folder = gi_test::scratch_folder("fuzz_obj");
  const std::string scene = "{" + gi_test::camera + R"(,
    "materials": [{"name": "white", "diffuse": 0.5, "emission": 1}],
    "meshes": [{"file": "mesh.obj", "material": "white"}]})";
  const std::string mesh = "# a box without a lid\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
                           "v 0 1 1\nusemtl white\nf 1 2 3 4\nf 5 6 2 1\nf 6 7 3 2\nf 7 8 4 3\nf 8 5 1 4\nf 1/1 2/2/2 3//3\n";
  gi::Rng rng(2025);
  int refused = 0;
  for (int m = 0; m < 2000; ++m) {
    std::string text = mesh;
    for (int k = 1 + static_cast<int>(rng.below(3)); k > 0; --k) mutate(text, rng);
    std::istringstream in(text);
    try {
      (void)gi::read_obj(in, "mesh.obj");
    } catch (const gi::SceneError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "mesh mutant " << m << ": not a SceneError but " << e.what();
    }
    if (m % 20 == 0) {
      gi_test::write_text(folder / "mesh.obj", text);
      read_or_refuse(scene, folder / "scene.json", "mesh mutant " + std::to_string(m));
    }
  }
  EXPECT_GT(refused, 300);
}

TEST(SceneFuzz, AFileCutAtAnyByteIsRefused) {
  for (const char* name : {"soft.json", "cornell.json"}) {
    const fs::path file = fs::path(GI_SOURCE_DIR) / "lessons/scenes" / name;
    const std::string text = read_whole(file);
    // Up to the closing brace every cut leaves the object open; after it, only the
    // final new line goes, and the file reads.
    for (std::size_t n = 0; n <= text.rfind('}'); ++n)
      EXPECT_THROW((void)gi::read_scene_text(text.substr(0, n), file), gi::SceneError) << name << " cut at byte " << n;
  }
}
