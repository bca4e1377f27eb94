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

class SamSegmenter final : public Segmenter {
 public:
  // Throws matbase::InputError naming the checkpoint (load_segment_anything).
  explicit SamSegmenter(const std::filesystem::path& checkpoint);
  matbase::Mask segment(const matbase::FloatImage& rgb, const Prompt& prompt) const override;
  std::string name() const override { return "sam:" + checkpoint_.string(); }
  SamSize size() const { return model_->size(); }

 private:
  std::filesystem::path checkpoint_;
  SegmentAnything model_;
};

}  // namespace matlearn
