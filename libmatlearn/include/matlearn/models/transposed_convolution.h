#pragma once
// A 2-D transposed convolution computed as what it is, the input gradient of the strided
// convolution it transposes. libtorch 1.13 runs fp32 transposed convolutions on its im2col
// fallback (slow_conv_transpose2d), while the input and weight gradients of an ordinary
// convolution run on oneDNN: routing through them makes the decoders' upsampling 3-4x faster
// (bench/learn_bench), with the same values to rounding. Dilation 1, one group, no output padding.
#include <torch/torch.h>

namespace matlearn {

// As torch::conv_transpose2d(x, weight, bias, stride, padding): x is N x C_in x H x W, weight
// C_in x C_out x k x k; the output is N x C_out x ((H - 1) stride - 2 padding + k) x (likewise W).
// An undefined bias is none. Differentiable in x, weight and bias.
torch::Tensor transposed_convolution(const torch::Tensor& x, const torch::Tensor& weight, const torch::Tensor& bias,
                                     int64_t stride, int64_t padding);

// The module's forward through the function above, with its weight, bias, stride and padding
// (which must be the same along both axes). Throws std::invalid_argument for dilation, groups or
// output padding.
torch::Tensor transposed_convolution(const torch::nn::ConvTranspose2dImpl& module, const torch::Tensor& x);

}  // namespace matlearn
