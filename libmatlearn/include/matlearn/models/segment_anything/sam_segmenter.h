#pragma once
// Segment Anything as an isolation segmenter (matlearn/isolation/segmenter.h): the photograph
// resized so that its longer side is 1024 (Pillow's bilinear filter, as the official predictor),
// normalised and padded; the prompt's box and points in that frame; the mask back at the
// photograph's size. A prompt of one point or none is ambiguous: the best of the three
// multi-mask outputs by predicted IoU is taken (as the MatPredict repository's preprocessing
// does); a box or several points take the single-mask output, as the official notes advise.
#include <filesystem>
#include <string>

#include "matlearn/isolation/segmenter.h"
#include "matlearn/models/segment_anything/segment_anything.h"

namespace matlearn {

// What the model says about a prompt on a photograph, each stage as the official SamPredictor
// has it, before the mask is taken.
struct SamPrediction {
  torch::Tensor input;      // 1 x 3 x 1024 x 1024: the photograph resized, normalised and padded
  torch::Tensor embedding;  // 1 x 256 x 64 x 64
  SamMasks masks;           // all four masks (256 x 256 logits over the input) and their predicted IoU
  int64_t chosen = 0;       // the mask taken: 0 for an unambiguous prompt, else the best of 1-3
  torch::Tensor logits;     // the chosen mask's logits at the photograph's size, height x width
};

class SamSegmenter final : public Segmenter {
 public:
  // Throws matbase::InputError naming the checkpoint (load_segment_anything).
  explicit SamSegmenter(const std::filesystem::path& checkpoint);
  // `prompt` in the photograph's pixels, as check_prompt accepts it; an empty one is default_prompt's box.
  SamPrediction predict(const matbase::FloatImage& rgb, const Prompt& prompt) const;
  // The object: where predict's logits are positive.
  matbase::Mask segment(const matbase::FloatImage& rgb, const Prompt& prompt) const override;
  std::string name() const override { return "sam:" + checkpoint_.string(); }
  SamSize size() const { return model_->size(); }

 private:
  std::filesystem::path checkpoint_;
  SegmentAnything model_;
};

}  // namespace matlearn
