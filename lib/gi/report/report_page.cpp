#include "gi/report/report_page.hpp"

#include <cstdio>
#include <sstream>

#include "gi/report/page_assets.hpp"

namespace gi {

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string url_path(const std::string& file) {
  std::string out;
  for (unsigned char c : file) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (plain) {
      out += static_cast<char>(c);
    } else {
      char code[4];
      std::snprintf(code, sizeof code, "%%%02X", c);
      out += code;
    }
  }
  return out;
}

std::string shell_command(const std::vector<std::string>& command) {
  std::string out;
  for (const std::string& arg : command) {
    if (!out.empty()) out += ' ';
    const bool plain = !arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789-_./=:,+@%") == std::string::npos;
    if (plain) {
      out += arg;
      continue;
    }
    out += '\'';
    for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

namespace {

std::string number(double v, int digits = 4) {
  std::ostringstream os;
  os.precision(digits);
  os << v;
  return os.str();
}

std::string point(const vec3& p) { return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")"; }

std::string link(const std::filesystem::path& file) {
  const std::string name = file.generic_string();
  return "<a href=\"" + html_escape(url_path(name)) + "\">" + html_escape(name) + "</a>";
}

// A picture's caption says how it was made: exposure, size, sampling, camera, and
// where its linear radiance is.
std::string picture_details(const Output& o) {
  const View& v = o.view;
  return "exposure " + number(o.exposure) + "; " + std::to_string(v.width) + " &times; " + std::to_string(v.height) +
         ", " + html_escape(v.pixel_samples) + "; camera at " + point(v.camera.eye) + " looking at " +
         point(v.camera.look_at) + ", " + number(v.camera.vertical_fov) + "&deg; vertical field of view; linear radiance: " +
         link(o.linear);
}

void table_html(std::ostream& os, const Output& o) {
  os << "<table>\n<caption>" << html_escape(o.caption) << " <span class=\"file\">" << link(o.file)
     << "</span></caption>\n";
  if (!o.table) {
    os << "</table>\n";
    return;
  }
  const TableText& t = *o.table;
  os << "<thead><tr>";
  for (std::size_t c = 0; c < t.header.size(); ++c)
    os << (t.numeric[c] ? "<th class=\"number\">" : "<th>") << html_escape(t.header[c]) << "</th>";
  os << "</tr></thead>\n<tbody>\n";
  for (const auto& row : t.rows) {
    os << "<tr>";
    for (std::size_t c = 0; c < row.size(); ++c)
      os << (t.numeric[c] ? "<td class=\"number\">" : "<td>") << html_escape(row[c]) << "</td>";
    os << "</tr>\n";
  }
  os << "</tbody>\n</table>\n";
}

void figure_html(std::ostream& os, const Output& o, const std::string& details, int width = 0, int height = 0) {
  os << "<figure><img src=\"" << html_escape(url_path(o.file.generic_string())) << "\" alt=\""
     << html_escape(o.caption) << "\"";
  if (width > 0) os << " width=\"" << width << "\" height=\"" << height << "\"";
  os << "><figcaption>" << html_escape(o.caption) << " <span class=\"file\">" << details << "</span></figcaption></figure>\n";
}

void output_html(std::ostream& os, const Output& o) {
  switch (o.kind) {
    case OutputKind::Text: break;  // gathered into <pre> blocks by the caller
    case OutputKind::Table: table_html(os, o); break;
    case OutputKind::Picture: figure_html(os, o, link(o.file) + "; " + picture_details(o), o.view.width, o.view.height); break;
    case OutputKind::Diagram:
    case OutputKind::Chart: figure_html(os, o, link(o.file)); break;
    case OutputKind::Viewer:
      os << "<p class=\"viewer\"><a href=\"" << html_escape(url_path(o.file.generic_string()))
         << "\">Open the interactive viewer</a> " << html_escape(o.caption) << "</p>\n";
      break;
    case OutputKind::Mesh: os << "<p class=\"file\">Mesh " << link(o.file) << ": " << html_escape(o.caption) << "</p>\n"; break;
    case OutputKind::Cache: os << "<p class=\"file\">Cache " << link(o.file) << ": " << html_escape(o.caption) << "</p>\n"; break;
    case OutputKind::Data: os << "<p class=\"file\">Data " << link(o.file) << ": " << html_escape(o.caption) << "</p>\n"; break;
    case OutputKind::Page: break;  // a viewer's script or style sheet: not news on its own
  }
}

}  // namespace

std::string report_page(const RunSummary& run, const std::vector<Output>& outputs) {
  std::ostringstream os;
  const bool complete = run.status == "complete";
  os << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(run.lesson)
     << "</title>\n<style>\n" << page_asset("report.css") << "</style>\n</head>\n<body>\n";
  if (run.in_index) os << "<nav><a href=\"../index.html\">all lessons</a></nav>\n";
  os << "<h1>" << html_escape(run.lesson) << "</h1>\n<p class=\"summary\">" << html_escape(run.summary) << "</p>\n"
     << "<p class=\"command\"><code>" << html_escape(shell_command(run.command)) << "</code></p>\n"
     << "<p class=\"status " << (complete ? "complete" : "failed") << "\">" << html_escape(run.status) << "</p>\n";
  // Consecutive text lines are one block, as they were on the terminal.
  bool in_text = false;
  for (const Output& o : outputs) {
    const bool text = o.kind == OutputKind::Text;
    if (text && !in_text) os << "<pre>";
    if (!text && in_text) os << "</pre>\n";
    in_text = text;
    if (text) os << html_escape(o.caption) << '\n';
    else output_html(os, o);
  }
  if (in_text) os << "</pre>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

}  // namespace gi
