#include "models/window_partition.h"

namespace matlearn {

torch::Tensor padded_to_windows(const torch::Tensor& grid, int64_t window) {
  const int64_t pad_bottom = (window - grid.size(1) % window) % window;
  const int64_t pad_right = (window - grid.size(2) % window) % window;
  if (pad_bottom == 0 && pad_right == 0) return grid;
  return torch::nn::functional::pad(grid, torch::nn::functional::PadFuncOptions({0, 0, 0, pad_right, 0, pad_bottom}));
}

torch::Tensor partition_windows(const torch::Tensor& grid, int64_t window) {
  const int64_t n = grid.size(0), h = grid.size(1), w = grid.size(2), c = grid.size(3);
  return grid.reshape({n, h / window, window, w / window, window, c})
      .permute({0, 1, 3, 2, 4, 5})
      .reshape({-1, window * window, c});
}

torch::Tensor merge_windows(const torch::Tensor& windows, int64_t batch, int64_t height, int64_t width, int64_t window) {
  const int64_t c = windows.size(-1);
  return windows.reshape({batch, height / window, width / window, window, window, c})
      .permute({0, 1, 3, 2, 4, 5})
      .reshape({batch, height, width, c});
}

}  // namespace matlearn
