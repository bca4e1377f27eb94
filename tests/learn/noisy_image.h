#pragma once
// The learn tests' noisy copies of an image: fixed-seed Gaussian noise added to every value.
#include <cstdint>
#include <random>

#include "matbase/image/float_image.h"

inline matbase::FloatImage plus_noise(const matbase::FloatImage& image, float sigma, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  matbase::FloatImage noisy = image;
  for (float& v : noisy.values) v += noise(rng);
  return noisy;
}
