#pragma once
// Rendering to an error rather than to a sample count (RenderSettings::target_error;
// docs/conventions.md, "Rendering to an error"). The error is the frame's relative RMSE over the
// pixels a surface covers: sqrt(mean over those pixels and the three channels of the squared
// error of the pixel's mean) over the mean of their colour.
//
// A pixel takes a power of two of samples, n, and keeps the sum of the first n / 2
// (PixelSums::first_half). A pixel's samples are its Owen-scrambled Sobol points in order, and
// the first 2^k of them form a net (Owen 1997; Sobol's sequence is a (t, s)-sequence in base 2),
// so each half is a stratified estimate of the same quality, and with A and B their means,
// (A - B)^2 / 4 estimates the squared error of the mean of all n, stratification's gain included.
// (The sample variance over n would ignore that gain and overestimate the error by a third on a
// dataset frame; adaptive sampling's two estimates, split by index parity, correlate with the
// path's later dimensions and disagree by more than the noise.) Over a frame's pixels the
// prediction is unbiased; one pixel's is too noisy to allocate by, so a pixel's spread,
// n (A - B)^2 / 4, is averaged over its 5 x 5 covered neighbours.
//
// Sampling goes in rounds: every pixel first takes the minimum; after each round the frame's
// error is predicted, and while it is above the target the pixels that take most error off per
// sample by doubling (sigma_p^2 / (2 n_p^2)) double, just enough of them for the prediction to
// reach the target. That is the greedy form of the allocation that minimises the frame's error
// for a total, n_p in proportion to sigma_p (Cauchy-Schwarz), and doubling only some pixels lands
// on the target rather than up to a factor sqrt(2) below it. A pixel takes at most the cap. A
// pixel whose samples met no surface but beside covered ones doubles along while it has under
// half their samples (a silhouette may cover it a little; plan_error_target_round says why).
#include <cstdint>
#include <vector>

#include "film/film.h"

namespace matrender {

struct FrameErrorEstimate {
  double relative_rmse = 0.0;       // predicted; 0 when no pixel is covered or the frame is black
  double mean_squared_error = 0.0;  // predicted, a covered pixel's channel on average
  double mean = 0.0;                // the covered pixels' mean colour (over the channels)
  uint64_t pixels = 0;         // covered pixels
};

// A pixel about to double: what it has becomes its first half.
inline void keep_first_half(PixelSums& s) {
  s.first_half = s.color;
  s.first_half_luminance_squares = s.luminance_squares;
}

// Whether a pixel counts in the frame's error: a surface covers it, and it has two halves.
inline bool counts_in_frame_error(const PixelSums& s) { return s.coverage > 0.0 && s.samples >= 2; }

// The frame's error predicted from its pixels' sums (their halves: PixelSums::first_half).
FrameErrorEstimate predict_frame_error(const std::vector<PixelSums>& sums);

// The largest power of two at most `samples` (1 for 0).
uint32_t power_of_two_at_most(uint32_t samples);

// The samples each pixel should have after the next round, for `target_error` (relative RMSE)
// and at most `cap` a pixel (a power of two), from the sums after this round: twice what a
// pixel has, or what it has. Returns false (and leaves `counts` alone) when the next round would
// take no sample: the prediction is at or below the target, or every covered pixel is at the cap.
bool plan_error_target_round(const std::vector<PixelSums>& sums, int width, int height, double target_error,
                             uint32_t cap, std::vector<uint32_t>& counts);

}  // namespace matrender
