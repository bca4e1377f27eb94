// The crop every isolated object and texture-target screenshot goes through, against hand-worked squares.
#include <catch2/catch.hpp>

#include "matbase/image/object_crop.h"

namespace {

matbase::Mask mask_with_box(int width, int height, const matbase::PixelBox& box) {
  matbase::Mask mask(static_cast<size_t>(width) * static_cast<size_t>(height), 0);
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x) mask[static_cast<size_t>(y * width + x)] = 1;
  return mask;
}

}  // namespace

TEST_CASE("mask_bounds finds the first and last column and row of the object", "[object_crop]") {
  const matbase::Mask mask = mask_with_box(64, 48, {10, 20, 49, 39});
  const auto box = matbase::mask_bounds(mask, 64, 48);
  REQUIRE(box);
  CHECK((box->x0 == 10 && box->y0 == 20 && box->x1 == 49 && box->y1 == 39));
  CHECK((box->width() == 40 && box->height() == 20));
  CHECK_FALSE(matbase::mask_bounds(matbase::Mask(64 * 48, 0), 64, 48));
  CHECK_THROWS_AS(matbase::mask_bounds(mask, 63, 48), std::invalid_argument);
}

TEST_CASE("object_crop_square centres the longer side grown by 4 % on each side, at least 2 px", "[object_crop]") {
  // 40 x 20: 4 % of 40 is 1.6, so the 2 px floor: side 44, centred on columns 10..49 and rows 20..39.
  matbase::CropSquare square = matbase::object_crop_square({10, 20, 49, 39});
  CHECK((square.side == 44 && square.left == 8 && square.top == 8));
  // 200 x 100 from (0, 0): 4 % of 200 is 8: side 216, reaching 8 px past the left and 58 px past the top.
  square = matbase::object_crop_square({0, 0, 199, 99});
  CHECK((square.side == 216 && square.left == -8 && square.top == -58));
  // One pixel: 1 + 2 * 2.
  square = matbase::object_crop_square({5, 7, 5, 7});
  CHECK((square.side == 5 && square.left == 3 && square.top == 5));
}

TEST_CASE("crop_to_square keeps the object and fills the rest with the background", "[object_crop]") {
  matbase::FloatImage image(4, 3, 2);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) image.at(x, y, 0) = static_cast<float>(10 * y + x), image.at(x, y, 1) = 0.5f;
  const matbase::Mask mask = mask_with_box(4, 3, {1, 0, 2, 1});
  const matbase::FloatImage crop = matbase::crop_to_square(image, {1, -1, 3}, {7.0f, 8.0f}, mask);
  REQUIRE((crop.width == 3 && crop.height == 3 && crop.channels == 2));
  // Row -1 is past the image; (3, 0) and row 2 are outside the mask.
  const float expected[3][3] = {{7, 7, 7}, {1, 2, 7}, {11, 12, 7}};
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) {
      CHECK(crop.at(x, y, 0) == expected[y][x]);
      CHECK(crop.at(x, y, 1) == (expected[y][x] == 7 ? 8.0f : 0.5f));
    }
  // Without a mask only the square's overhang is background.
  CHECK(matbase::crop_to_square(image, {1, -1, 3}, {7.0f, 8.0f}).at(2, 2, 0) == 13.0f);
  CHECK_THROWS_AS(matbase::crop_to_square(image, {0, 0, 2}, {7.0f}), std::invalid_argument);
}
