#include "metrics/fft2d.h"

#include <unsupported/Eigen/FFT>

namespace matlearn {
namespace {

void transform(ComplexGrid& grid, int width, int height, bool inverse) {
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> in, out;
  const size_t w = static_cast<size_t>(width), h = static_cast<size_t>(height);
  in.resize(w);
  for (size_t y = 0; y < h; ++y) {
    std::copy(grid.begin() + static_cast<long>(y * w), grid.begin() + static_cast<long>((y + 1) * w), in.begin());
    inverse ? fft.inv(out, in) : fft.fwd(out, in);
    std::copy(out.begin(), out.end(), grid.begin() + static_cast<long>(y * w));
  }
  in.resize(h);
  for (size_t x = 0; x < w; ++x) {
    for (size_t y = 0; y < h; ++y) in[y] = grid[y * w + x];
    inverse ? fft.inv(out, in) : fft.fwd(out, in);
    for (size_t y = 0; y < h; ++y) grid[y * w + x] = out[y];
  }
}

}  // namespace

void fft2d_forward(ComplexGrid& grid, int width, int height) { transform(grid, width, height, false); }
void fft2d_inverse(ComplexGrid& grid, int width, int height) { transform(grid, width, height, true); }

}  // namespace matlearn
