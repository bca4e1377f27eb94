#include "matlearn/models/segment_anything/segment_anything.h"

#include <map>
#include <stdexcept>

#include "matbase/input_error.h"
#include "matlearn/models/state_dict.h"

namespace matlearn {
namespace {

// A tensor only each size's image encoder has.
constexpr const char* kVitBMark = "image_encoder.blocks.0.attn.qkv.weight";
constexpr const char* kMobileSamMark = "image_encoder.layers.0.blocks.0.conv1.c.weight";

}  // namespace

SegmentAnythingImpl::SegmentAnythingImpl(SamSize size) : size_(size) {
  if (size == SamSize::VitB)
    vit_ = register_module("image_encoder", SamVitEncoder(SamVitConfig::vit_b()));
  else
    tiny_vit_ = register_module("image_encoder", SamTinyVitEncoder());
  prompt_encoder_ = register_module("prompt_encoder", SamPromptEncoder());
  mask_decoder_ = register_module("mask_decoder", SamMaskDecoder());
}

torch::Tensor SegmentAnythingImpl::embed(const torch::Tensor& image) {
  return size_ == SamSize::VitB ? vit_(image) : tiny_vit_(image);
}

SamMasks SegmentAnythingImpl::decode(const torch::Tensor& embedding, const std::optional<torch::Tensor>& points,
                                     const std::optional<torch::Tensor>& labels, const std::optional<torch::Tensor>& boxes) {
  const SamPromptTokens tokens = prompt_encoder_(points, labels, boxes);
  return mask_decoder_(embedding, prompt_encoder_->dense_positional_encoding(), tokens.sparse, tokens.dense);
}

SegmentAnything load_segment_anything(const std::filesystem::path& checkpoint) {
  std::map<std::string, torch::Tensor> tensors;
  try {
    tensors = read_state_dict(checkpoint);
  } catch (const std::runtime_error& e) {
    throw matbase::InputError(std::string(e.what()) + " (a released Segment Anything checkpoint is read after "
                              "scripts/convert_segment_anything.py converts it)");
  }
  const bool vit_b = tensors.count(kVitBMark) > 0, mobile_sam = tensors.count(kMobileSamMark) > 0;
  if (vit_b == mobile_sam)
    throw matbase::InputError(checkpoint.string() + " is not a Segment Anything checkpoint of a size this build has (SAM ViT-B " +
                              "or MobileSAM, converted by scripts/convert_segment_anything.py)");
  SegmentAnything model(vit_b ? SamSize::VitB : SamSize::MobileSam);
  try {
    load_state_dict(*model, tensors, checkpoint.string());
  } catch (const std::runtime_error& e) {
    throw matbase::InputError(e.what());
  }
  model->eval();
  return model;
}

}  // namespace matlearn
