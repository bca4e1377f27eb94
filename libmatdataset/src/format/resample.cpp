#include "matdataset/format/resample.h"

#include <algorithm>
#include <cmath>

namespace matdataset {
namespace {

// Weights of the input pixels [first, first + weights.size()) for one output pixel.
struct Footprint {
  int first = 0;
  std::vector<double> weights;
};

// Pillow's antialiased BILINEAR footprints along one axis: output pixel i is centred at
// (i + 0.5) scale in input pixels, with a triangle filter of radius max(scale, 1).
std::vector<Footprint> bilinear_footprints(int in, int out) {
  const double scale = static_cast<double>(in) / out;
  const double radius = std::max(scale, 1.0);
  std::vector<Footprint> footprints(static_cast<size_t>(out));
  for (int i = 0; i < out; ++i) {
    const double centre = (i + 0.5) * scale;
    const int first = std::max(static_cast<int>(centre - radius + 0.5), 0);
    const int last = std::min(static_cast<int>(centre + radius + 0.5), in);
    Footprint& f = footprints[static_cast<size_t>(i)];
    f.first = first;
    double total = 0.0;
    for (int j = first; j < last; ++j) {
      const double w = std::max(0.0, 1.0 - std::abs((j - centre + 0.5) / radius));
      f.weights.push_back(w);
      total += w;
    }
    if (total > 0.0)
      for (double& w : f.weights) w /= total;
  }
  return footprints;
}

// Separable filtering of `channels` interleaved planes: rows first, then columns.
std::vector<double> resample(const std::vector<double>& values, int channels, int in_w, int in_h, int out_w, int out_h) {
  const std::vector<Footprint> fx = bilinear_footprints(in_w, out_w), fy = bilinear_footprints(in_h, out_h);
  const size_t c = static_cast<size_t>(channels);
  std::vector<double> rows(static_cast<size_t>(out_w) * static_cast<size_t>(in_h) * c, 0.0);
  for (int y = 0; y < in_h; ++y)
    for (int x = 0; x < out_w; ++x) {
      const Footprint& f = fx[static_cast<size_t>(x)];
      for (size_t k = 0; k < f.weights.size(); ++k)
        for (size_t ch = 0; ch < c; ++ch)
          rows[(static_cast<size_t>(y) * static_cast<size_t>(out_w) + static_cast<size_t>(x)) * c + ch] +=
              f.weights[k] * values[(static_cast<size_t>(y) * static_cast<size_t>(in_w) + static_cast<size_t>(f.first) + k) * c + ch];
    }
  std::vector<double> out(static_cast<size_t>(out_w) * static_cast<size_t>(out_h) * c, 0.0);
  for (int y = 0; y < out_h; ++y) {
    const Footprint& f = fy[static_cast<size_t>(y)];
    for (size_t k = 0; k < f.weights.size(); ++k)
      for (int x = 0; x < out_w; ++x)
        for (size_t ch = 0; ch < c; ++ch)
          out[(static_cast<size_t>(y) * static_cast<size_t>(out_w) + static_cast<size_t>(x)) * c + ch] +=
              f.weights[k] * rows[((static_cast<size_t>(f.first) + k) * static_cast<size_t>(out_w) + static_cast<size_t>(x)) * c + ch];
  }
  return out;
}

}  // namespace

matbase::FloatImage resize_bilinear(const matbase::FloatImage& image, int width, int height) {
  return resize_bilinear_weighted(image, std::vector<float>(image.pixel_count(), 1.0f), width, height);
}

matbase::FloatImage resize_bilinear_weighted(const matbase::FloatImage& image, const std::vector<float>& weights, int width, int height) {
  const size_t c = static_cast<size_t>(image.channels);
  // Numerator planes w v and the weight plane w, filtered together.
  std::vector<double> planes(image.pixel_count() * (c + 1));
  for (size_t p = 0; p < image.pixel_count(); ++p) {
    for (size_t ch = 0; ch < c; ++ch) planes[p * (c + 1) + ch] = double(weights[p]) * image.values[p * c + ch];
    planes[p * (c + 1) + c] = weights[p];
  }
  const std::vector<double> filtered = resample(planes, image.channels + 1, image.width, image.height, width, height);
  matbase::FloatImage out(width, height, image.channels);
  for (size_t p = 0; p < out.pixel_count(); ++p) {
    const double w = filtered[p * (c + 1) + c];
    for (size_t ch = 0; ch < c; ++ch)
      out.values[p * c + ch] = w > 1e-12 ? static_cast<float>(filtered[p * (c + 1) + ch] / w) : 0.0f;
  }
  return out;
}

std::vector<int32_t> resize_nearest(const std::vector<int32_t>& ids, int in_width, int in_height, int width, int height) {
  std::vector<int32_t> out(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) {
    const int sy = std::min(static_cast<int>((y + 0.5) * in_height / height), in_height - 1);
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(static_cast<int>((x + 0.5) * in_width / width), in_width - 1);
      out[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] =
          ids[static_cast<size_t>(sy) * static_cast<size_t>(in_width) + static_cast<size_t>(sx)];
    }
  }
  return out;
}

matbase::FloatImage resize_unit_vectors(const matbase::FloatImage& encoded, const std::vector<float>& weights, int width, int height) {
  matbase::FloatImage decoded = encoded;
  for (float& v : decoded.values) v = 2.0f * v - 1.0f;
  matbase::FloatImage resized = resize_bilinear_weighted(decoded, weights, width, height);
  for (size_t p = 0; p < resized.pixel_count(); ++p) {
    float* n = &resized.values[p * 3];
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const float scale = length > 0.0f ? 1.0f / length : 0.0f;
    for (int c = 0; c < 3; ++c) n[c] = 0.5f * n[c] * scale + 0.5f;
  }
  return resized;
}

}  // namespace matdataset
