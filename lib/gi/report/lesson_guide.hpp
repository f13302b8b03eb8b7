#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gi/report/page_assets.hpp"

namespace gi {

// What the report pages say about a lesson, read from the opening of its doc
// (docs/NN_topic.md), the one place it is written:
//
//   # 01 — Rays: where does a ray meet a sphere, where a plane?
//
//   Lesson `01_rays` · lab [1](../exercises/lab01/README.md) · source ...
//
//   What this lesson shows, one paragraph: its first sentence is the line the
//   index of lessons prints.
struct LessonGuide {
  std::string lesson;  // "01_rays"
  std::string title;   // the doc's heading
  std::string doc;     // "docs/01_rays.md", from the source tree's root
  std::string lab;     // "exercises/lab01/README.md", or empty: the lesson has no lab
  std::string shows;   // the opening paragraph, in the doc's markdown
};

// Reads the opening of a doc called `file_name` (its first bytes are enough); throws
// std::invalid_argument naming the line that is missing.
LessonGuide read_guide(std::string_view text, const std::string& file_name);

// The guide of a lesson from the docs compiled into the library (doc_openings), or
// nothing for a program that has no doc of its own (14_make_reference).
std::optional<LessonGuide> lesson_guide(const std::string& lesson);
const std::vector<PageAsset>& doc_openings();  // made by cmake/EmbedFiles.cmake

// A file of the source tree the library was built from, "docs/01_rays.md" -> an
// absolute path.
std::filesystem::path source_file(const std::string& relative);

// The doc's inline markdown as HTML: `code`, **strong**, *emphasis*, and a link's
// text without its target (targets are relative to docs/, not to a page).
std::string markdown_inline_html(const std::string& markdown);
// Its first sentence as plain text: up to the first ". " before a capital letter.
std::string first_sentence(const std::string& markdown);

}  // namespace gi
