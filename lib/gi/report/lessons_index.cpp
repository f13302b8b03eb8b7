#include "gi/report/lessons_index.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "gi/core/atomic_file.hpp"
#include "gi/core/platform/folder_lock.hpp"
#include "gi/report/page_assets.hpp"
#include "gi/report/report_page.hpp"

namespace gi {

namespace {

namespace fs = std::filesystem;

// Records are small (a few kB); anything far larger is not one of ours.
constexpr std::uintmax_t largest_record = 16 << 20;

struct LessonRow {
  std::string folder, lesson, status, command, problem;
  std::size_t outputs = 0;
  bool viewer = false, page = false;
};

LessonRow read_row(const fs::path& folder) {
  LessonRow row;
  row.folder = folder.filename().string();
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
    row.command = shell_command(json.at("command").get<std::vector<std::string>>());
    for (const nlohmann::json& o : json.at("outputs")) {
      ++row.outputs;
      row.viewer = row.viewer || o.at("kind") == "viewer";
    }
  } catch (const nlohmann::json::exception&) {
    row.problem = json.is_discarded() ? "outputs.json is not valid JSON" : "outputs.json is not a lesson's record";
  }
  return row;
}

}  // namespace

std::string lessons_index_page(const fs::path& folder) {
  std::vector<LessonRow> rows;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.is_directory(error) && fs::exists(entry.path() / "outputs.json", error)) rows.push_back(read_row(entry.path()));
  std::sort(rows.begin(), rows.end(), [](const LessonRow& a, const LessonRow& b) { return a.folder < b.folder; });

  std::ostringstream os;
  os << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>gi-workbench lessons</title>\n"
     << "<style>\n" << page_asset("report.css") << "</style>\n</head>\n<body>\n<h1>Lessons run in " << html_escape(fs::absolute(folder).lexically_normal().string())
     << "</h1>\n";
  if (rows.empty()) os << "<p>No lesson has run here yet.</p>\n";
  else os << "<table>\n<thead><tr><th>lesson</th><th>status</th><th>outputs</th><th>viewer</th><th>command</th></tr></thead>\n<tbody>\n";
  for (const LessonRow& r : rows) {
    const std::string base = html_escape(url_path(r.folder)) + "/";
    const std::string name = html_escape(r.lesson.empty() ? r.folder : r.lesson);
    os << "<tr><td>" << (r.page ? "<a href=\"" + base + "index.html\">" + name + "</a>" : name) << "</td>";
    if (!r.problem.empty()) {
      os << "<td class=\"failed\" colspan=\"4\">" << html_escape(r.problem) << "</td></tr>\n";
      continue;
    }
    os << "<td" << (r.status == "complete" ? "" : " class=\"failed\"") << ">" << html_escape(r.status) << "</td><td>"
       << r.outputs << "</td><td>" << (r.viewer ? "<a href=\"" + base + "viewer.html\">open</a>" : "")
       << "</td><td><code>" << html_escape(r.command) << "</code></td></tr>\n";
  }
  if (!rows.empty()) os << "</tbody>\n</table>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

void update_lessons_index(const fs::path& folder) {
  const platform::FolderLock lock(folder);
  const std::string page = lessons_index_page(folder);
  write_atomically(folder / "index.html", [&](std::ostream& out) { out << page; });
}

}  // namespace gi
