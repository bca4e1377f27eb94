#pragma once
// Segment Anything's mask decoder (Kirillov et al. 2023, section 3 and appendix A): an IoU token
// and four mask tokens join the prompt's tokens in the two-way transformer over the image
// embedding; the image tokens are upscaled 4x to 256 x 256 and each mask token's MLP gives the
// weights that combine their 32 channels into one mask's logits; a head scores each mask's IoU.
// Laid out as the official "mask_decoder" (4,058,340 parameters), shared by SAM and MobileSAM.
#include <cstdint>

#include <torch/torch.h>

#include "matlearn/models/segment_anything/two_way_transformer.h"

namespace matlearn {

// Linear layers with ReLU between them (none after the last), the official MLP's "layers.k".
class SamMlpImpl : public torch::nn::Module {
 public:
  SamMlpImpl(int64_t in, int64_t hidden, int64_t out, int64_t layers);
  torch::Tensor forward(torch::Tensor x);

 private:
  torch::nn::ModuleList layers_{nullptr};
};
TORCH_MODULE(SamMlp);

struct SamMasks {
  torch::Tensor logits;  // B x masks x 256 x 256, the object where > 0
  torch::Tensor iou;     // B x masks, the predicted IoU of each
};

class SamMaskDecoderImpl : public torch::nn::Module {
 public:
  static constexpr int64_t kMaskTokens = 4;  // one for an unambiguous prompt, three for an ambiguous one
  SamMaskDecoderImpl();

  // image: B x 256 x 64 x 64 from the image encoder; image_pe: 1 x 256 x 64 x 64; sparse and dense:
  // the prompt encoder's. All four masks, the first being the single-mask output and the next
  // three the multi-mask ones.
  SamMasks forward(const torch::Tensor& image, const torch::Tensor& image_pe, const torch::Tensor& sparse,
                   const torch::Tensor& dense);

 private:
  TwoWayTransformer transformer_{nullptr};
  torch::nn::Embedding iou_token_{nullptr}, mask_tokens_{nullptr};
  torch::nn::Sequential output_upscaling_{nullptr};
  torch::nn::ModuleList hypernetworks_{nullptr};
  SamMlp iou_head_{nullptr};
};
TORCH_MODULE(SamMaskDecoder);

}  // namespace matlearn
