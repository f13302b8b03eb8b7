#include "gi/report/report_page.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include "gi/image/diff.hpp"

#include "gi/report/chart.hpp"
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

int shown_width(int width) {
  if (width <= 0) return 0;
  const int factor = std::max(1, std::min(1100 / width, (320 + width - 1) / width));
  return width * factor;
}

std::string source_link(const std::filesystem::path& folder, const std::string& relative) {
  // Both made absolute: a source tree named without a drive (as a cross build run by
  // Wine names it) and a folder with one are then on the same drive.
  std::error_code error;
  const std::filesystem::path file = std::filesystem::absolute(source_file(relative), error).lexically_normal();
  const std::filesystem::path from = std::filesystem::absolute(folder, error).lexically_normal();
  const std::filesystem::path link = file.lexically_relative(from);
  return url_path((link.empty() ? file : link).generic_string());
}

std::string chapter_link(const std::filesystem::path& folder, const std::string& doc) {
  std::error_code error;
  if (std::filesystem::is_regular_file(folder / "chapter.html", error)) return "chapter.html";
  return source_link(folder, doc);
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
  os << "<div class=\"table\"><table>\n<caption>" << html_escape(o.caption) << " <span class=\"file\">" << link(o.file)
     << "</span></caption>\n";
  if (!o.table) {
    os << "</table></div>\n";
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
  os << "</tbody>\n</table></div>\n";
}

// Tick values for a colour bar over [a, b] (either order): steps of {1, 2, 5} x 10^k
// giving at most five intervals, or on a log scale the powers of ten between.
std::vector<double> bar_ticks(double a, double b, bool log) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  std::vector<double> ticks;
  if (!(hi > lo)) return ticks;
  if (log) {
    for (int e = static_cast<int>(std::ceil(std::log10(lo) - 1e-9)); e <= std::floor(std::log10(hi) + 1e-9); ++e)
      ticks.push_back(power_of_ten(e));
    return ticks;
  }
  const double raw = (hi - lo) / 5, decade = power_of_ten(static_cast<int>(std::floor(std::log10(raw))));
  double step = 10 * decade;
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) {
      step = m * decade;
      break;
    }
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

// A colour bar's value, short: 0.25, 94, 1.27e-4 (no leading zeros in the exponent).
std::string short_number(double v) {
  if (v == 0 || (std::abs(v) >= 1e-3 && std::abs(v) < 1e5)) return number(v, 3);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  std::string text = buffer;
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(exponent[0] == '-' || exponent[0] == '+' ? 1 : 0);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

std::string tick_text(double v, bool log) {
  if (!log) return short_number(v);
  const int e = static_cast<int>(std::lround(std::log10(v)));
  if (std::abs(v - power_of_ten(e)) > 1e-9 * v) return short_number(v);
  return "10<sup>" + std::to_string(e) + "</sup>";
}

// The colour bar under a false-colour picture: the ramp from black (the scale's lo,
// left) to red (hi, right), the values along it and what they measure.
void colour_bar_html(std::ostream& os, const ColourScale& scale) {
  const double lo = scale.log10 ? std::log10(scale.lo) : scale.lo, hi = scale.log10 ? std::log10(scale.hi) : scale.hi;
  std::string gradient;
  for (const Pixel& p : false_colour_stops)
    gradient += (gradient.empty() ? "" : ", ") + std::string("rgb(") + std::to_string(std::lround(255 * p.x)) + " " +
                std::to_string(std::lround(255 * p.y)) + " " + std::to_string(std::lround(255 * p.z)) + ")";
  os << "<div class=\"colour-bar\" title=\""
     << html_escape(false_colour_map_name) << "\">\n<div class=\"ramp\" style=\"background: linear-gradient(to right, "
     << gradient << ")\"></div>\n<div class=\"ticks\">";
  // The ends always, and the round values between that do not crowd them.
  std::vector<std::pair<double, double>> ticks = {{0.0, scale.lo}, {1.0, scale.hi}};
  if (std::isfinite(lo) && std::isfinite(hi) && hi != lo)
    for (double t : bar_ticks(scale.lo, scale.hi, scale.log10)) {
      const double f = ((scale.log10 ? std::log10(t) : t) - lo) / (hi - lo);
      if (f > 0.15 && f < 0.85) ticks.push_back({f, t});
    }
  std::sort(ticks.begin(), ticks.end());
  for (const auto& [f, v] : ticks) {
    const char* align = f < 0.01 ? "start" : f > 0.99 ? "end" : "middle";
    os << "<span class=\"" << align << "\" style=\"left: " << number(100 * f, 4) << "%\">" << tick_text(v, scale.log10)
       << "</span>";
  }
  os << "</div>\n<div class=\"quantity\">" << html_escape(scale.quantity) << (scale.log10 ? " (log scale)" : "")
     << "</div>\n</div>\n";
}

// A picture or diagram in a gallery: shown at shown_width, the caption beneath, how
// it was made folded away.
void figure_html(std::ostream& os, const Output& o, int width, int height, const std::string& details) {
  const int shown = shown_width(width);
  // In a gallery, figures share a row: each may shrink to 200 px and grows to the
  // size it is shown at. A strip of pictures set side by side (2.5 times as wide as
  // high, or more) has a row of its own: its parts are what is compared.
  std::string classes = o.colour_scale ? "false-colour" : "";
  if (height > 0 && 2 * width >= 5 * height) classes += classes.empty() ? "strip" : " strip";
  os << "<figure" << (classes.empty() ? "" : " class=\"" + classes + "\"") << " style=\"max-width: "
     << std::max(shown, 240) << "px\"><img src=\"" << html_escape(url_path(o.file.generic_string())) << "\" alt=\"" << html_escape(o.caption)
     << "\"";
  if (width > 0) os << " width=\"" << shown << "\" height=\"" << (shown / width) * height << "\"";
  os << ">\n";
  if (o.colour_scale) colour_bar_html(os, *o.colour_scale);
  os << "<figcaption>" << html_escape(o.caption) << " <details><summary>" << link(o.file) << "</summary>" << details
     << "</details></figcaption></figure>\n";
}

bool in_gallery(const Output& o) { return o.kind == OutputKind::Picture || o.kind == OutputKind::Diagram; }

void output_html(std::ostream& os, const Output& o) {
  switch (o.kind) {
    case OutputKind::Text: break;  // gathered into <pre> blocks by the caller
    case OutputKind::Table: table_html(os, o); break;
    case OutputKind::Picture: figure_html(os, o, o.view.width, o.view.height, picture_details(o)); break;
    case OutputKind::Diagram:
      figure_html(os, o, o.width, o.height,
                  o.colour_scale ? "false colour: " + html_escape(false_colour_map_name) : std::string("a diagram"));
      break;
    case OutputKind::Chart:
      os << "<figure class=\"chart\"><img src=\"" << html_escape(url_path(o.file.generic_string())) << "\" alt=\""
         << html_escape(o.caption) << "\"><figcaption>" << html_escape(o.caption) << " <span class=\"file\">"
         << link(o.file) << "</span></figcaption></figure>\n";
      break;
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

// The top of the page: what the lesson shows, where to read and practise it, and the
// viewer, each one click away.
void header_html(std::ostream& os, const RunSummary& run, const std::vector<Output>& outputs) {
  if (run.in_index) os << "<nav><a href=\"../index.html\">all lessons</a></nav>\n";
  const LessonGuide* guide = run.guide ? &*run.guide : nullptr;
  os << "<h1>" << html_escape(guide ? guide->title : run.lesson) << "</h1>\n<section class=\"shows\">\n"
     << "<h2>What this shows</h2>\n<p>" << (guide ? markdown_inline_html(guide->shows) : html_escape(run.summary))
     << "</p>\n</section>\n<p class=\"links\">";
  if (guide) {
    os << "<a class=\"doc\" href=\"" << html_escape(chapter_link(run.folder, guide->doc)) << "\">Read the chapter: "
       << html_escape(guide->doc) << "</a>";
    if (!guide->lab.empty())
      os << " <a class=\"lab\" href=\"" << html_escape(source_link(run.folder, guide->lab)) << "\">The lab: "
         << html_escape(guide->lab) << "</a>";
  }
  for (const Output& o : outputs)
    if (o.kind == OutputKind::Viewer)
      os << " <a class=\"viewer-link\" href=\"" << html_escape(url_path(o.file.generic_string()))
         << "\">Open the interactive viewer</a>";
  // The live page, where the WebAssembly build has made one (docs/live/make_live.py).
  std::error_code error;
  if (std::filesystem::is_regular_file(run.folder / "live.html", error))
    os << " <a class=\"live-link\" href=\"live.html\">Run it in the browser</a>";
  const bool complete = run.status == "complete";
  os << "</p>\n<p class=\"status " << (complete ? "complete" : "failed") << "\">" << html_escape(run.status) << "</p>\n"
     << "<p class=\"command\"><code>" << html_escape(shell_command(run.command)) << "</code></p>\n";
}

}  // namespace

std::string report_page(const RunSummary& run, const std::vector<Output>& outputs) {
  std::ostringstream os;
  os << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(run.lesson)
     << "</title>\n<style>\n" << page_asset("report.css") << "</style>\n</head>\n<body>\n";
  header_html(os, run, outputs);
  // Consecutive text lines are one block, as they were on the terminal; consecutive
  // pictures one gallery, side by side, to be compared.
  enum class Run { None, Text, Gallery } open = Run::None;
  for (const Output& o : outputs) {
    const Run kind = o.kind == OutputKind::Text ? Run::Text : in_gallery(o) ? Run::Gallery : Run::None;
    if (kind != open && open == Run::Text) os << "</pre>\n";
    if (kind != open && open == Run::Gallery) os << "</div>\n";
    if (kind != open && kind == Run::Text) os << "<pre>";
    if (kind != open && kind == Run::Gallery) os << "<div class=\"gallery\">\n";
    open = kind;
    if (kind == Run::Text) os << html_escape(o.caption) << '\n';
    else output_html(os, o);
  }
  if (open == Run::Text) os << "</pre>\n";
  if (open == Run::Gallery) os << "</div>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

}  // namespace gi
