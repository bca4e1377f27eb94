#pragma once
// Piecewise-constant distributions over [0, 1) and [0, 1)^2, sampled by inverting their CDFs
// (pbrt-v4, sections A.4.1 and A.5.1, PiecewiseConstant1D/2D). The environment light draws
// directions from one built over its image.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace matrender {

// The density proportional to n non-negative cell weights, cell i covering [i / n, (i + 1) / n).
// Weights that are all zero give the uniform density.
class PiecewiseConstant1D {
 public:
  PiecewiseConstant1D() = default;
  explicit PiecewiseConstant1D(const std::vector<float>& weights);

  size_t size() const { return cdf_.size() - 1; }
  // The mean weight: the integral over [0, 1) of the function the weights are cells of.
  double integral() const { return integral_; }

  // The point u's CDF inversion gives, its density and its cell.
  float sample(float u, float* pdf, size_t* cell) const;
  float pdf(float x) const { return pdf_of_cell(cell_of(x)); }
  float pdf_of_cell(size_t cell) const;
  size_t cell_of(float x) const;

 private:
  // n + 1 entries from 0 to 1. Every density and draw comes from these, so they agree even where
  // rounding to float empties a cell of tiny weight.
  std::vector<float> cdf_;
  double integral_ = 0.0;
};

// The density on [0, 1)^2 proportional to a grid of weights, row-major with `width` columns:
// a marginal density over rows picks y, then that row's conditional density picks x.
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  PiecewiseConstant2D(const std::vector<float>& weights, size_t width, size_t height);

  double integral() const { return marginal_.integral(); }
  // The point (x, y) u gives and its density with respect to area on the unit square.
  glm::vec2 sample(glm::vec2 u, float* pdf) const;
  float pdf(glm::vec2 p) const;

 private:
  std::vector<PiecewiseConstant1D> rows_;
  PiecewiseConstant1D marginal_;
};

}  // namespace matrender
