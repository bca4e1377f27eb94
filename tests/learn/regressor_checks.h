#pragma once
// What every regressor's test checks: the parameter count for 6 outputs, that only the 1x1 head
// (head_inputs channels plus a bias per output) changes with the output count, and a finite
// full-resolution output. Include after catch.hpp with CATCH_CONFIG_PREFIX_ALL (torch tests).
#include <cstdint>

#include <torch/torch.h>

#include "matlearn/models/regressor.h"

inline void check_regressor(matlearn::Architecture architecture, int64_t expected_parameters, int64_t head_inputs,
                            int64_t height, int64_t width) {
  const auto six = matlearn::make_regressor(architecture, 6);
  CATCH_CHECK(matlearn::parameter_count(*six) == expected_parameters);
  CATCH_CHECK(matlearn::parameter_count(*six) - matlearn::parameter_count(*matlearn::make_regressor(architecture, 3)) ==
              3 * (head_inputs + 1));
  six->eval();
  torch::NoGradGuard no_grad;
  const torch::Tensor out = six->forward(torch::randn({2, 3, height, width}));
  CATCH_CHECK(out.sizes() == torch::IntArrayRef({2, 6, height, width}));
  CATCH_CHECK(torch::isfinite(out).all().item<bool>());
}
