#pragma once
// Adaptive sampling as Blender 3.4's Cycles does it (Render > Sampling > Noise Threshold and Min
// Samples; docs/conventions.md, "Adaptive sampling"). Every pixel keeps a second sum of half its
// samples; at fixed sample counts a pixel whose two estimates agree to the threshold stops, unless
// a neighbour is still sampling. The rules are those of Cycles' Integrator::get_adaptive_sampling
// (scene/integrator.cpp), AdaptiveSampling::need_filter (integrator/adaptive_sampling.cpp) and
// kernel/film/adaptive_sampling.h at v3.4.1.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace matrender {

class AdaptiveSampling {
 public:
  // Pixels are checked every kStep samples (a power of two, as in Cycles).
  static constexpr uint32_t kStep = 16;

  // From the user's settings: noise_threshold 0 turns adaptive sampling off (nullopt);
  // min_samples 0 asks for Cycles' automatic minimum, max(4, ceil(16 / threshold^0.3))
  // (threshold 0.1: 32 samples, 0.01: 64, 0.001: 128).
  static std::optional<AdaptiveSampling> from_settings(double noise_threshold, int min_samples);

  uint32_t min_samples() const { return min_samples_; }
  // The bound the per-pixel error is held to: 5 x the user's threshold (Cycles' "arbitrary
  // factor that makes the threshold more similar to what it was before").
  float error_bound() const { return error_bound_; }

  // The sample count at which pixels are next checked, once the image has taken `samples`
  // samples per pixel: the first multiple of kStep above min_samples + 1 (Cycles checks after
  // sample index s when s > min_samples and s mod kStep = kStep - 1), then every kStep.
  uint32_t next_check(uint32_t samples) const;

 private:
  AdaptiveSampling(float error_bound, uint32_t min_samples) : error_bound_(error_bound), min_samples_(min_samples) {}
  float error_bound_;
  uint32_t min_samples_;
};

// Which half a sample belongs to for the second estimate. Each half should be as well spread
// as the whole, or the two disagree by more than the pixel's noise. Cycles splits its PMJ02
// sequence by the parity of the index's odd bits (Christensen et al. 2018, "Progressive
// Multi-Jittered Sample Sequences", section 10.2.1) and its Sobol sequence by the last bit, which
// for Sobol puts every sample of one half in one half of the pixel. Our pairs are Owen-scrambled
// Sobol: in the first Sobol dimension (the radical inverse) the two samples of a stratum 2^-(m-1)
// wide among the first 2^m differ exactly in index bit m - 1, so the parity of all index bits
// puts one in each half at every m. Applied to the shuffled index of the pixel-filter pair, each
// half is stratified along the pixel's x. Along y no split that is linear in the index bits can
// do the same (the partner's index differs in an even number of bits), so the halves disagree a
// little more than the pixel's noise there, and a pixel errs toward more samples.
inline bool in_second_estimate(uint32_t sobol_index) { return (__builtin_popcount(sobol_index) & 1) != 0; }

// Whether a pixel has converged: the error of Dammertz et al. 2010 ("A hierarchical automatic
// stopping condition for Monte Carlo global illumination", section 2.1) as Cycles 3.4
// normalises it, |I - A|_1 / n / (1e-4 + sqrt(|I|_1 / n)) < error_bound, where I sums all n
// samples of the pixel's colour and A twice those of the second estimate.
bool pixel_converged(const glm::dvec3& sum, const glm::dvec3& second_estimate_sum, uint32_t samples,
                     float error_bound);

// Keeps the neighbours of every pixel still sampling sampling too: `converged` (row-major,
// width x height, 1 = converged) loses its 1 wherever one of the 3 x 3 neighbours is 0, as
// Cycles' two box passes (film_adaptive_sampling_filter_x, then _y) do.
void keep_neighbours_sampling(std::vector<uint8_t>& converged, int width, int height);

}  // namespace matrender
