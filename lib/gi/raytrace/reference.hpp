#pragma once
#include <filesystem>

#include "gi/image/image.hpp"
#include "gi/raytrace/render.hpp"

namespace gi {

// A reference image is expensive (hundreds of samples per pixel) and the same on
// every run with the same settings, so it is rendered once and kept: when
// `pfm_file` exists it is read back, otherwise the scene is rendered and written
// there (PFM keeps the linear floats exactly). Name the file after everything
// that changes the picture.
Image cached_reference(const World& world, const RenderSettings& settings, const std::filesystem::path& pfm_file);

}  // namespace gi
