// lessons/scenes/s10.json and its Tachyon twin s10.tachyon.dat describe one picture,
// so that the two renderers can be timed on it (docs/02). Tachyon's view is
// left-handed, ours right-handed: every x is negated, and nothing else changes.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "gi/scene/scene_file.hpp"

namespace {

using gi::vec3;

// The words of the Tachyon file, and a cursor over them.
struct Words {
  std::vector<std::string> words;
  std::size_t at = 0;
  bool find(const std::string& word) {  // moves past the next `word`
    while (at < words.size())
      if (words[at++] == word) return true;
    return false;
  }
  double number() { return std::stod(words.at(at++)); }
  vec3 triple() {
    const double x = number(), y = number();
    return vec3(x, y, number());
  }
  std::string next() const { return words.at(at); }
};

Words tachyon_file() {
  std::ifstream in(std::string(GI_SOURCE_DIR) + "/lessons/scenes/s10.tachyon.dat");
  Words w;
  for (std::string word; in >> word;) w.words.push_back(word);
  return w;
}

vec3 mirrored(const vec3& v) { return vec3(-v.x, v.y, v.z); }

}  // namespace

TEST(TachyonTwin, TheS10FileIsTheTachyonSceneWithXNegated) {
  std::vector<std::string> warnings;
  const gi::Scene s = gi::load_scene(std::string(GI_SOURCE_DIR) + "/lessons/scenes/s10.json", warnings);
  Words t = tachyon_file();
  ASSERT_GT(t.words.size(), 100u) << "lessons/scenes/s10.tachyon.dat is missing or empty";

  ASSERT_TRUE(t.find("CENTER"));
  EXPECT_EQ(mirrored(t.triple()), s.camera.eye);
  ASSERT_TRUE(t.find("VIEWDIR"));  // look_at = eye + VIEWDIR, up to the rounding of 3.5 - 0.3
  const vec3 view = mirrored(t.triple()), ours = s.camera.look_at - s.camera.eye;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(view[c], ours[c], 1e-15);
  ASSERT_TRUE(t.find("UPDIR"));
  EXPECT_EQ(t.triple(), s.camera.up);
  ASSERT_TRUE(t.find("BACKGROUND"));
  EXPECT_EQ(t.triple(), s.background);

  ASSERT_TRUE(t.find("PLANE") && t.find("CENTER"));
  EXPECT_EQ(t.triple(), s.planes.at(0).point);
  ASSERT_TRUE(t.find("NORMAL"));
  EXPECT_EQ(t.triple(), s.planes.at(0).normal);

  for (const gi::PointLight& light : s.lights) {
    ASSERT_TRUE(t.find("LIGHT") && t.find("CENTER"));
    EXPECT_EQ(mirrored(t.triple()), light.position);
    ASSERT_TRUE(t.find("COLOR"));
    EXPECT_EQ(t.triple(), light.intensity);
  }
  EXPECT_FALSE(Words(t).find("LIGHT")) << "the Tachyon file has more lights than s10.json";

  for (const gi::Sphere& sphere : s.spheres) {
    const gi::Material& m = s.materials.at(sphere.material);
    ASSERT_TRUE(t.find("SPHERE") && t.find("CENTER"));
    EXPECT_EQ(mirrored(t.triple()), sphere.center) << m.name;
    ASSERT_TRUE(t.find("RAD"));
    EXPECT_EQ(t.number(), sphere.radius) << m.name;
    if (t.next() != "TEXTURE") {  // a texture named earlier: the mirror or the glass
      EXPECT_EQ(t.next(), m.name);
      continue;
    }
    // k_d = DIFFUSE x COLOR, as Tachyon shades it; k_a = AMBIENT; n = PHONG_SIZE.
    ASSERT_TRUE(t.find("AMBIENT"));
    EXPECT_EQ(t.number(), m.ambient) << m.name;
    ASSERT_TRUE(t.find("DIFFUSE"));
    const double diffuse = t.number();
    ASSERT_TRUE(t.find("PHONG_SIZE"));
    EXPECT_EQ(t.number(), m.shininess) << m.name;
    ASSERT_TRUE(t.find("COLOR"));
    const vec3 kd = diffuse * t.triple();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(kd[c], m.diffuse[c], 1e-15) << m.name;
  }
  EXPECT_FALSE(Words(t).find("SPHERE")) << "the Tachyon file has more spheres than s10.json";
}
