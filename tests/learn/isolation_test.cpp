// Isolating an object: prompts refused by name, mask cleanup on hand-drawn masks, GrabCut on a
// synthetic photograph whose object is known, and the crop a network is fed.
#include <cmath>
#include <random>
#include <thread>

#include <catch2/catch.hpp>

#include "matbase/input_error.h"
#include "matlearn/isolation/grabcut.h"
#include "matlearn/isolation/mask_cleanup.h"
#include "matlearn/isolation/object_isolation.h"
#include "matlearn/isolation/prompt.h"

namespace {

// A mask from rows of '#' (inside) and '.' (outside).
matbase::Mask drawn(const std::vector<std::string>& rows) {
  matbase::Mask mask;
  for (const std::string& row : rows)
    for (const char c : row) mask.push_back(c == '#' ? 1 : 0);
  return mask;
}

// A 96 x 72 photograph: a reddish disc of radius 20 at (40, 36) with a little noise, on a
// background of green-grey blotches, and the disc's true mask.
struct Photo {
  matbase::FloatImage rgb{96, 72, 3};
  matbase::Mask truth;
};
Photo disc_photo() {
  Photo photo;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> noise(-0.06f, 0.06f);
  photo.truth.assign(96 * 72, 0);
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 96; ++x) {
      const bool inside = std::hypot(x + 0.5 - 40.0, y + 0.5 - 36.0) < 20.0;
      photo.truth[static_cast<size_t>(y * 96 + x)] = inside;
      const float blotch = 0.5f + 0.25f * std::sin(0.3f * static_cast<float>(x)) * std::cos(0.23f * static_cast<float>(y));
      const float base[3] = {inside ? 0.75f : 0.35f * blotch, inside ? 0.2f : 0.6f * blotch, inside ? 0.15f : 0.4f * blotch};
      for (int c = 0; c < 3; ++c) photo.rgb.at(x, y, c) = std::clamp(base[c] + noise(random), 0.0f, 1.0f);
    }
  return photo;
}

double intersection_over_union(const matbase::Mask& a, const matbase::Mask& b) {
  size_t both = 0, either = 0;
  for (size_t p = 0; p < a.size(); ++p) both += a[p] && b[p], either += a[p] || b[p];
  return either ? static_cast<double>(both) / static_cast<double>(either) : 1.0;
}

}  // namespace

TEST_CASE("prompts outside the image, or empty, are refused naming the image", "[isolation]") {
  using matlearn::check_prompt;
  CHECK_NOTHROW(check_prompt({matbase::PixelBox{0, 0, 95, 71}, {{95, 71, true}, {0, 0, false}}}, 96, 72, "photo.jpg"));
  CHECK_THROWS_WITH(check_prompt({matbase::PixelBox{10, 10, 96, 20}, {}}, 96, 72, "photo.jpg"),
                    "photo.jpg: the box (10,10)-(96,20) reaches outside the 96 x 72 image (columns 0 to 95, rows 0 to 71)");
  CHECK_THROWS_WITH(check_prompt({matbase::PixelBox{30, 10, 20, 20}, {}}, 96, 72, "photo.jpg"),
                    "photo.jpg: the box (30,10)-(20,20) is empty: its last column or row comes before its first");
  CHECK_THROWS_WITH(check_prompt({std::nullopt, {{3, 72, true}}}, 96, 72, "photo.jpg"),
                    "photo.jpg: the point (3,72) lies outside the 96 x 72 image (columns 0 to 95, rows 0 to 71)");
  CHECK_THROWS_AS(check_prompt({std::nullopt, {{-1, 0, true}}}, 96, 72, "photo.jpg"), matbase::InputError);
}

TEST_CASE("default_prompt is the central box a twentieth in from each side; grown_box stays in the image", "[isolation]") {
  const matlearn::Prompt prompt = matlearn::default_prompt(100, 50);
  REQUIRE(prompt.box);
  CHECK((prompt.box->x0 == 5 && prompt.box->y0 == 2 && prompt.box->x1 == 94 && prompt.box->y1 == 47));
  const matbase::PixelBox grown = matlearn::grown_box({10, 4, 49, 23}, 0.05, 52, 30);
  CHECK((grown.x0 == 8 && grown.y0 == 3 && grown.x1 == 51 && grown.y1 == 24));
  const matbase::PixelBox clipped = matlearn::grown_box({0, 0, 99, 49}, 0.05, 100, 50);
  CHECK((clipped.x0 == 0 && clipped.y0 == 0 && clipped.x1 == 99 && clipped.y1 == 49));
}

TEST_CASE("mask cleanup keeps one object and fills its holes", "[isolation]") {
  const matbase::Mask mask = drawn({"##......",
                                    "##..####",
                                    "....#..#",
                                    "....####",
                                    ".#......"});
  CHECK(matlearn::largest_component(mask, 8, 5) == drawn({"........",
                                                          "....####",
                                                          "....#..#",
                                                          "....####",
                                                          "........"}));
  // Diagonal neighbours connect (8-connected): the top-left block and a point on it.
  CHECK(matlearn::components_holding(mask, 8, 5, {{1, 1, true}, {3, 3, true}}) == drawn({"##......",
                                                                                         "##......",
                                                                                         "........",
                                                                                         "........",
                                                                                         "........"}));
  // The ring's inside is a hole; the outside reaches the border.
  const matbase::Mask ring = matlearn::largest_component(mask, 8, 5);
  CHECK(matlearn::filled_holes(ring, 8, 5) == drawn({"........",
                                                     "....####",
                                                     "....####",
                                                     "....####",
                                                     "........"}));
  // cleaned_object_mask: the point's region wins over the larger one; without points the largest.
  matlearn::Prompt on_block{std::nullopt, {{0, 0, true}, {7, 4, false}}};
  CHECK(matlearn::cleaned_object_mask(mask, 8, 5, on_block) == matlearn::components_holding(mask, 8, 5, on_block.points));
  CHECK(matlearn::cleaned_object_mask(mask, 8, 5, {}) == matlearn::filled_holes(ring, 8, 5));
  const matbase::Mask nothing(40, 0);
  CHECK(matlearn::cleaned_object_mask(nothing, 8, 5, {}) == nothing);
}

TEST_CASE("GrabCut finds a disc on a blotchy background from a box, the same on any thread", "[isolation]") {
  const Photo photo = disc_photo();
  const matlearn::Prompt box{matlearn::grown_box({20, 16, 59, 55}, 0.05, 96, 72), {}};
  const matbase::Mask found = matlearn::grabcut_mask(photo.rgb, box);
  const matbase::Mask object = matlearn::cleaned_object_mask(found, 96, 72, box);
  CHECK(intersection_over_union(object, photo.truth) > 0.95);
  matbase::Mask on_thread;
  std::thread([&] { on_thread = matlearn::grabcut_mask(photo.rgb, box); }).join();
  CHECK(on_thread == found);
  CHECK(matlearn::grabcut_mask(photo.rgb, box) == found);
  // With no prompt the central box holds the disc too.
  CHECK(intersection_over_union(matlearn::cleaned_object_mask(matlearn::grabcut_mask(photo.rgb, {}), 96, 72, {}), photo.truth) >
        0.9);
}

TEST_CASE("GrabCut refuses prompts that leave it nothing to learn from", "[isolation]") {
  const Photo photo = disc_photo();
  CHECK_THROWS_WITH(matlearn::grabcut_mask(photo.rgb, {matbase::PixelBox{0, 0, 95, 71}, {}}),
                    Catch::Contains("this box covers the whole image and no point is marked background"));
  CHECK_NOTHROW(matlearn::grabcut_mask(photo.rgb, {matbase::PixelBox{0, 0, 95, 71}, {{2, 2, false}, {90, 3, false}}}));
  CHECK_THROWS_WITH(matlearn::grabcut_mask(photo.rgb, {matbase::PixelBox{40, 36, 41, 37}, {}}),
                    Catch::Contains("this box holds fewer than 5 pixels"));
}

TEST_CASE("isolate_object crops the square around the object onto the background", "[isolation]") {
  const Photo photo = disc_photo();
  const matlearn::GrabCutSegmenter grabcut;
  const matlearn::IsolatedObject object = matlearn::isolate_object(
      photo.rgb, {matbase::PixelBox{18, 14, 61, 57}, {}}, grabcut, 32, matdataset::CropBackground::White, "disc.png");
  const matdataset::IsolatedInput& isolated = object.isolated;
  // The disc spans about 40 px: a square of 40 + 2 * 2 around it.
  CHECK(std::abs(isolated.crop.side - 44) <= 2);
  CHECK(std::abs(isolated.crop.left + isolated.crop.side / 2 - 40) <= 1);
  REQUIRE((isolated.input.rgb.width == 32 && isolated.input.rgb.height == 32 && isolated.input.mask.size() == 32 * 32));
  // The corners are off the disc: white; the centre is the disc's red.
  for (int c = 0; c < 3; ++c) CHECK(isolated.input.rgb.at(0, 0, c) == 1.0f);
  CHECK(isolated.input.mask[0] == 0);
  CHECK(isolated.input.mask[16 * 32 + 16] == 1);
  CHECK(isolated.input.rgb.at(16, 16, 0) > 0.6f);
  CHECK(isolated.input.rgb.at(16, 16, 1) < 0.35f);
  CHECK_THROWS_WITH(matlearn::isolate_object(photo.rgb, {matbase::PixelBox{0, 0, 95, 71}, {}}, grabcut, 32,
                                             matdataset::CropBackground::Black, "disc.png"),
                    Catch::StartsWith("disc.png: grabcut: GrabCut learns the background"));
  CHECK_THROWS_WITH(matlearn::isolate_object(photo.rgb, {matbase::PixelBox{0, 0, 96, 71}, {}}, grabcut, 32,
                                             matdataset::CropBackground::Black, "disc.png"),
                    Catch::StartsWith("disc.png: the box (0,0)-(96,71) reaches outside"));
}
