// The transposed convolution routed through a convolution's gradients
// (matlearn/models/transposed_convolution.h) against libtorch's own conv_transpose2d, the
// independent implementation: values and all three gradients, for the decoders' two shapes
// (4x4 stride 2 padding 1 without bias, 2x2 stride 2 with bias) on odd sizes.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include "matlearn/models/transposed_convolution.h"

using namespace matlearn;

namespace {

// Largest difference relative to the reference's largest magnitude.
double relative_difference(const torch::Tensor& ours, const torch::Tensor& reference) {
  return (ours - reference).abs().max().item<double>() / reference.abs().max().item<double>();
}

}  // namespace

CATCH_TEST_CASE("Transposed convolutions equal libtorch's, with their gradients", "[learn]") {
  torch::manual_seed(3);
  struct Case {
    int64_t kernel, stride, padding;
    bool bias;
  };
  for (const Case c : {Case{4, 2, 1, false}, Case{2, 2, 0, true}, Case{3, 1, 1, true}}) {
    CATCH_INFO("kernel " << c.kernel << " stride " << c.stride << " padding " << c.padding);
    const torch::Tensor x = torch::randn({2, 6, 5, 7}, torch::requires_grad());
    const torch::Tensor weight = torch::randn({6, 4, c.kernel, c.kernel}, torch::requires_grad());
    const torch::Tensor bias = c.bias ? torch::randn({4}, torch::requires_grad()) : torch::Tensor();
    const torch::Tensor upstream = torch::randn_like(torch::conv_transpose2d(x, weight, bias, c.stride, c.padding));

    const torch::Tensor reference = torch::conv_transpose2d(x, weight, bias, c.stride, c.padding);
    const torch::Tensor ours = transposed_convolution(x, weight, bias, c.stride, c.padding);
    CATCH_REQUIRE(ours.sizes() == reference.sizes());
    CATCH_CHECK(relative_difference(ours, reference) < 1e-5);

    std::vector<torch::Tensor> inputs = {x, weight};
    if (c.bias) inputs.push_back(bias);
    const auto reference_gradients = torch::autograd::grad({reference}, inputs, {upstream});
    const auto our_gradients = torch::autograd::grad({ours}, inputs, {upstream});
    for (size_t i = 0; i < inputs.size(); ++i) {
      CATCH_INFO("gradient " << i);
      CATCH_CHECK(relative_difference(our_gradients[i], reference_gradients[i]) < 1e-5);
    }
  }
}

CATCH_TEST_CASE("A ConvTranspose2d module runs through the same function, or says why it cannot", "[learn]") {
  torch::manual_seed(4);
  torch::nn::ConvTranspose2d up(torch::nn::ConvTranspose2dOptions(3, 2, 4).stride(2).padding(1));
  const torch::Tensor x = torch::randn({1, 3, 6, 6});
  CATCH_CHECK(relative_difference(transposed_convolution(*up, x), up->forward(x)) < 1e-5);
  torch::nn::ConvTranspose2d padded(torch::nn::ConvTranspose2dOptions(3, 2, 3).stride(2).output_padding(1));
  CATCH_CHECK_THROWS_WITH(transposed_convolution(*padded, x), Catch::Contains("output padding"));
}
