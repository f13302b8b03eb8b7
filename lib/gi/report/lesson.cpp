#include "gi/report/lesson.hpp"

#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

#include "gi/core/atomic_file.hpp"
#include "gi/core/not_implemented.hpp"
#include "gi/core/platform/process.hpp"
#include "gi/image/image_io.hpp"
#include "gi/report/lesson_guide.hpp"
#include "gi/report/lessons_index.hpp"
#include "gi/report/page_assets.hpp"
#include "gi/report/report_page.hpp"
#include "gi/report/run_process.hpp"
#include "gi/scene/builtin_scenes.hpp"
#include "gi/scene/scene_file.hpp"
#include "gi/scene/utf8.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;

// The exit status and the one line on stderr for what a lesson threw.
int report_failure(const std::string& name, std::string& status) {
  try {
    throw;
  } catch (const SceneError& e) {  // "file:line:column: path: message" says it all
    std::cerr << name << ": error: " << printable(e.what()) << '\n';
    status = std::string("bad input: ") + e.what();
    return 2;
  } catch (const OptionError& e) {
    std::cerr << name << ": error: " << printable(e.what()) << " (try --help)\n";
    status = std::string("bad input: ") + e.what();
    return 2;
  } catch (const NotImplemented& e) {
    // The BVH (lab 5) finds the hits of every rendering lesson; until it is written
    // they can fall back on testing every primitive.
    const bool bvh = std::string(e.what()).find("exercise 5.") != std::string::npos;
    std::cerr << name << ": " << e.what() << (bvh ? " (until then, render with --accel brute-force)" : "") << '\n';
    status = std::string("stopped: ") + e.what();
    return 3;
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << printable(e.what()) << '\n';
    status = std::string("failed: ") + e.what();
    return 1;
  }
}

// A temporary left by a run that was killed: ".<name>.<pid>.<n>.partial" whose
// process no longer exists. Those of a run still going are left alone.
bool abandoned(const fs::path& file) {
  if (!is_partial_file(file)) return false;
  std::string name = file.filename().string();
  name.resize(name.size() - std::string(".partial").size());
  name.erase(name.rfind('.'));  // the counter
  const std::string pid = name.substr(name.rfind('.') + 1);
  if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid.size() > 9) return false;
  return !platform::process_exists(std::stoll(pid));
}

Output output(OutputKind kind, const std::string& caption, const fs::path& file) {
  Output o;
  o.kind = kind;
  o.caption = caption;
  o.file = file;
  return o;
}

}  // namespace

Lesson::Lesson(std::string name, std::string summary, LessonFeatures features)
    : name_(std::move(name)), options_(name_, std::move(summary)) {
  add_common_options(options_, common_, name_, features.threads, features.seed);
}

void Lesson::add_image_size(int& width, int& height, const std::string& what) {
  options_.add("--width", width, what + " width in pixels", min_image_size, max_image_size)
      .add("--height", height, what + " height in pixels", min_image_size, max_image_size);
}

void Lesson::add_check(std::function<void()> check) { checks_.push_back(std::move(check)); }

void Lesson::add_scene(std::string& choice, const std::vector<std::string>& names, SceneLoader load) {
  std::string listed;
  for (const std::string& n : names) listed += (listed.empty() ? "" : ", ") + n;
  options_.add("--scene", choice, "the scene: a built-in one (" + listed + ") or a scene file NAME.json " +
                                      "(lessons/scenes/ has examples; docs/scene_files.md)");
  options_.add_parsed("--mesh-folder", "DIR",
                      "a scene file may also read its OBJ meshes from below DIR (default: only from below its own "
                      "folder)",
                      [this](const std::string& text) { scene_file_rules_.mesh_folder = text; });
  add_check([this, &choice, load] {
    std::vector<std::string> warnings;
    try {
      load(choice, warnings);
    } catch (const SceneError&) {
      throw;
    } catch (const std::invalid_argument& e) {  // an unknown name, a camera that cannot see
      throw OptionError(e.what());
    }
    for (const std::string& w : warnings) std::cerr << name_ << ": warning: " << printable(w) << '\n';
  });
}

void Lesson::add_scene(std::string& choice, Scene& scene) {
  add_scene(choice, scene_names(), [this, &scene](const std::string& c, std::vector<std::string>& warnings) {
    scene = load_scene(c, warnings, scene_file_rules_);
  });
}

void Lesson::add_scene_changes(SceneChanges& changes) {
  options_.add_parsed("--camera", "EYE:LOOK_AT[:FOV]",
                      "look from EYE at LOOK_AT (x,y,z each) with a vertical field of view FOV in degrees; "
                      "the same solution from a new viewpoint (default: the scene's camera)",
                      [&changes](const std::string& text) { changes.camera = parse_camera_change(text); });
  options_.add_parsed("--light-scale", "NAME=FACTOR[,NAME=FACTOR ...]",
                      "multiply the emission of the named lights (surfaces) by FACTOR: a new light, the same form "
                      "factors",
                      [&changes](const std::string& text) { changes.light_scales = parse_light_scales(text); });
}

void Lesson::prepare_folder() {
  const std::string& text = common_.out;
  if (text.empty()) throw OptionError("--out needs a folder, got an empty name");
  if (text[0] == '-')
    throw OptionError("--out must name a folder, got '" + text + "' (for a folder of that name write ./" + text + ")");
  out_ = text;
  std::error_code error;
  if (fs::exists(out_, error) && !fs::is_directory(out_, error))
    throw OptionError("--out " + text + " is a file, not a folder");
  fs::create_directories(out_, error);
  if (error) throw OptionError("--out: cannot create the folder " + text + ": " + error.message());
  try {  // a folder that exists may still refuse files (read-only file system)
    write_atomically(out_ / ".write-test", [](std::ostream&) {});
    fs::remove(out_ / ".write-test", error);
  } catch (const WriteError& e) {
    throw OptionError("--out: cannot write into " + text + " (" + e.what() + ")");
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(out_, error))
    if (abandoned(entry.path())) fs::remove(entry.path(), error);
  // The record of an earlier run would describe files this run may not write, and its
  // page would show them: both go, and the record this run writes first says
  // "running", with the process, until the run ends. A run that is killed leaves that
  // record, which the index of lessons shows as killed once the process is gone.
  fs::remove(out_ / "outputs.json", error);
  fs::remove(out_ / "index.html", error);
}

// The folder above holds an index of lessons when this folder is named after the
// lesson, as out/<lesson> is: a folder given by --out under another name may sit
// anywhere (/tmp), and no index is written beside it.
std::optional<fs::path> Lesson::index_folder() const {
  const fs::path folder = fs::absolute(out_).lexically_normal();
  const fs::path named = folder.has_filename() ? folder : folder.parent_path();
  if (named.filename() != name_) return std::nullopt;
  return named.parent_path();
}

int Lesson::run(int argc, const char* const* argv, const std::function<void()>& body) {
  command_.assign(argv, argv + argc);
  bool started = false;
  std::string status = "complete";
  int code = 0;
  try {
    if (!options_.parse(argc, argv)) return 0;
    for (const auto& check : checks_) check();
    prepare_folder();
    started = true;
    write_record("running");
    if (const auto index = index_folder()) update_lessons_index(*index);
    body();
    check_outputs();
  } catch (...) {
    code = report_failure(name_, status);
  }
  if (started) {
    // The record first: the pages are made from it. A failure here after a failure
    // in the body adds no second line.
    for (const auto& write : {&Lesson::write_record, &Lesson::write_pages}) {
      try {
        (this->*write)(status);
      } catch (const std::exception& e) {
        if (code == 0) std::cerr << name_ << ": error: " << printable(e.what()) << '\n';
        if (code == 0) code = 1;
      }
    }
  }
  return code;
}

void Lesson::check_outputs() const {
  std::error_code error;
  for (const Output& o : outputs_) {
    if (o.file.empty()) continue;
    const auto check = [&](const fs::path& file, std::uintmax_t bytes) {
      if (fs::file_size(out_ / file, error) != bytes || error)
        throw std::runtime_error((out_ / file).string() + " is missing or changed since this run wrote it");
    };
    check(o.file, o.bytes);
    if (!o.linear.empty()) check(o.linear, o.linear_bytes);
  }
}

void Lesson::write_record(const std::string& status) const {
  const std::string json = outputs_json(name_, command_, status, outputs_, this_process());
  write_atomically(out_ / "outputs.json", [&](std::ostream& out) { out << json; });
}

void Lesson::write_pages(const std::string& status) const {
  const std::optional<fs::path> index = index_folder();
  const std::string page = report_page(
      {name_, options_.summary(), status, command_, index.has_value(), out_, lesson_guide(name_)}, outputs_);
  write_atomically(out_ / "index.html", [&](std::ostream& out) { out << page; });
  if (index) update_lessons_index(*index);
}

void Lesson::picture(const Image& radiance, const std::string& stem, const std::string& caption, const View& view,
                     double exposure, const Image* shown) {
  write_png(shown ? *shown : radiance, path(stem + ".png"), exposure);
  write_pfm(radiance, path(stem + ".pfm"));
  Output o = output(OutputKind::Picture, caption, stem + ".png");
  o.bytes = fs::file_size(path(stem + ".png"));
  o.linear = stem + ".pfm";
  o.linear_bytes = fs::file_size(path(stem + ".pfm"));
  o.exposure = exposure;
  o.view = view;
  outputs_.push_back(std::move(o));
}

void Lesson::diagram(const Image& image, const std::string& stem, const std::string& caption, double exposure) {
  file(stem + ".png", OutputKind::Diagram, caption, [&](const fs::path& p) { write_png(image, p, exposure); });
  outputs_.back().width = image.width;
  outputs_.back().height = image.height;
}

void Lesson::diagram(const Image& image, const std::string& stem, const std::string& caption,
                     const ColourScale& scale) {
  diagram(image, stem, caption);
  outputs_.back().colour_scale = scale;
}

void Lesson::diagram(const MatrixChart& chart, const std::string& stem, const std::string& caption,
                     const ColourScale& scale) {
  const MatrixSvg svg = matrix_svg(chart);
  file(stem + ".svg", OutputKind::Diagram, caption, [&](const fs::path& p) {
    write_atomically(p, [&](std::ostream& out) { out << svg.text; });
  });
  outputs_.back().width = svg.width;
  outputs_.back().height = svg.height;
  outputs_.back().colour_scale = scale;
}

void Lesson::table(const Table& table, const std::string& stem) {
  table.print();
  file(stem + ".csv", OutputKind::Table, table.title(), [&](const fs::path& p) { table.write_csv(p); });
  outputs_.back().table = table.text();
}

void Lesson::chart(const Chart& chart, const std::string& stem) {
  file(stem + ".svg", OutputKind::Chart, chart.title, [&](const fs::path& p) { write_svg(chart, p); });
}

void Lesson::file(const std::string& name, OutputKind kind, const std::string& caption,
                  const std::function<void(const fs::path&)>& write) {
  write(path(name));
  record(name, kind, caption);
}

void Lesson::viewer(const std::string& caption, const std::function<void(const fs::path&)>& write_data) {
  for (const Output& o : outputs_)
    if (o.kind == OutputKind::Viewer) throw std::logic_error("a lesson has one viewer: viewer.html is written already");
  file("viewer_data.js", OutputKind::Data, "the data the viewer shows", write_data);
  for (const std::string& name : viewer_asset_names()) {
    const std::string_view contents = page_asset(name);
    const OutputKind kind = name == "viewer.html" ? OutputKind::Viewer : OutputKind::Page;
    file(name, kind, kind == OutputKind::Viewer ? caption : "copied from docs/viewer/",
         [&](const fs::path& p) { write_atomically(p, [&](std::ostream& out) { out << contents; }); });
  }
}

void Lesson::record(const fs::path& file, OutputKind kind, const std::string& caption) {
  // Names inside the folder are kept relative to it, whichever way they were given.
  const fs::path inside = file.lexically_relative(out_);
  const fs::path relative = !inside.empty() && *inside.begin() != ".." ? inside : file;
  Output o = output(kind, caption, relative);
  o.bytes = fs::file_size(out_ / relative);
  outputs_.push_back(std::move(o));
}

void Lesson::say(const std::string& line) {
  std::cout << line << '\n' << std::flush;
  outputs_.push_back(output(OutputKind::Text, line, {}));
}

int run_lesson(const std::string& name, const std::function<int()>& body) {
  try {
    return body();
  } catch (...) {
    std::string status;
    return report_failure(name, status);
  }
}

}  // namespace gi
