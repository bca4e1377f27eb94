// Isolating an object: prompts refused by name, mask cleanup on hand-drawn masks, GrabCut on a
// synthetic photograph whose object is known, and the crop a network is fed.
#include <algorithm>
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

struct Disc {
  double x, y, radius;
  bool holds(int px, int py) const { return std::hypot(px + 0.5 - x, py + 0.5 - y) < radius; }
};

// A photograph of reddish discs with a little noise on a background of green-grey blotches, and
// their true mask; by default 96 x 72 with a disc of radius 20 at (40, 36).
struct Photo {
  matbase::FloatImage rgb;
  matbase::Mask truth;
};
Photo disc_photo(int width = 96, int height = 72, const std::vector<Disc>& discs = {{40.0, 36.0, 20.0}}) {
  Photo photo{matbase::FloatImage(width, height, 3), matbase::Mask(static_cast<size_t>(width) * static_cast<size_t>(height), 0)};
  std::mt19937 random(7);
  std::uniform_real_distribution<float> noise(-0.06f, 0.06f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool inside = std::any_of(discs.begin(), discs.end(), [&](const Disc& disc) { return disc.holds(x, y); });
      photo.truth[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] = inside;
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

TEST_CASE("scaled_prompt keeps a box's pixels and moves a point to the pixel holding its centre", "[isolation]") {
  // 1600 x 1200 to 640 x 480: a scale of 0.4 on both axes.
  const matlearn::Prompt scaled = matlearn::scaled_prompt(
      {matbase::PixelBox{901, 351, 1398, 848}, {{1150, 600, true}, {0, 0, false}, {1599, 1199, true}}}, 1600, 1200, 640, 480);
  REQUIRE(scaled.box);
  // 901 * 0.4 = 360.4 and 351 * 0.4 = 140.4 lie in pixels 360 and 140; the last pixels end at
  // 1399 * 0.4 = 559.6 and 849 * 0.4 = 339.6, inside pixels 559 and 339.
  CHECK((scaled.box->x0 == 360 && scaled.box->y0 == 140 && scaled.box->x1 == 559 && scaled.box->y1 == 339));
  REQUIRE(scaled.points.size() == 3);
  // Centres (1150.5, 600.5) * 0.4 = (460.2, 240.2); (0.5, 0.5) * 0.4; (1599.5, 1199.5) * 0.4 = (639.8, 479.8).
  CHECK((scaled.points[0].x == 460 && scaled.points[0].y == 240 && scaled.points[0].foreground));
  CHECK((scaled.points[1].x == 0 && scaled.points[1].y == 0 && !scaled.points[1].foreground));
  CHECK((scaled.points[2].x == 639 && scaled.points[2].y == 479));
  // A one-pixel box stays a box: pixel 5 covers 2.0 to 2.4.
  const matlearn::Prompt tiny = matlearn::scaled_prompt({matbase::PixelBox{5, 5, 5, 5}, {}}, 1600, 1200, 640, 480);
  CHECK((tiny.box->x0 == 2 && tiny.box->x1 == 2 && tiny.box->y0 == 2 && tiny.box->y1 == 2));
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

TEST_CASE("GrabCut segments a photograph larger than its working size there, the box scaled with it", "[isolation]") {
  // Two discs alike, 1600 x 1200: segmented at 640 x 480. A box around the right one only.
  const Disc left{450.0, 600.0, 200.0}, right{1150.0, 600.0, 200.0};
  const Photo photo = disc_photo(1600, 1200, {left, right});
  const matlearn::Prompt box{matbase::PixelBox{901, 351, 1398, 848}, {}};
  const matbase::Mask found = matlearn::grabcut_mask(photo.rgb, box);
  REQUIRE(found.size() == photo.truth.size());
  matbase::Mask right_disc(found.size(), 0);
  size_t on_left = 0;
  for (int y = 0; y < 1200; ++y)
    for (int x = 0; x < 1600; ++x) {
      const size_t p = static_cast<size_t>(y) * 1600 + static_cast<size_t>(x);
      right_disc[p] = right.holds(x, y);
      on_left += found[p] && left.holds(x, y);
    }
  CHECK(intersection_over_union(matlearn::cleaned_object_mask(found, 1600, 1200, box), right_disc) > 0.97);
  CHECK(on_left == 0);
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
