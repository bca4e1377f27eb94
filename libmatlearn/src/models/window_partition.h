#pragma once
// Cutting a grid of tokens into square windows for windowed attention and putting them back: the
// one layout Swin (Liu et al. 2021, section 3.2), SAM's ViT and MobileSAM's TinyViT share. Grids
// are N x H x W x C, channels last; windows are numbered row by row within each image.
#include <torch/torch.h>

namespace matlearn {

// The grid zero-padded at the bottom and right to multiples of `window` (unchanged when it is).
torch::Tensor padded_to_windows(const torch::Tensor& grid, int64_t window);

// N x H x W x C (H, W multiples of `window`) to (N * windows) x window^2 x C.
torch::Tensor partition_windows(const torch::Tensor& grid, int64_t window);

// The inverse of partition_windows for `batch` images of height x width tokens.
torch::Tensor merge_windows(const torch::Tensor& windows, int64_t batch, int64_t height, int64_t width, int64_t window);

}  // namespace matlearn
