#pragma once
#include <string>
#include <vector>

#include "gi/report/outputs.hpp"

namespace gi {

// The report page of one lesson run, index.html in its output folder: everything the
// lesson printed and wrote, in the order it did -- text, tables as HTML tables,
// pictures and charts shown, other files linked -- under its command line and
// status. Static HTML, its style sheet inline (docs/viewer/report.css): it opens
// with file://, fetches nothing from anywhere and runs no script.
struct RunSummary {
  std::string lesson, summary, status;  // status as in outputs.json: "complete", "failed: ..."
  std::vector<std::string> command;     // argv as typed
  bool in_index = false;                // a lessons index in the folder above links back to it
};
std::string report_page(const RunSummary& run, const std::vector<Output>& outputs);

// Text made safe inside HTML elements and attribute values.
std::string html_escape(const std::string& text);
// A file name as a relative URL: bytes other than letters, digits and -._~/ percent-encoded.
std::string url_path(const std::string& file);
// The command line as a POSIX shell would take it back: arguments holding spaces,
// quotes or other special characters are single-quoted.
std::string shell_command(const std::vector<std::string>& command);

}  // namespace gi
