#pragma once
// What a user says about the object to isolate in an image: a box around it, points on it
// (foreground) or off it (background), or nothing. Coordinates are pixel indices, column x and row
// y from the top-left pixel, as Segment Anything's prompts and a mask's bounding box give them.
#include <optional>
#include <string>
#include <vector>

#include "matbase/image/object_crop.h"

namespace matlearn {

struct PromptPoint {
  int x = 0;
  int y = 0;
  bool foreground = true;
};

struct Prompt {
  std::optional<matbase::PixelBox> box;  // both corners inside the object's box, included
  std::vector<PromptPoint> points;
  bool empty() const { return !box && points.empty(); }
};

// Throws matbase::InputError, opening with `image` (the file), for a box with a corner outside
// the width x height image, an empty box (its last column or row before its first) and a point
// outside the image.
void check_prompt(const Prompt& prompt, int width, int height, const std::string& image);

// What "no prompt" means: the object lies inside the image's central box, a twentieth of each side
// in from the border (the most central object of a photograph framed on it; GrabCut learns the
// background from the border).
Prompt default_prompt(int width, int height);

// The label's box grown by `fraction` of its width and height on each side, within the image: a
// box prompt as a user draws it around an object (the bench's, 5 %).
matbase::PixelBox grown_box(const matbase::PixelBox& box, double fraction, int width, int height);

// The prompt in a copy of a width x height image resized to scaled_width x scaled_height: a box
// keeps every pixel it covered in part, a point lands in the pixel that holds its centre.
Prompt scaled_prompt(const Prompt& prompt, int width, int height, int scaled_width, int scaled_height);

}  // namespace matlearn
