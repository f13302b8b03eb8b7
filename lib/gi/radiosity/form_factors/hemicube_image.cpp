#include "gi/radiosity/form_factors/hemicube_image.hpp"

namespace gi {

Image unfold_hemicube(int resolution, const std::function<Pixel(HemicubeFace, int, int)>& colour) {
  const int res = resolution, h = res / 2;
  Image image(2 * res, 2 * res);
  for (int r = 0; r < res; ++r)
    for (int c = 0; c < res; ++c) image.at(h + c, h + res - 1 - r) = colour(HemicubeFace::Top, c, r);
  for (int r = 0; r < h; ++r)      // r: height above the horizon
    for (int c = 0; c < res; ++c) {  // c: across the face
      image.at(h + res + h - 1 - r, h + res - 1 - c) = colour(HemicubeFace::PlusX, c, r);
      image.at(r, h + res - 1 - c) = colour(HemicubeFace::MinusX, c, r);
      image.at(h + c, r) = colour(HemicubeFace::PlusY, c, r);
      image.at(h + c, h + res + h - 1 - r) = colour(HemicubeFace::MinusY, c, r);
    }
  return image;
}

}  // namespace gi
