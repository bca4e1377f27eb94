#pragma once
// The paper's eight metrics of one predicted map against its truth, together, and their means
// over many maps: what evaluation tables hold.
#include <array>
#include <string>

#include "matbase/image/float_image.h"

namespace matlearn {

// In the order of the paper's tables.
enum class Metric { rmse, psnr, sre, ssim, fsim, uiq, sam, issm };
constexpr std::array<Metric, 8> kAllMetrics = {Metric::rmse, Metric::psnr, Metric::sre, Metric::ssim,
                                               Metric::fsim, Metric::uiq,  Metric::sam, Metric::issm};
std::string metric_name(Metric metric);  // "RMSE", "PSNR", ...
// True where larger is better (PSNR, SRE, SSIM, FSIM, UIQ, ISSM), false for RMSE and SAM.
bool higher_is_better(Metric metric);

struct MetricScores {
  std::array<double, 8> values{};  // indexed by Metric
  double& operator[](Metric m) { return values[static_cast<size_t>(m)]; }
  double operator[](Metric m) const { return values[static_cast<size_t>(m)]; }
};

enum class MetricConvention {
  correct,       // matlearn/image_metrics.h on the float maps, data range 1, masked
  paper_compat,  // image-similarity-measures' conventions on the maps quantised to 8 bits, unmasked
};

// All eight metrics of `prediction` against `truth` (values in [0, 1]). In the correct
// convention only mask pixels count; SAM needs at least two channels and is NaN for one-channel
// maps. In the paper-compatible one pixels outside the mask are set to 0 in both images (the
// object cut out, as on the dataset's black background), then both are quantised to 8 bits and
// compared whole, as the package does.
MetricScores score_map(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask, MetricConvention convention);

// The mean of many maps' scores, metric by metric: NaN entries are skipped (a mean of none is
// NaN); an infinite PSNR (a perfect map) makes the mean infinite.
class ScoreMean {
 public:
  void add(const MetricScores& scores);
  MetricScores mean() const;
  int count() const { return count_; }

 private:
  std::array<double, 8> sums_{};
  std::array<int, 8> counts_{};
  int count_ = 0;
};

}  // namespace matlearn
