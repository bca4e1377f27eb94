#pragma once
// Isolating an object in an image before a network sees it, the paper's Segment Anything step: a
// segmenter's pixels, cleaned into one object (mask_cleanup.h), cropped to the square around it
// with the background composited and resized to the network's input (matdataset::isolated_input).
#include <string>

#include "matbase/image/float_image.h"
#include "matdataset/format/sample_reader.h"
#include "matlearn/isolation/prompt.h"
#include "matlearn/isolation/segmenter.h"

namespace matlearn {

struct IsolatedObject {
  matbase::Mask mask;                  // the object in the whole image, cleaned
  matdataset::IsolatedInput isolated;  // the network's input and where it was cropped
};

// Throws matbase::InputError opening with `image` (the file, or what the image is) for a prompt
// check_prompt refuses, a prompt the segmenter cannot use, or no object found.
IsolatedObject isolate_object(const matbase::FloatImage& rgb, const Prompt& prompt, const Segmenter& segmenter, int size,
                              matdataset::CropBackground background, const std::string& image);

}  // namespace matlearn
