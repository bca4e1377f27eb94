#include "matlearn/isolation/object_isolation.h"

#include <algorithm>

#include "matbase/input_error.h"
#include "matlearn/isolation/mask_cleanup.h"

namespace matlearn {

IsolatedObject isolate_object(const matbase::FloatImage& rgb, const Prompt& prompt, const Segmenter& segmenter, int size,
                              matdataset::CropBackground background, const std::string& image) {
  check_prompt(prompt, rgb.width, rgb.height, image);
  matbase::Mask found;
  try {
    found = segmenter.segment(rgb, prompt);
  } catch (const matbase::InputError& e) {
    throw matbase::InputError(image + ": " + segmenter.name() + ": " + e.what());
  }
  IsolatedObject object;
  object.mask = cleaned_object_mask(found, rgb.width, rgb.height, prompt);
  if (std::none_of(object.mask.begin(), object.mask.end(), [](uint8_t v) { return v != 0; }))
    throw matbase::InputError(image + ": " + segmenter.name() +
                              " found no object; give a box around it (--box) or a point on it (--point X,Y)");
  object.isolated = matdataset::isolated_input(rgb, object.mask, size, background);
  return object;
}

}  // namespace matlearn
