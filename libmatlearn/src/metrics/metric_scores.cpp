#include "matlearn/metric_scores.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "matlearn/image_metrics.h"
#include "matlearn/paper_compat_metrics.h"

namespace matlearn {
namespace {

matbase::FloatImage cut_out(const matbase::FloatImage& image, const matbase::Mask& mask) {
  if (mask.empty()) return image;
  matbase::FloatImage out = image;
  for (size_t p = 0; p < image.pixel_count(); ++p)
    if (!mask[p])
      for (int c = 0; c < image.channels; ++c) out.values[p * static_cast<size_t>(image.channels) + static_cast<size_t>(c)] = 0.0f;
  return out;
}

}  // namespace

std::string metric_name(Metric metric) {
  switch (metric) {
    case Metric::rmse: return "RMSE";
    case Metric::psnr: return "PSNR";
    case Metric::sre: return "SRE";
    case Metric::ssim: return "SSIM";
    case Metric::fsim: return "FSIM";
    case Metric::uiq: return "UIQ";
    case Metric::sam: return "SAM";
    case Metric::issm: return "ISSM";
  }
  throw std::logic_error("unknown metric");
}

bool higher_is_better(Metric metric) { return metric != Metric::rmse && metric != Metric::sam; }

MetricScores score_map(const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask, MetricConvention convention) {
  MetricScores s;
  if (convention == MetricConvention::paper_compat) {
    namespace pc = paper_compat;
    const pc::Image8 t = pc::quantize_8bit(cut_out(truth, mask)), p = pc::quantize_8bit(cut_out(prediction, mask));
    s[Metric::rmse] = pc::rmse(t, p);
    s[Metric::psnr] = pc::psnr(t, p);
    s[Metric::sre] = pc::sre(t, p);
    s[Metric::ssim] = pc::ssim(t, p);
    s[Metric::fsim] = pc::fsim(t, p);
    s[Metric::uiq] = pc::uiq(t, p);
    s[Metric::sam] = pc::sam_degrees(t, p);
    s[Metric::issm] = pc::issm(t, p);
    return s;
  }
  s[Metric::rmse] = rmse(truth, prediction, 1.0, mask);
  s[Metric::psnr] = psnr(truth, prediction, 1.0, mask);
  s[Metric::sre] = sre(truth, prediction, mask);
  s[Metric::ssim] = ssim(truth, prediction, 1.0, mask);
  s[Metric::fsim] = fsim(truth, prediction, 1.0, mask);
  s[Metric::uiq] = uiq(truth, prediction, mask);
  s[Metric::sam] = truth.channels >= 2 ? sam_degrees(truth, prediction, mask) : std::numeric_limits<double>::quiet_NaN();
  s[Metric::issm] = issm(truth, prediction, mask);
  return s;
}

void ScoreMean::add(const MetricScores& scores) {
  for (size_t m = 0; m < sums_.size(); ++m) {
    if (std::isnan(scores.values[m])) continue;
    sums_[m] += scores.values[m];
    ++counts_[m];
  }
  ++count_;
}

MetricScores ScoreMean::mean() const {
  MetricScores s;
  for (size_t m = 0; m < sums_.size(); ++m)
    s.values[m] = counts_[m] > 0 ? sums_[m] / counts_[m] : std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace matlearn
