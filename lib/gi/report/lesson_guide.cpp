#include "gi/report/lesson_guide.hpp"

#include <cctype>
#include <stdexcept>

#include "gi/report/report_page.hpp"

namespace gi {

namespace {

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

bool blank(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

// The text between `open` and `close` after `from` in `line`, or empty.
std::string between(std::string_view line, std::string_view from, char close) {
  const std::size_t at = line.find(from);
  if (at == std::string_view::npos) return "";
  const std::size_t start = at + from.size(), end = line.find(close, start);
  return end == std::string_view::npos ? "" : std::string(line.substr(start, end - start));
}

// Markdown's inline marks, each turned into HTML (html) or dropped (plain text).
std::string render_inline(const std::string& md, bool html) {
  std::string out;
  bool strong = false, em = false;
  for (std::size_t i = 0; i < md.size(); ++i) {
    const char c = md[i];
    if (c == '`') {
      const std::size_t end = md.find('`', i + 1);
      if (end != std::string::npos) {
        const std::string code = md.substr(i + 1, end - i - 1);
        out += html ? "<code>" + html_escape(code) + "</code>" : code;
        i = end;
        continue;
      }
    } else if (c == '*' && i + 1 < md.size() && md[i + 1] == '*') {
      if (html) out += strong ? "</strong>" : "<strong>";
      strong = !strong;
      ++i;
      continue;
    } else if (c == '*') {
      if (html) out += em ? "</em>" : "<em>";
      em = !em;
      continue;
    } else if (c == '[') {  // [text](target): the text alone
      const std::size_t close = md.find("](", i);
      const std::size_t end = close == std::string::npos ? close : md.find(')', close);
      if (end != std::string::npos) {
        out += render_inline(md.substr(i + 1, close - i - 1), html);
        i = end;
        continue;
      }
    }
    out += html ? html_escape(std::string(1, c)) : std::string(1, c);
  }
  if (html && strong) out += "</strong>";
  if (html && em) out += "</em>";
  return out;
}

}  // namespace

LessonGuide read_guide(std::string_view text, const std::string& file_name) {
  const auto fail = [&](const std::string& what) { throw std::invalid_argument("docs/" + file_name + ": " + what); };
  const std::vector<std::string_view> lines = lines_of(text);
  LessonGuide guide;
  guide.doc = "docs/" + file_name;
  if (lines.empty() || lines[0].substr(0, 2) != "# ") fail("the first line is not its title, '# NN — ...'");
  guide.title = std::string(lines[0].substr(2));
  std::size_t i = 1;
  while (i < lines.size() && blank(lines[i])) ++i;
  if (i == lines.size() || lines[i].substr(0, 8) != "Lesson `")
    fail("no line 'Lesson `NN_topic` · lab [N](../exercises/labNN/README.md) · source ...' under the title");
  guide.lesson = between(lines[i], "Lesson `", '`');
  std::string lab = between(lines[i], "lab [", ')');
  if (!lab.empty()) {
    lab = lab.substr(lab.find("](") == std::string::npos ? lab.size() : lab.find("](") + 2);
    if (lab.rfind("../", 0) == 0) lab = lab.substr(3);
    guide.lab = lab;
  }
  ++i;
  while (i < lines.size() && blank(lines[i])) ++i;
  if (i == lines.size() || lines[i][0] == '#')
    fail("no opening paragraph (what the lesson shows) under the line 'Lesson `" + guide.lesson + "` ...'");
  for (; i < lines.size() && !blank(lines[i]); ++i) {
    if (!guide.shows.empty()) guide.shows += ' ';
    guide.shows += lines[i];
  }
  if (i == lines.size()) fail("the opening paragraph does not end within the doc's first part");
  return guide;
}

std::optional<LessonGuide> lesson_guide(const std::string& lesson) {
  for (const PageAsset& doc : doc_openings())
    if (doc.name == lesson + ".md") return read_guide(doc.contents, doc.name);
  return std::nullopt;
}

std::filesystem::path source_file(const std::string& relative) { return std::filesystem::path(GI_SOURCE_DIR) / relative; }

std::string markdown_inline_html(const std::string& markdown) { return render_inline(markdown, true); }

std::string first_sentence(const std::string& markdown) {
  const std::string plain = render_inline(markdown, false);
  for (std::size_t at = plain.find(". "); at != std::string::npos; at = plain.find(". ", at + 1))
    if (at + 2 < plain.size() && std::isupper(static_cast<unsigned char>(plain[at + 2]))) return plain.substr(0, at + 1);
  return plain;
}

}  // namespace gi
