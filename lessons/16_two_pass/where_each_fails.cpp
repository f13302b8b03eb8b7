// Lesson 16, step 4: crops, side by side, and the gather's difference (where_each_fails.hpp).
#include "where_each_fails.hpp"

#include <algorithm>
#include <string>

#include "gi/image/diff.hpp"

namespace lesson16 {
namespace {

// 4. Where each fails, side by side with the truth, enlarged: squares given as
//    fractions of the picture (they scale with --width).
struct CropPlace {
  std::string stem, caption;
  double x, y;  // the square's top-left corner, fraction of width and height
};

void crops(const Settings& s, const std::vector<Picture>& pictures, const gi::Image& truth, gi::Lesson& lesson) {
  const std::vector<CropPlace> cornell{{"shadow", "the floor between the blocks: their shadows", 0.36, 0.70},
                                       {"corner", "the ceiling by the green wall: the gather's noise", 0.70, 0.10}};
  const std::vector<CropPlace> spheres{{"caustic", "under the glass sphere: the caustic", 0.58, 0.80},
                                       {"mirror", "the mirror sphere", 0.2, 0.55}};
  const std::vector<CropPlace>& places = s.scene == "cornell" ? cornell : spheres;
  const int side = std::min({std::max(8, s.width / 6), s.width, s.height}), factor = std::max(1, 128 / side);
  for (const CropPlace& place : places) {
    std::vector<gi::Image> row;
    const int x = std::min(static_cast<int>(place.x * s.width), s.width - side);
    const int y = std::min(static_cast<int>(place.y * s.height), s.height - side);
    for (const Picture& p : pictures) row.push_back(gi::enlarge(gi::crop(p.radiance, x, y, side, side), factor));
    row.push_back(gi::enlarge(gi::crop(truth, x, y, side, side), factor));
    lesson.diagram(gi::side_by_side(row), s.scene + "_crop_" + place.stem,
                   place.caption + ": ray traced, radiosity, two-pass mesh, two-pass gather, path traced", 2);
  }
}

}  // namespace

void where_each_fails(const Settings& s, const std::vector<Picture>& pictures, const gi::Image& truth,
                      gi::Lesson& lesson) {
  crops(s, pictures, truth, lesson);
  std::vector<gi::Image> row;
  for (const Picture& p : pictures) row.push_back(p.radiance);
  row.push_back(truth);
  lesson.diagram(gi::side_by_side(row), s.scene + "_side_by_side",
                 "ray traced, radiosity, two-pass mesh, two-pass gather, path traced", 2);
  lesson.diagram(gi::difference_image(pictures.back().radiance, truth, 0.1), s.scene + "_gather_difference",
                 "|two-pass with final gather - path traced|, mean over channels: black 0, red 0.1 (radiance)",
                 gi::ColourScale{0, 0.1, "|difference| in radiance, mean over R, G, B"});
}

}  // namespace lesson16
