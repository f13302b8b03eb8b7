#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gi/report/lesson_guide.hpp"
#include "gi/report/outputs.hpp"

namespace gi {

// The report page of one lesson run, index.html in its output folder. At the top,
// what the lesson shows (the opening of its doc, lesson_guide.hpp), links to the doc,
// the lab and the viewer, the status and the command line; below, everything the
// lesson printed and wrote, in the order it did: text, tables as HTML tables,
// pictures side by side at a size that can be read (small ones enlarged pixel for
// pixel), false-colour pictures over their colour bars, charts, other files linked.
// Static HTML, its style sheet inline (docs/viewer/report.css): it opens with
// file://, fetches nothing from anywhere and runs no script.
struct RunSummary {
  std::string lesson, summary, status;  // status as in outputs.json: "complete", "failed: ..."
  std::vector<std::string> command;     // argv as typed
  bool in_index = false;                // a lessons index in the folder above links back to it
  std::filesystem::path folder;         // where the page is written: links to the docs start there
  std::optional<LessonGuide> guide;     // the doc's opening; without one the summary stands in
};
std::string report_page(const RunSummary& run, const std::vector<Output>& outputs);

// Text made safe inside HTML elements and attribute values.
std::string html_escape(const std::string& text);
// A file name as a relative URL: bytes other than letters, digits and -._~/ percent-encoded.
std::string url_path(const std::string& file);
// The command line as a POSIX shell would take it back: arguments holding spaces,
// quotes or other special characters are single-quoted.
std::string shell_command(const std::vector<std::string>& command);

// How large a picture of `width` pixels is shown: enlarged by a whole factor (nearest
// neighbour, so every pixel stays a sharp square) until it is at least 320 px wide,
// never past 1100 px.
int shown_width(int width);
// The link from a page in `folder` to a file of the source tree ("docs/01_rays.md"):
// relative when the two share a root, as out/ and docs/ do.
std::string source_link(const std::filesystem::path& folder, const std::string& relative);
// The link from a page in `folder` to a lesson's chapter (guide.doc, "docs/06_x.md"):
// the chapter as a page, chapter.html, where the book (docs/book/make_book.py) has put
// one in that folder, else the Markdown itself.
std::string chapter_link(const std::filesystem::path& folder, const std::string& doc);

}  // namespace gi
