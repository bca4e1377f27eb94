// The Swin-T and ConvNeXt-T encoders (matlearn/models/swin_encoder.h, convnext_encoder.h) against
// torchvision's swin_t and convnext_tiny. The 96 x 64 input makes Swin's token grids 24 x 16 down
// to 3 x 2: padded to the window, shifted windows with their mask, and grids no larger than one
// window, where the shift is skipped.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <cmath>

#include "matlearn/models/convnext_encoder.h"
#include "matlearn/models/stochastic_depth.h"
#include "matlearn/models/swin_encoder.h"
#include "torchvision_reference.h"

using namespace matlearn;

namespace {

template <class Features>
std::vector<std::pair<std::string, torch::Tensor>> named_stages(const Features& f) {
  return {{"stage1", f.stages[0]}, {"stage2", f.stages[1]}, {"stage3", f.stages[2]}, {"stage4", f.stages[3]}};
}

}  // namespace

CATCH_TEST_CASE("The Swin-T encoder has torchvision's parameter names, shapes and count", "[learn]") {
  // docs/networks.md: features + norm 27,519,354; 183 tensors without the head.
  torchvision_reference::check_names_and_count(*SwinTEncoder(), "swin_t", 183, 27519354);
}

CATCH_TEST_CASE("With torchvision's weights the Swin-T encoder computes torchvision's stage outputs", "[learn]") {
  SwinTEncoder encoder;
  torchvision_reference::check_stage_outputs(encoder, "swin_t", [&](const torch::Tensor& input) {
    return named_stages(encoder->forward(input));
  });
}

CATCH_TEST_CASE("The ConvNeXt-T encoder has torchvision's parameter names, shapes and count", "[learn]") {
  // docs/networks.md: features 27,818,592; 178 tensors without the classifier.
  torchvision_reference::check_names_and_count(*ConvNeXtTEncoder(), "convnext_tiny", 178, 27818592);
}

CATCH_TEST_CASE("With torchvision's weights the ConvNeXt-T encoder computes torchvision's stage outputs", "[learn]") {
  ConvNeXtTEncoder encoder;
  torchvision_reference::check_stage_outputs(encoder, "convnext_tiny", [&](const torch::Tensor& input) {
    return named_stages(encoder->forward(input));
  });
}

CATCH_TEST_CASE("Stochastic depth drops whole rows with its probability and keeps the expectation", "[learn]") {
  torch::manual_seed(3);
  const int64_t rows = 20000;
  const torch::Tensor branch = torch::ones({rows, 2, 3});
  CATCH_CHECK(torch::equal(drop_residual_rows(branch, 0.3, /*training=*/false), branch));
  const torch::Tensor dropped = drop_residual_rows(branch, 0.3, /*training=*/true);
  const torch::Tensor first = dropped.select(1, 0).select(1, 0);
  // Every row is all zero or all 1 / 0.7.
  CATCH_CHECK(torch::equal(dropped, first.view({rows, 1, 1}).expand({rows, 2, 3})));
  const double zero_rows = (first == 0).sum().item<double>();
  CATCH_CHECK(((first == 0) | (first - 1.0 / 0.7).abs().lt(1e-6)).all().item<bool>());
  // Binomial(rows, 0.3): within 4 standard deviations.
  CATCH_CHECK(std::abs(zero_rows - 0.3 * rows) < 4.0 * std::sqrt(rows * 0.3 * 0.7));
  CATCH_CHECK(block_drop_probability(0.2, 0, 12) == 0.0);
  CATCH_CHECK(std::abs(block_drop_probability(0.2, 11, 12) - 0.2) < 1e-15);
}
