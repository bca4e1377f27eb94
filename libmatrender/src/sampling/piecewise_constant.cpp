#include "sampling/piecewise_constant.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace matrender {

PiecewiseConstant1D::PiecewiseConstant1D(const std::vector<float>& weights) {
  if (weights.empty()) throw std::invalid_argument("a piecewise-constant distribution needs a cell");
  const size_t n = weights.size();
  std::vector<double> sums(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) {
    if (!(weights[i] >= 0.0f) || std::isinf(weights[i]))
      throw std::invalid_argument("piecewise-constant weights must be finite and non-negative");
    sums[i + 1] = sums[i] + weights[i];
  }
  integral_ = sums[n] / static_cast<double>(n);
  cdf_.resize(n + 1);
  for (size_t i = 0; i <= n; ++i)
    cdf_[i] = static_cast<float>(sums[n] > 0.0 ? sums[i] / sums[n] : static_cast<double>(i) / static_cast<double>(n));
  cdf_[n] = 1.0f;
}

size_t PiecewiseConstant1D::cell_of(float x) const {
  const float scaled = x * static_cast<float>(size());
  if (!(scaled > 0.0f)) return 0;
  return std::min(static_cast<size_t>(scaled), size() - 1);
}

float PiecewiseConstant1D::pdf_of_cell(size_t cell) const {
  // The cell's probability over its width 1 / n.
  return (cdf_[cell + 1] - cdf_[cell]) * static_cast<float>(size());
}

float PiecewiseConstant1D::sample(float u, float* pdf, size_t* cell) const {
  // The cell with cdf[i] <= u < cdf[i + 1]; cells of zero probability have equal bounds and are
  // never chosen, also when u rounds up to 1.
  const auto above = std::upper_bound(cdf_.begin(), cdf_.end(), u);
  size_t i = std::min(static_cast<size_t>(std::max<std::ptrdiff_t>(0, (above - cdf_.begin()) - 1)), size() - 1);
  while (i > 0 && !(cdf_[i + 1] > cdf_[i])) --i;
  const float mass = cdf_[i + 1] - cdf_[i];
  const float within = mass > 0.0f ? std::clamp((u - cdf_[i]) / mass, 0.0f, 1.0f) : 0.5f;
  if (cell) *cell = i;
  if (pdf) *pdf = pdf_of_cell(i);
  const float x = (static_cast<float>(i) + within) / static_cast<float>(size());
  return std::min(x, 0x1.fffffep-1f);
}
PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<float>& weights, size_t width, size_t height) {
  if (width == 0 || height == 0 || weights.size() != width * height)
    throw std::invalid_argument("a piecewise-constant grid needs width x height weights");
  rows_.reserve(height);
  std::vector<float> row_integrals(height);
  for (size_t y = 0; y < height; ++y) {
    rows_.emplace_back(std::vector<float>(weights.begin() + y * width, weights.begin() + (y + 1) * width));
    row_integrals[y] = static_cast<float>(rows_.back().integral());
  }
  marginal_ = PiecewiseConstant1D(row_integrals);
}

glm::vec2 PiecewiseConstant2D::sample(glm::vec2 u, float* pdf) const {
  float pdf_y, pdf_x;
  size_t row;
  const float y = marginal_.sample(u.y, &pdf_y, &row);
  const float x = rows_[row].sample(u.x, &pdf_x, nullptr);
  if (pdf) *pdf = pdf_y * pdf_x;
  return {x, y};
}

float PiecewiseConstant2D::pdf(glm::vec2 p) const {
  const size_t row = marginal_.cell_of(p.y);
  return marginal_.pdf_of_cell(row) * rows_[row].pdf(p.x);
}

}  // namespace matrender
