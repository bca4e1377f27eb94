#pragma once
// Segment Anything as one module laid out as the official "Sam" (image_encoder, prompt_encoder,
// mask_decoder), at the two sizes this build has: SAM ViT-B and MobileSAM (TinyViT-5M).
// docs/segment_anything.md states the layout, the counts and the pre- and post-processing.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <torch/torch.h>

#include "matlearn/models/segment_anything/sam_mask_decoder.h"
#include "matlearn/models/segment_anything/sam_prompt_encoder.h"
#include "matlearn/models/segment_anything/sam_tiny_vit_encoder.h"
#include "matlearn/models/segment_anything/sam_vit_encoder.h"

namespace matlearn {

enum class SamSize { VitB, MobileSam };

class SegmentAnythingImpl : public torch::nn::Module {
 public:
  explicit SegmentAnythingImpl(SamSize size);
  SamSize size() const { return size_; }

  // A normalised, padded N x 3 x 1024 x 1024 image to its N x 256 x 64 x 64 embedding.
  torch::Tensor embed(const torch::Tensor& image);
  // All four masks of a prompt on one embedding (SamPromptEncoder's inputs, in the input frame).
  SamMasks decode(const torch::Tensor& embedding, const std::optional<torch::Tensor>& points,
                  const std::optional<torch::Tensor>& labels, const std::optional<torch::Tensor>& boxes);

 private:
  SamSize size_;
  SamVitEncoder vit_{nullptr};
  SamTinyVitEncoder tiny_vit_{nullptr};
  SamPromptEncoder prompt_encoder_{nullptr};
  SamMaskDecoder mask_decoder_{nullptr};
};
TORCH_MODULE(SegmentAnything);

// The model a converted checkpoint (scripts/convert_segment_anything.py) holds, its size told by
// its tensors, loaded and in eval mode. Throws matbase::InputError naming the file: missing, not a
// dict of tensors, of neither size, or not fitting it (the first mismatched tensors named).
SegmentAnything load_segment_anything(const std::filesystem::path& checkpoint);

}  // namespace matlearn
