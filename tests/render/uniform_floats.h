#pragma once
// Deterministic uniform random floats for the statistical tests.
#include <cmath>
#include <cstdint>
#include <algorithm>
#include <random>

#include <glm/glm.hpp>

// Uniform floats in [0, 1) from the top 24 bits of a 64-bit Mersenne Twister: every value is a
// multiple of 2^-24, exactly representable, and 1 never occurs. (std::uniform_real_distribution
// is implementation-defined, so expectations would differ between standard libraries.)
class UniformFloats {
 public:
  explicit UniformFloats(std::uint64_t seed) : engine_(seed) {}
  float next() { return static_cast<float>(engine_() >> 40) * 0x1p-24f; }
  glm::vec2 next2() {
    const float u = next();
    return {u, next()};
  }

 private:
  std::mt19937_64 engine_;
};

// Uniformly distributed over the upper hemisphere (cos theta uniform in (0, 1]).
inline glm::vec3 random_upper_direction(UniformFloats& rng) {
  const float cos_theta = 1.0f - rng.next();
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 6.28318530717958647692f * rng.next();
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// Uniformly distributed over the whole sphere.
inline glm::vec3 random_unit_vector(UniformFloats& rng) {
  const float z = 1.0f - 2.0f * rng.next();
  const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  const float phi = 6.28318530717958647692f * rng.next();
  return {r * std::cos(phi), r * std::sin(phi), z};
}
