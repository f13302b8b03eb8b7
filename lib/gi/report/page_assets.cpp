#include "gi/report/page_assets.hpp"

#include <stdexcept>

namespace gi {

std::string_view page_asset(const std::string& name) {
  for (const PageAsset& asset : page_assets())
    if (asset.name == name) return asset.contents;
  throw std::out_of_range("no page asset '" + name + "' (the files of docs/viewer/ are compiled in)");
}

std::vector<std::string> viewer_asset_names() {
  std::vector<std::string> names;
  for (const PageAsset& asset : page_assets())
    if (asset.name.rfind("viewer", 0) == 0) names.push_back(asset.name);
  return names;
}

}  // namespace gi
