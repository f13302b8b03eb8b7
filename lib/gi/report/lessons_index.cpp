#include "gi/report/lessons_index.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "gi/core/atomic_file.hpp"
#include "gi/core/platform/folder_lock.hpp"
#include "gi/report/lesson_guide.hpp"
#include "gi/report/page_assets.hpp"
#include "gi/report/report_page.hpp"
#include "gi/report/run_process.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;

// Records are small (a few kB); anything far larger is not one of ours.
constexpr std::uintmax_t largest_record = 16 << 20;

struct LessonRow {
  std::string folder, lesson, status, problem;
  RunProcess process;
  bool recorded = false, viewer = false, page = false;
};

LessonRow read_row(const fs::path& folder) {
  LessonRow row;
  row.folder = folder.filename().string();
  row.recorded = true;
  row.page = fs::exists(folder / "index.html");
  const fs::path record = folder / "outputs.json";
  std::error_code error;
  if (fs::file_size(record, error) > largest_record || error) {
    row.problem = "outputs.json is too large to be a lesson's record";
    return row;
  }
  std::ifstream in(record);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  try {
    row.lesson = json.at("lesson").get<std::string>();
    row.status = json.at("status").get<std::string>();
    if (json.contains("process"))
      row.process = {json.at("process").at("id").get<long>(), json.at("process").at("started").get<std::string>()};
    for (const nlohmann::json& o : json.at("outputs")) row.viewer = row.viewer || o.at("kind") == "viewer";
  } catch (const nlohmann::json::exception&) {
    row.problem = json.is_discarded() ? "outputs.json is not valid JSON" : "outputs.json is not a lesson's record";
  }
  return row;
}

// What the index says of a run: its record's status, but a record still saying
// "running" whose process has gone was killed before it could say anything else.
std::string shown_status(const LessonRow& row) {
  if (!row.recorded) return "not run yet";
  if (row.status == "running" && !still_running(row.process)) return "killed before it finished: run it again";
  return row.status;
}

// "exercises/lab01/README.md" -> "lab 1".
std::string lab_name(const std::string& lab) {
  const std::size_t start = lab.find("lab"), end = lab.find('/', start);
  std::string number = lab.substr(start + 3, end - start - 3);
  while (number.size() > 1 && number[0] == '0') number.erase(0, 1);
  return "lab " + number;
}

std::string status_class(const std::string& status) {
  if (status == "complete") return "complete";
  if (status == "running" || status == "not run yet") return "pending";
  return "failed";
}

}  // namespace

std::string lessons_index_page(const fs::path& folder) {
  // Every lesson of the course (the docs compiled in), then any other folder holding
  // a record, in folder order.
  std::vector<LessonRow> rows;
  for (const PageAsset& doc : doc_openings()) {
    LessonRow row;
    row.folder = doc.name.substr(0, doc.name.size() - 3);  // "01_rays.md"
    row.lesson = row.folder;
    rows.push_back(row);
  }
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    if (!entry.is_directory(error) || !fs::exists(entry.path() / "outputs.json", error)) continue;
    LessonRow row = read_row(entry.path());
    const auto same = std::find_if(rows.begin(), rows.end(), [&](const LessonRow& r) { return r.folder == row.folder; });
    if (same != rows.end()) *same = row;
    else rows.push_back(row);
  }
  std::sort(rows.begin(), rows.end(), [](const LessonRow& a, const LessonRow& b) { return a.folder < b.folder; });

  std::ostringstream os;
  os << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>gi-workbench lessons</title>\n"
     << "<style>\n" << page_asset("report.css") << "</style>\n</head>\n<body>\n<h1>The lessons</h1>\n"
     << "<p class=\"summary\">Global illumination, ray tracing and radiosity, one lesson at a time: what each shows, "
     << "whether it has run here (" << html_escape(fs::absolute(folder).lexically_normal().string())
     << "), and its chapter and lab.</p>\n";
  if (fs::is_regular_file(folder / "book" / "index.html", error))
    os << "<p class=\"links\"><a class=\"book\" href=\"book/index.html\">The course book: every chapter</a></p>\n";
  // The WebAssembly build's live pages (docs/live/make_live.py), where they are made.
  if (fs::is_regular_file(folder / "live" / "index.html", error))
    os << "<p class=\"links\"><a class=\"live\" href=\"live/index.html\">Every lesson live in the browser</a></p>\n";
  if (rows.empty()) os << "<p>No lesson has run here yet.</p>\n";
  else
    os << "<div class=\"table\"><table class=\"contents\">\n<thead><tr><th>lesson</th><th>what it shows</th>"
       << "<th>status</th><th>chapter</th><th>lab</th></tr></thead>\n<tbody>\n";
  for (const LessonRow& r : rows) {
    const std::string base = html_escape(url_path(r.folder)) + "/";
    const std::optional<LessonGuide> guide = lesson_guide(r.lesson.empty() ? r.folder : r.lesson);
    const std::string name = html_escape(guide ? guide->title : r.lesson.empty() ? r.folder : r.lesson);
    os << "<tr><td>" << (r.page ? "<a href=\"" + base + "index.html\">" + name + "</a>" : name)
       << (r.viewer && r.page ? "<br><a class=\"viewer-link\" href=\"" + base + "viewer.html\">viewer</a>" : "")
       << "</td><td>" << (guide ? html_escape(first_sentence(guide->shows)) : "") << "</td>";
    if (!r.problem.empty()) {
      os << "<td class=\"failed\">" << html_escape(r.problem) << "</td>";
    } else {
      const std::string status = shown_status(r);
      os << "<td class=\"" << status_class(status) << "\">" << html_escape(status) << "</td>";
    }
    // The chapter as a page where the book has made one (docs/book/), else its Markdown.
    const std::string chapter = !guide ? ""
                                : fs::is_regular_file(folder / r.folder / "chapter.html", error)
                                    ? base + "chapter.html"
                                    : html_escape(source_link(folder, guide->doc));
    os << "<td>" << (guide ? "<a class=\"doc\" href=\"" + chapter + "\">" +
                                 html_escape(guide->doc.substr(5)) + "</a>"
                           : "")
       << "</td><td>"
       << (guide && !guide->lab.empty()
               ? "<a class=\"lab\" href=\"" + html_escape(source_link(folder, guide->lab)) + "\">" +
                     html_escape(lab_name(guide->lab)) + "</a>"
               : "")
       << "</td></tr>\n";
  }
  if (!rows.empty()) os << "</tbody>\n</table></div>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

void update_lessons_index(const fs::path& folder) {
  const platform::FolderLock lock(folder);
  const std::string page = lessons_index_page(folder);
  write_atomically(folder / "index.html", [&](std::ostream& out) { out << page; });
}

}  // namespace gi
