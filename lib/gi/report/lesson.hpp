#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gi/image/image.hpp"
#include "gi/report/chart.hpp"
#include "gi/report/matrix_chart.hpp"
#include "gi/report/options.hpp"
#include "gi/report/outputs.hpp"
#include "gi/report/scene_options.hpp"
#include "gi/report/table.hpp"
#include "gi/scene/scene.hpp"
#include "gi/scene/scene_file.hpp"

namespace gi {

// What a lesson offers besides --out, which every lesson has: an option it would
// ignore is not offered.
struct LessonFeatures {
  bool threads = true;  // --threads N: it runs work in parallel
  bool seed = true;     // --seed N: it draws random numbers
};

// A lesson: its name, said once; its options; the checks of its configuration; its
// output folder; and the record of what it printed and wrote, in order.
//
//   gi::Lesson lesson("01_rays", "Ray-sphere and ray-plane intersection ...");
//   lesson.add_image_size(width, height);
//   lesson.add_scene(scene_name, scene);  // --scene
//   return lesson.run(argc, argv, [&] { ... lesson.table(t, "ray_sphere"); ... });
class Lesson {
 public:
  Lesson(std::string name, std::string summary, LessonFeatures features = {});

  Options& options() { return options_; }
  // --width and --height in [min_image_size, max_image_size], the one range of
  // every lesson that renders; `what` names the image in --help.
  void add_image_size(int& width, int& height, const std::string& what = "image");
  // A check of the whole configuration (sizes that multiply, option combinations),
  // run after parsing and before any work: throw OptionError to refuse.
  void add_check(std::function<void()> check);

  // --scene NAME|FILE: a built-in scene (`names`, listed in --help) or a scene file
  // (docs/scene_files.md). `load` reads the choice into the lesson's own scene as a
  // check, before any work (call add_scene before the checks that look at the scene):
  // a bad file is refused with status 2 and one line, "file:line:column: path:
  // message"; the warnings it adds are printed on stderr.
  // Adds --mesh-folder DIR too: where else a scene file may read its meshes from
  // (SceneFileRules, scene_file.hpp); a loader hands scene_file_rules() to the reader.
  using SceneLoader = std::function<void(const std::string& choice, std::vector<std::string>& warnings)>;
  void add_scene(std::string& choice, const std::vector<std::string>& names, SceneLoader load);
  const SceneFileRules& scene_file_rules() const { return scene_file_rules_; }
  // The ray tracer's: a built-in scene (builtin_scenes.hpp) or a file, into `scene`.
  void add_scene(std::string& choice, Scene& scene);
  // --camera EYE:LOOK_AT[:FOV] and --light-scale NAME=FACTOR,... into `changes`
  // (scene_changes.hpp): the radiosity lessons' new viewpoint and light.
  void add_scene_changes(SceneChanges& changes);

  // Parses the command line, runs the checks, makes sure the output folder can be
  // created and written, writes outputs.json saying "running" (with this process),
  // runs `body`, then checks that every file it wrote is in place and writes
  // outputs.json again with the outcome and the report page, index.html, made from
  // it (report_page.hpp); a folder named after the lesson (out/08_radiosity_system)
  // also updates the index of lessons in the folder above (lessons_index.hpp), at
  // the start and at the end.
  // Returns the exit status:
  //   0  done, every file written is in place (also after --help)
  //   1  a failure while running: an error, a full disk, a file missing at the end
  //   2  a bad command line or configuration, found before any work
  //   3  an exercise not done yet (a student kit)
  // In every case but 0 one line on stderr says why.
  int run(int argc, const char* const* argv, const std::function<void()>& body);

  const std::string& name() const { return name_; }
  const std::filesystem::path& out() const { return out_; }
  int threads() const { return common_.threads; }
  std::uint64_t seed() const { return common_.seed; }

  // Each writer writes atomically into out() and records the output.
  // A rendered picture: stem.png shows clamp(exposure * radiance), sRGB-encoded;
  // stem.pfm beside it keeps the radiance itself, unclamped; `view` states the camera.
  // `shown`, when given, is what the PNG shows instead (display.hpp's white clamp).
  void picture(const Image& radiance, const std::string& stem, const std::string& caption, const View& view,
               double exposure = 1, const Image* shown = nullptr);
  // A PNG that is not a view of radiance (crops and strips, an item buffer).
  void diagram(const Image& image, const std::string& stem, const std::string& caption, double exposure = 1);
  // A false-colour PNG (false_colour, difference_image): `scale` says what its colours
  // mean -- the values at black and red, the quantity and its unit -- and the report
  // page draws it as a colour bar beneath the picture.
  void diagram(const Image& image, const std::string& stem, const std::string& caption, const ColourScale& scale);
  // A labelled heat map (matrix_chart.hpp): stem.svg, shown as a false-colour diagram.
  void diagram(const MatrixChart& chart, const std::string& stem, const std::string& caption, const ColourScale& scale);
  // Prints the table on stdout and writes stem.csv.
  void table(const Table& table, const std::string& stem);
  void chart(const Chart& chart, const std::string& stem);  // stem.svg
  // Any other file, written by `write` to the path it is given (e.g. write_ply).
  void file(const std::string& name, OutputKind kind, const std::string& caption,
            const std::function<void(const std::filesystem::path&)>& write);
  // The interactive viewer (docs/viewer/): viewer.html and its scripts are copied
  // in, and `write_data` writes the data it shows to the path it is given
  // (viewer_data.js; lib/gi/viewer/data.hpp). One per lesson.
  void viewer(const std::string& caption, const std::function<void(const std::filesystem::path&)>& write_data);
  // A file some library function wrote into out() (a cached reference).
  void record(const std::filesystem::path& file, OutputKind kind, const std::string& caption);
  // Prints one line on stdout and records it.
  void say(const std::string& line);

  const std::vector<Output>& outputs() const { return outputs_; }

 private:
  std::filesystem::path path(const std::string& name) const { return out_ / name; }
  void prepare_folder();
  std::optional<std::filesystem::path> index_folder() const;
  void check_outputs() const;
  void write_record(const std::string& status) const;
  void write_pages(const std::string& status) const;

  std::string name_;
  Options options_;
  CommonOptions common_;
  std::vector<std::function<void()>> checks_;
  SceneFileRules scene_file_rules_;
  std::filesystem::path out_;
  std::vector<std::string> command_;
  std::vector<Output> outputs_;
};

// Runs a lesson's body and turns what it throws into one readable line on stderr
// and an exit status: 2 for a bad command line, 3 for an exercise not done yet,
// 1 for any other error. The body returns the status on success (normally 0).
// Lessons use Lesson::run, which adds the checks of the folder and the outputs.
int run_lesson(const std::string& name, const std::function<int()>& body);

}  // namespace gi
