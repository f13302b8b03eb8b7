// The scene options every rendering lesson shares: their text, and what a lesson does
// with a scene it cannot use (status 2, one line, nothing written).
#include "gi/report/scene_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gi/report/lesson.hpp"
#include "gi/report/options.hpp"
#include "gi/scene/scene_error.hpp"

namespace {

namespace fs = std::filesystem;
using gi::vec3;

std::string camera_error(const std::string& text) {
  try {
    (void)gi::parse_camera_change(text);
  } catch (const gi::OptionError& e) {
    return e.what();
  }
  return "";
}

std::string scales_error(const std::string& text) {
  try {
    (void)gi::parse_light_scales(text);
  } catch (const gi::OptionError& e) {
    return e.what();
  }
  return "";
}

struct SceneRun {
  int status;
  std::string err;
  bool worked;
};

// A lesson with --scene, --camera and --light-scale, its scene read by `load`, run with `args`.
SceneRun run_with_scene(const std::vector<std::string>& args, const std::function<void(const std::string&, std::vector<std::string>&)>& load,
        const fs::path& out) {
  gi::Lesson lesson("01_x", "A test lesson.");
  std::string choice = "one";
  gi::SceneChanges changes;
  lesson.add_scene(choice, {"one", "two"}, load);
  lesson.add_scene_changes(changes);
  const std::string out_arg = out.string();  // a path's c_str() is wchar_t* on Windows
  std::vector<const char*> argv{"01_x", "--out", out_arg.c_str()};
  for (const std::string& a : args) argv.push_back(a.c_str());
  bool worked = false;
  testing::internal::CaptureStderr();
  const int status = lesson.run(static_cast<int>(argv.size()), argv.data(), [&] { worked = true; });
  return {status, testing::internal::GetCapturedStderr(), worked};
}

}  // namespace

TEST(SceneOptions, ACameraIsEyeLookAtAndAFieldOfView) {
  const gi::CameraChange c = gi::parse_camera_change("278,273,-800:278,273.5,0:40");
  EXPECT_EQ(c.eye, vec3(278, 273, -800));
  EXPECT_EQ(c.look_at, vec3(278, 273.5, 0));
  EXPECT_EQ(c.fov, 40.0);
  EXPECT_FALSE(gi::parse_camera_change("0,0,1:0,0,0").fov.has_value());
  EXPECT_EQ(camera_error("1,2"), "--camera expects EYE:LOOK_AT[:FOV] such as 278,273,-800:278,273,0:40, got '1,2'");
  EXPECT_EQ(camera_error("1,2:3,4,5"), "--camera eye: expected three numbers x,y,z, got '1,2'");
  const std::string decimal = "expected a decimal number such as 2, -0.5 or 1e-3, got '";
  EXPECT_EQ(camera_error("1,2,3:3,x,5"), "--camera look-at: " + decimal + "x'");
  EXPECT_EQ(camera_error("1,2,3:3,nan,5"), "--camera look-at: " + decimal + "nan'");
  // The grammar of number_text.hpp, not the converter's: no hex, sign '+', spaces or inf.
  EXPECT_EQ(camera_error("0x10,0,0:0,0,0"), "--camera eye: " + decimal + "0x10'");
  EXPECT_EQ(camera_error("+1,0,0:0,0,0"), "--camera eye: " + decimal + "+1'");
  EXPECT_EQ(camera_error(" 1,0,0:0,0,0"), "--camera eye: " + decimal + " 1'");
  EXPECT_EQ(camera_error("inf,0,0:0,0,0"), "--camera eye: " + decimal + "inf'");
  EXPECT_EQ(camera_error("1,0,0:0,0,0:1e"), "--camera field of view: " + decimal + "1e'");
  EXPECT_EQ(camera_error("1e-320,0,0:0,0,0"),
            "--camera eye: the number must be 0 or at least 2.2250738585072014e-308 in size (a smaller double has "
            "lost digits), got '1e-320'");
  EXPECT_FALSE(std::signbit(gi::parse_camera_change("-0,1,2:0,0,0").eye.x)) << "-0 is kept as 0";
  EXPECT_EQ(camera_error("1,2,3:1,2,3"), "--camera: the eye and the point looked at must differ");
  EXPECT_EQ(camera_error("1,2,3:0,0,0:180"), "--camera: the field of view must lie in (0, 180) degrees, got 180");
  EXPECT_EQ(camera_error("1e7,0,0:0,0,0"), "--camera eye: each coordinate must lie in [-1e6, 1e6], got '1e7,0,0'");
}

TEST(SceneOptions, LightScalesAreNamesWithFactors) {
  const std::vector<gi::LightScale> s = gi::parse_light_scales("light=2,short block 1=0");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].light, "light");
  EXPECT_EQ(s[0].factor, 2.0);
  EXPECT_EQ(s[1].light, "short block 1");
  EXPECT_EQ(s[1].factor, 0.0);
  EXPECT_EQ(scales_error("light"), "--light-scale expects NAME=FACTOR[,NAME=FACTOR ...] such as light=2, got 'light'");
  EXPECT_EQ(scales_error("=2"), "--light-scale expects NAME=FACTOR[,NAME=FACTOR ...] such as light=2, got '=2'");
  EXPECT_EQ(scales_error("light=-1"), "--light-scale light: the factor must lie in [0, 1e6], got -1");
  EXPECT_EQ(scales_error("light=two"),
            "--light-scale light: expected a decimal number such as 2, -0.5 or 1e-3, got 'two'");
  EXPECT_EQ(scales_error("light=0x10"),
            "--light-scale light: expected a decimal number such as 2, -0.5 or 1e-3, got '0x10'");
  EXPECT_EQ(scales_error("light=1e-320"),
            "--light-scale light: the number must be 0 or at least 2.2250738585072014e-308 in size (a smaller "
            "double has lost digits), got '1e-320'");
  EXPECT_EQ(scales_error("light=1,light=2"), "--light-scale names 'light' twice");
}

TEST(SceneOptions, FileStemsAreSafe) {
  EXPECT_EQ(gi::file_stem("cornell"), "cornell");
  EXPECT_EQ(gi::file_stem("my room/../x!"), "my_room____x_");
  EXPECT_EQ(gi::file_stem(""), "scene");
}

TEST(SceneOptions, ABadSceneIsStatusTwoWithItsOneLineAndNothingWritten) {
  const fs::path out = fs::path(testing::TempDir()) / "gi_scene_options" / "out";
  fs::remove_all(out.parent_path());
  const auto bad_file = [](const std::string&, std::vector<std::string>&) {
    throw gi::SceneError(gi::FileLocation{"box.json", 3, 7, "spheres[0].radius"}, "must be > 0, got -1");
  };
  SceneRun r = run_with_scene({}, bad_file, out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "01_x: error: box.json:3:7: spheres[0].radius: must be > 0, got -1\n");
  EXPECT_FALSE(r.worked);
  EXPECT_FALSE(fs::exists(out)) << "a refused scene must not make the output folder";
  const auto unknown = [](const std::string& choice, std::vector<std::string>&) {
    throw std::invalid_argument("unknown scene '" + choice + "'");
  };
  r = run_with_scene({"--scene", "three"}, unknown, out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "01_x: error: unknown scene 'three' (try --help)\n");
  r = run_with_scene({"--camera", "0,0,0:0,0,0"}, [](const std::string&, std::vector<std::string>&) {}, out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "01_x: error: --camera: the eye and the point looked at must differ (try --help)\n");
  EXPECT_FALSE(fs::exists(out));
  // Warnings are printed, and the lesson goes on.
  r = run_with_scene({}, [](const std::string&, std::vector<std::string>& w) { w.push_back("box.json:1:1: a warning"); }, out);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.err, "01_x: warning: box.json:1:1: a warning\n");
  EXPECT_TRUE(r.worked);
}
