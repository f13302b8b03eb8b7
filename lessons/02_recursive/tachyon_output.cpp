#include "tachyon_output.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>
#include <vector>

#include "gi/core/decimal.hpp"

namespace gi {

namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// The progress meter ends its lines in '\r' to redraw itself on a terminal; a pipe
// sees them all, so '\r' ends a line as '\n' does. Blank lines are dropped.
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find_first_of("\r\n"), text.size());
    if (const std::string_view line = trim(text.substr(0, end)); !line.empty()) lines.push_back(line);
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  return lines;
}

bool mentions_failure(std::string_view line) {
  std::string lower(line);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower.find("fail") != std::string::npos || lower.find("error") != std::string::npos;
}

// Why Tachyon rendered nothing, in its own words: its last line that speaks of a
// failure ("Parser failed due to nonexistent input file: x.dat"), else its last line.
std::string reason(const std::vector<std::string_view>& lines) {
  if (lines.empty()) return "it printed nothing";
  const auto failure = std::find_if(lines.rbegin(), lines.rend(), mentions_failure);
  return "it said \"" + std::string(failure != lines.rend() ? *failure : lines.back()) + "\"";
}

// "0.0971 seconds" -> 0.0971; anything else (no number, no unit, more text) throws.
double seconds_of(std::string_view value, std::string_view line) {
  double seconds = 0;
  const auto [end, error] = read_decimal(value.data(), value.data() + value.size(), seconds);
  const std::string_view unit = trim(value.substr(static_cast<std::size_t>(end - value.data())));
  if (error != std::errc() || unit != "seconds" || !std::isfinite(seconds) || seconds < 0)
    throw TachyonOutputError("tachyon's output: cannot read a time of seconds, not negative, from \"" +
                             std::string(line) + "\"");
  return seconds;
}

}  // namespace

TachyonReport parse_tachyon_output(const std::string& text) {
  constexpr std::string_view time_label = "Ray Tracing Time:", version_label = "Version ";
  TachyonReport report{"", 0};
  int times = 0;
  const std::vector<std::string_view> lines = lines_of(text);
  for (const std::string_view line : lines) {
    if (line.starts_with("Tachyon") && report.version.empty())
      if (const std::size_t at = line.find(version_label); at != std::string_view::npos)
        report.version = trim(line.substr(at + version_label.size()));
    if (line.starts_with(time_label)) {
      report.ray_tracing_seconds = seconds_of(trim(line.substr(time_label.size())), line);
      ++times;
    }
  }
  if (times == 0) throw TachyonOutputError("tachyon rendered nothing (no \"Ray Tracing Time\"): " + reason(lines));
  if (times > 1)
    throw TachyonOutputError("tachyon's output: " + std::to_string(times) +
                             " \"Ray Tracing Time\" lines, expected one render");
  return report;
}

}  // namespace gi
