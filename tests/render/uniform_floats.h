#pragma once
// Deterministic uniform random floats for the statistical tests.
#include <cstdint>
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
