#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gi/report/table.hpp"
#include "gi/scene/camera.hpp"

namespace gi {

// JSON's spelling of a string (quotes, backslashes and control characters escaped)
// and of a number (the shortest text that reads back as the same double; JSON has no
// NaN or infinity: null).
std::string json_string(const std::string& text);
std::string json_number(double v);

// How a picture was seen, so that an outside renderer can make the same one: the
// pinhole camera (camera.hpp: pixel (x, y) spans [x, x + 1] x [y, y + 1] of the image
// plane, row 0 at the top), the image size, and how each pixel was sampled.
struct View {
  Camera camera;
  int width = 0, height = 0;
  std::string pixel_samples;  // "one eye ray through the pixel centre", "4 x 4 jittered, box filter" ...
};

// How a false-colour diagram maps values to colours: the ramp of image/diff.hpp's
// false_colour, black at `lo`, red at `hi` (lo above hi gives a bar that runs
// downwards, as "near is red" does), linear in the quantity or, with `log10`, in its
// logarithm (lo and hi are then the quantity's own values, 1e-6 and 0.1, not their
// exponents). `quantity` names what the colour shows, with its unit: the report page
// draws the bar beneath the picture with it.
struct ColourScale {
  double lo = 0, hi = 1;
  std::string quantity;
  bool log10 = false;
};

// What a lesson printed and wrote, in order: the record a report page is built from.
enum class OutputKind {
  Text,     // a line printed on stdout
  Table,    // printed on stdout, and written as CSV
  Picture,  // a rendered picture: PNG for the eye, PFM beside it with the linear radiance
  Diagram,  // a PNG that is not a view of radiance: false colour, heat maps, crops
  Chart,    // SVG
  Mesh,     // PLY
  Cache,    // a cached result the lesson read or made (a reference image)
  Viewer,   // an interactive page (viewer.html, docs/viewer/) that shows a Data file
  Data,     // what an interactive page reads (viewer_data.js)
  Page,     // a file a page needs: a script or a style sheet copied from docs/viewer/
};
std::string kind_name(OutputKind kind);  // "text", "table", "picture" ...

struct Output {
  OutputKind kind = OutputKind::Text;
  std::string caption;          // a table's title, a picture's subject, a text line
  std::filesystem::path file;   // relative to the output folder; empty for text
  std::uintmax_t bytes = 0;     // as written, checked again when the lesson ends
  std::filesystem::path linear; // Picture: the PFM beside the PNG
  std::uintmax_t linear_bytes = 0;
  double exposure = 1;          // Picture: the PNG shows clamp(exposure * radiance)
  View view;                    // Picture
  int width = 0, height = 0;    // Diagram: the PNG's size in pixels (a Picture's is in its view)
  std::optional<ColourScale> colour_scale;  // Diagram in false colour
  std::optional<TableText> table;  // Table: its cells as printed, for the report page (not in the JSON)
};

// Who writes a lesson's folder while it runs: the process id and a stamp of when that
// process started (run_process.hpp), so that a later reader can tell a run still going
// from one that was killed, whose id the system may since have given to another.
struct RunProcess {
  long id = 0;
  std::string started;
};

// The record as JSON (outputs.json in the lesson's folder): the lesson, its command
// line, its status -- "running" from the start (with the process), then "complete",
// or the error that stopped it -- and every output.
std::string outputs_json(const std::string& lesson, const std::vector<std::string>& command, const std::string& status,
                         const std::vector<Output>& outputs, const RunProcess& process = {});

}  // namespace gi
