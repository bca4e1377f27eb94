#include "matlearn/models/transposed_convolution.h"

#include <stdexcept>

namespace matlearn {
namespace {

using torch::autograd::AutogradContext;
using torch::autograd::tensor_list;

// With y = conv(a, W) (stride s, padding p) and <., .> the sum of products, the transposed
// convolution of x is d<conv(a, W), x>/da. Hence its three gradients, for an upstream gradient g:
// with respect to x, conv(g, W); with respect to W, the weight gradient of conv at input g and
// output gradient x; with respect to the bias, g summed over batch and pixels.
class TransposedConvolution : public torch::autograd::Function<TransposedConvolution> {
 public:
  static torch::Tensor forward(AutogradContext* ctx, const torch::Tensor& x, const torch::Tensor& weight,
                               int64_t stride, int64_t padding) {
    ctx->save_for_backward({x, weight});
    ctx->saved_data["stride"] = stride;
    ctx->saved_data["padding"] = padding;
    const auto side = [&](int64_t in) { return (in - 1) * stride - 2 * padding + weight.size(2); };
    // Only the shape of the convolution's input is read.
    const torch::Tensor output_shape = torch::empty({x.size(0), weight.size(1), side(x.size(2)), side(x.size(3))}, x.options());
    return std::get<0>(at::convolution_backward(x, output_shape, weight, c10::nullopt, {stride, stride},
                                                {padding, padding}, {1, 1}, false, {0, 0}, 1, {true, false, false}));
  }

  static tensor_list backward(AutogradContext* ctx, tensor_list upstream) {
    const auto saved = ctx->get_saved_variables();
    const torch::Tensor &x = saved[0], &weight = saved[1], &g = upstream[0];
    const int64_t stride = ctx->saved_data["stride"].toInt(), padding = ctx->saved_data["padding"].toInt();
    torch::Tensor x_gradient, weight_gradient;
    if (ctx->needs_input_grad(0)) x_gradient = torch::conv2d(g, weight, {}, stride, padding);
    if (ctx->needs_input_grad(1))
      weight_gradient = std::get<1>(at::convolution_backward(x, g, weight, c10::nullopt, {stride, stride},
                                                             {padding, padding}, {1, 1}, false, {0, 0}, 1,
                                                             {false, true, false}));
    return {x_gradient, weight_gradient, torch::Tensor(), torch::Tensor()};
  }
};

}  // namespace

torch::Tensor transposed_convolution(const torch::Tensor& x, const torch::Tensor& weight, const torch::Tensor& bias,
                                     int64_t stride, int64_t padding) {
  TORCH_CHECK(x.dim() == 4 && weight.dim() == 4 && x.size(1) == weight.size(0) && weight.size(2) == weight.size(3),
              "transposed_convolution: x is N x C_in x H x W and weight C_in x C_out x k x k");
  torch::Tensor y = TransposedConvolution::apply(x, weight, stride, padding);
  if (bias.defined()) y = y + bias.view({1, -1, 1, 1});
  return y;
}

torch::Tensor transposed_convolution(const torch::nn::ConvTranspose2dImpl& module, const torch::Tensor& x) {
  // The module keeps its settings as ConvNd options; a transposed one's padding is a plain array.
  const torch::nn::detail::ConvNdOptions<2>& o = module.options;
  const auto& padding = c10::get<torch::ExpandingArray<2>>(o.padding());
  const bool square = (*o.stride())[0] == (*o.stride())[1] && (*padding)[0] == (*padding)[1];
  if (!square || (*o.dilation())[0] != 1 || (*o.dilation())[1] != 1 || o.groups() != 1 || (*o.output_padding())[0] != 0 ||
      (*o.output_padding())[1] != 0)
    throw std::invalid_argument("transposed_convolution: only equal strides and paddings, no dilation, groups or output padding");
  return transposed_convolution(x, module.weight, module.bias, (*o.stride())[0], (*padding)[0]);
}

}  // namespace matlearn
