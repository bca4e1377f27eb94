#include "matlearn/models/swin_convnext_u.h"

namespace matlearn {

SwinTUImpl::SwinTUImpl(int64_t output_channels) {
  encoder_ = register_module("encoder", SwinTEncoder());
  decoder_ = register_module("decoder", UpConvDecoder(768, output_channels));
}

torch::Tensor SwinTUImpl::forward(const torch::Tensor& image) {
  return decoder_->forward(encoder_->forward(image).stages[3]);
}

ConvNeXtTUImpl::ConvNeXtTUImpl(int64_t output_channels) {
  encoder_ = register_module("encoder", ConvNeXtTEncoder());
  decoder_ = register_module("decoder", UpConvDecoder(768, output_channels));
}

torch::Tensor ConvNeXtTUImpl::forward(const torch::Tensor& image) {
  return decoder_->forward(encoder_->forward(image).stages[3]);
}

}  // namespace matlearn
