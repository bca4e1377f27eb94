#pragma once
// Two-dimensional discrete Fourier transforms of row-major complex grids, any size (Eigen's FFT
// module, kissfft underneath): rows first, then columns.
#include <complex>
#include <vector>

namespace matlearn {

using ComplexGrid = std::vector<std::complex<double>>;  // height rows of width values

// In place. The inverse divides by width * height, so inverse(forward(g)) == g.
void fft2d_forward(ComplexGrid& grid, int width, int height);
void fft2d_inverse(ComplexGrid& grid, int width, int height);

}  // namespace matlearn
