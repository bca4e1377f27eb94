#include "matlearn/denoising/denoising_unet.h"

namespace matlearn {
namespace {

torch::nn::Conv2d conv3x3(int64_t in, int64_t out) {
  return torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, 3).padding(1));
}

// Every convolution through oneDNN, whatever the image's size: libtorch 1.13 picks oneDNN only
// above a size it judges worth it, and the result of its fallback depends on the thread count.
torch::Tensor convolve(const torch::nn::Conv2d& conv, const torch::Tensor& x) {
  return torch::mkldnn_convolution(x, conv->weight, conv->bias, {1, 1}, {1, 1}, {1, 1}, 1);
}

torch::Tensor pool(const torch::Tensor& x) { return torch::max_pool2d(x, 2, 2); }

torch::Tensor upsample(const torch::Tensor& x) {
  return torch::nn::functional::interpolate(
      x, torch::nn::functional::InterpolateFuncOptions().scale_factor(std::vector<double>{2.0, 2.0}).mode(torch::kNearest));
}

}  // namespace

DenoisingUNetImpl::DenoisingUNetImpl() {
  enc_conv0_ = register_module("enc_conv0", conv3x3(kDenoiserInputChannels, 32));
  enc_conv1_ = register_module("enc_conv1", conv3x3(32, 32));
  enc_conv2_ = register_module("enc_conv2", conv3x3(32, 48));
  enc_conv3_ = register_module("enc_conv3", conv3x3(48, 64));
  enc_conv4_ = register_module("enc_conv4", conv3x3(64, 80));
  enc_conv5a_ = register_module("enc_conv5a", conv3x3(80, 96));
  enc_conv5b_ = register_module("enc_conv5b", conv3x3(96, 96));
  dec_conv4a_ = register_module("dec_conv4a", conv3x3(96 + 64, 112));
  dec_conv4b_ = register_module("dec_conv4b", conv3x3(112, 112));
  dec_conv3a_ = register_module("dec_conv3a", conv3x3(112 + 48, 96));
  dec_conv3b_ = register_module("dec_conv3b", conv3x3(96, 96));
  dec_conv2a_ = register_module("dec_conv2a", conv3x3(96 + 32, 64));
  dec_conv2b_ = register_module("dec_conv2b", conv3x3(64, 64));
  dec_conv1a_ = register_module("dec_conv1a", conv3x3(64 + kDenoiserInputChannels, 64));
  dec_conv1b_ = register_module("dec_conv1b", conv3x3(64, 32));
  dec_conv0_ = register_module("dec_conv0", conv3x3(32, 3));
}

torch::Tensor DenoisingUNetImpl::forward(const torch::Tensor& input) {
  TORCH_CHECK(input.dim() == 4 && input.size(1) == kDenoiserInputChannels && input.size(2) % kDenoiserSideMultiple == 0 &&
                  input.size(3) % kDenoiserSideMultiple == 0,
              "the denoising U-Net takes N x 9 x H x W with H and W multiples of 16, got ", input.sizes());
  // A 3x3 convolution and its ReLU.
  const auto layer = [](const torch::nn::Conv2d& conv, const torch::Tensor& x) { return torch::relu(convolve(conv, x)); };
  torch::Tensor x = layer(enc_conv0_, input.contiguous(input.suggest_memory_format()));
  const torch::Tensor half = pool(layer(enc_conv1_, x));
  const torch::Tensor quarter = pool(layer(enc_conv2_, half));
  const torch::Tensor eighth = pool(layer(enc_conv3_, quarter));
  x = pool(layer(enc_conv4_, eighth));
  x = layer(enc_conv5b_, layer(enc_conv5a_, x));
  x = torch::cat({upsample(x), eighth}, 1);
  x = layer(dec_conv4b_, layer(dec_conv4a_, x));
  x = torch::cat({upsample(x), quarter}, 1);
  x = layer(dec_conv3b_, layer(dec_conv3a_, x));
  x = torch::cat({upsample(x), half}, 1);
  x = layer(dec_conv2b_, layer(dec_conv2a_, x));
  x = torch::cat({upsample(x), input}, 1);
  x = layer(dec_conv1b_, layer(dec_conv1a_, x));
  return convolve(dec_conv0_, x);
}

}  // namespace matlearn
