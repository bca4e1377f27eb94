#include "matlearn/denoising/hdr_transfer.h"

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "matbase/image/srgb.h"

namespace matlearn {
namespace {

// ln(1 + kTransferMax / kTransferToe): the denominator of equation 1.
const double kTransferScale = std::log1p(static_cast<double>(kTransferMax) / kTransferToe);

float usable(float v) { return std::isfinite(v) && v > 0.0f ? v : 0.0f; }

}  // namespace

torch::Tensor hdr_transfer(const torch::Tensor& exposed) {
  const torch::Tensor v = torch::nan_to_num(exposed, 0.0, kTransferMax, 0.0).clamp(0.0, kTransferMax);
  return torch::log1p(v / kTransferToe) / kTransferScale;
}

torch::Tensor hdr_transfer_inverse(const torch::Tensor& transferred) {
  const torch::Tensor t = torch::nan_to_num(transferred, 0.0, 1.0, 0.0).clamp(0.0, 1.0);
  return torch::expm1(t * kTransferScale) * kTransferToe;
}

float auto_exposure(const float* rgb, int width, int height) {
  double log_sum = 0.0;
  size_t blocks = 0;
  for (int by = 0; by < height; by += kExposureBlock)
    for (int bx = 0; bx < width; bx += kExposureBlock) {
      double luminance = 0.0;
      int pixels = 0;
      for (int y = by; y < std::min(height, by + kExposureBlock); ++y)
        for (int x = bx; x < std::min(width, bx + kExposureBlock); ++x, ++pixels) {
          const float* p = rgb + 3 * (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x));
          luminance += matbase::rec709_luminance(glm::dvec3(usable(p[0]), usable(p[1]), usable(p[2])));
        }
      luminance /= std::max(pixels, 1);
      if (luminance > kDarkBlock) {
        log_sum += std::log(luminance);
        ++blocks;
      }
    }
  if (blocks == 0) return 1.0f;
  const double exposure = kExposureKey / std::exp(log_sum / static_cast<double>(blocks));
  return std::isfinite(exposure) ? static_cast<float>(exposure) : 1.0f;
}

}  // namespace matlearn
