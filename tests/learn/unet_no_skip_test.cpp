// UNet-no-skip (matlearn/models/unet_no_skip.h): its reconstructed parameter count and output.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include "matlearn/models/unet_no_skip.h"

using namespace matlearn;

CATCH_TEST_CASE("UNet-no-skip has the reconstructed parameter count and full-resolution output", "[learn]") {
  int64_t six = 0, three = 0;
  UNetNoSkip model(6);
  for (const torch::Tensor& p : model->parameters()) six += p.numel();
  for (const torch::Tensor& p : UNetNoSkip(3)->parameters()) three += p.numel();
  CATCH_CHECK(six == 23730758);  // ../shared/reference/networks.md; the paper's 23.6M
  CATCH_CHECK(six - three == 3 * (32 + 1));  // only the 1x1 head depends on the outputs
  model->eval();
  torch::NoGradGuard no_grad;
  const torch::Tensor out = model->forward(torch::randn({2, 3, 32, 48}));
  CATCH_CHECK(out.sizes() == torch::IntArrayRef({2, 6, 32, 48}));
  CATCH_CHECK(torch::isfinite(out).all().item<bool>());
}
