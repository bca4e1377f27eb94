#pragma once
// OpenCV's GrabCut (Rother, Kolmogorov and Blake 2004, "GrabCut: interactive foreground
// extraction using iterated graph cuts"), the segmenter that needs no weights: colour models of
// the object and its background, learnt from a box (outside it is background) and refined by
// points (a small disc around each is certainly object or certainly background), then a graph
// cut. Good where the object's colours differ from its surroundings'; it does not know objects.
#include <string>

#include "matbase/image/float_image.h"
#include "matlearn/isolation/prompt.h"
#include "matlearn/isolation/segmenter.h"

namespace matlearn {

struct GrabCutSettings {
  int iterations = 5;  // OpenCV's sample's count: the colour models settle within a few
  // A point marks a disc of this fraction of the image's shorter side (at least 1 pixel).
  double point_radius_fraction = 0.01;
  // A larger image is segmented at this longer side and its mask brought back: GrabCut's time
  // grows with the pixels (a 12-megapixel photograph would take minutes), while the network sees
  // the object at 224 px or so.
  int working_side = 640;
};

// The pixels GrabCut finds to be the object (before cleanup: mask_cleanup.h) in `rgb`, a
// display-encoded RGB image in [0, 1] (its first three channels are read). An empty prompt is
// default_prompt's box; an image longer than settings.working_side is segmented at that size. The
// same mask for the same image and prompt, on any thread. Throws
// matbase::InputError when nothing in the prompt says what the background looks like (a box
// over the whole image and no background point).
matbase::Mask grabcut_mask(const matbase::FloatImage& rgb, const Prompt& prompt, const GrabCutSettings& settings = {});

class GrabCutSegmenter final : public Segmenter {
 public:
  explicit GrabCutSegmenter(GrabCutSettings settings = {}) : settings_(settings) {}
  matbase::Mask segment(const matbase::FloatImage& rgb, const Prompt& prompt) const override {
    return grabcut_mask(rgb, prompt, settings_);
  }
  std::string name() const override { return "grabcut"; }

 private:
  GrabCutSettings settings_;
};

}  // namespace matlearn
