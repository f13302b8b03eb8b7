#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace gi {

// The browser pages' static files, kept in docs/viewer/ and compiled into the
// library (cmake/EmbedFiles.cmake), so that a lesson copies them next to the files
// it writes and its pages open with file:// alone, wherever the lesson runs.
struct PageAsset {
  std::string name;           // "viewer.html", "report.css" ...
  std::string_view contents;  // the file's bytes
};
const std::vector<PageAsset>& page_assets();

// The asset called `name`; throws std::out_of_range naming it when there is none.
std::string_view page_asset(const std::string& name);

// The names of the interactive viewer's files (viewer.html and what it loads).
std::vector<std::string> viewer_asset_names();

}  // namespace gi
