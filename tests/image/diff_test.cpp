#include "gi/image/diff.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

TEST(Diff, BlackWhereEqualRedAtTheLargestDifference) {
  gi::Image a(3, 1, gi::Pixel(0.5f)), b = a;
  b.at(2, 0) = gi::Pixel(0.9f);
  const gi::Image d = gi::difference_image(a, b);
  EXPECT_EQ(d.at(0, 0), gi::Pixel(0));
  EXPECT_EQ(d.at(2, 0), gi::Pixel(1, 0, 0));
  // The value at red, for the picture's colour bar: |0.9 - 0.5| in every channel.
  EXPECT_FLOAT_EQ(gi::largest_difference(a, b), 0.4f);
  EXPECT_EQ(gi::largest_difference(a, a), 0.0);
}

TEST(Diff, FalseColourRamp) {
  const gi::Image img = gi::false_colour({0.0, 0.25, 0.5, 0.75, 1.0, 2.0}, 6, 1, 0.0, 1.0);
  EXPECT_EQ(img.at(0, 0), gi::Pixel(0, 0, 0));
  EXPECT_EQ(img.at(1, 0), gi::Pixel(0, 0, 1));
  EXPECT_EQ(img.at(2, 0), gi::Pixel(0, 1, 0));
  EXPECT_EQ(img.at(3, 0), gi::Pixel(1, 1, 0));
  EXPECT_EQ(img.at(4, 0), gi::Pixel(1, 0, 0));
  EXPECT_EQ(img.at(5, 0), gi::Pixel(1, 0, 0));  // clamped
}

TEST(Diff, CropEnlargeSideBySide) {
  gi::Image img(4, 3);
  img.at(2, 1) = gi::Pixel(1);
  const gi::Image c = gi::crop(img, 2, 1, 2, 2);
  EXPECT_EQ(c.at(0, 0), gi::Pixel(1));
  EXPECT_THROW(gi::crop(img, 3, 0, 2, 1), std::invalid_argument);
  const gi::Image e = gi::enlarge(c, 3);
  EXPECT_EQ(e.width, 6);
  EXPECT_EQ(e.at(2, 2), gi::Pixel(1));
  EXPECT_EQ(e.at(3, 3), gi::Pixel(0));
  const gi::Image s = gi::side_by_side({img, c}, 1, gi::Pixel(0.5f));
  EXPECT_EQ(s.width, 4 + 1 + 2);
  EXPECT_EQ(s.height, 3);
  EXPECT_EQ(s.at(4, 0), gi::Pixel(0.5f));
  EXPECT_EQ(s.at(5, 0), gi::Pixel(1));
  EXPECT_EQ(s.at(5, 2), gi::Pixel(0.5f));  // below the shorter image: gap colour
}

TEST(Diff, ImageGridReadsLeftToRightThenTopToBottom) {
  std::vector<gi::Image> images;
  for (int k = 0; k < 5; ++k) images.emplace_back(2, 3, gi::Pixel(0.1f * static_cast<float>(k + 1)));
  const gi::Image g = gi::image_grid(images, 2, 1, gi::Pixel(1));
  EXPECT_EQ(g.width, 2 + 1 + 2);
  EXPECT_EQ(g.height, 3 * 3 + 2 * 1);  // three rows, the last holding one image
  EXPECT_EQ(g.at(0, 0), images[0].at(0, 0));
  EXPECT_EQ(g.at(3, 0), images[1].at(0, 0));
  EXPECT_EQ(g.at(0, 4), images[2].at(0, 0));
  EXPECT_EQ(g.at(4, 6), images[3].at(1, 2));
  EXPECT_EQ(g.at(1, 8), images[4].at(1, 0));
  EXPECT_EQ(g.at(3, 8), gi::Pixel(1));  // beside the last row's one image: gap colour
  EXPECT_EQ(g.at(0, 3), gi::Pixel(1));  // between rows
  EXPECT_THROW(gi::image_grid(images, 0), std::invalid_argument);
  EXPECT_THROW(gi::image_grid({}, 2), std::invalid_argument);
}
