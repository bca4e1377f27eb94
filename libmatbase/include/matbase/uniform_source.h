#pragma once
// Seeded random numbers for the built-in objects and the procedural material library.
#include <cstdint>
#include <random>

namespace matbase {

// Uniform numbers from std::mt19937's raw output: the engine's sequence is fixed by the C++
// standard, the library's distributions are not, so objects are identical on every platform.
class UniformSource {
 public:
  explicit UniformSource(uint32_t seed) : engine_(seed) {}

  // 24 random bits scaled into [0, 1).
  double next() { return static_cast<double>(engine_() >> 8) * (1.0 / 16777216.0); }
  double between(double lower, double upper) { return lower + (upper - lower) * next(); }
  uint32_t bits() { return static_cast<uint32_t>(engine_()); }
  // One of `count` choices, uniformly.
  uint32_t choice(uint32_t count) { return bits() % count; }

 private:
  std::mt19937 engine_;
};

}  // namespace matbase
