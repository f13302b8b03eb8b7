#include "gi/raytrace/reference.hpp"

#include "gi/image/image_io.hpp"

namespace gi {

Image cached_reference(const World& world, const RenderSettings& settings, const std::filesystem::path& pfm_file) {
  if (std::filesystem::exists(pfm_file)) {
    Image cached = read_pfm(pfm_file);
    if (cached.width == settings.width && cached.height == settings.height) return cached;
  }
  const Image reference = render(world, settings).image;
  write_pfm(reference, pfm_file);
  return reference;
}

}  // namespace gi
