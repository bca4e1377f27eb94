// The eight metrics together (matlearn/metric_scores.h): identical maps, one-channel maps, the
// paper-compatible convention's cut-out, and means that skip what is undefined.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "matlearn/metric_scores.h"
#include "matlearn/paper_compat_metrics.h"

using namespace matlearn;

namespace {

matbase::FloatImage ramp(int channels) {
  matbase::FloatImage image(24, 24, channels);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      for (int c = 0; c < channels; ++c) image.at(x, y, c) = 0.2f + 0.02f * static_cast<float>(x) + 0.1f * static_cast<float>(c);
  return image;
}

}  // namespace

TEST_CASE("A map scored against itself is perfect on every metric", "[learn]") {
  const matbase::FloatImage a = ramp(3);
  const MetricScores s = score_map(a, a, {}, MetricConvention::correct);
  CHECK(s[Metric::rmse] == 0.0);
  CHECK(std::isinf(s[Metric::psnr]));
  CHECK(s[Metric::ssim] == Approx(1.0));
  CHECK(s[Metric::fsim] == Approx(1.0));
  CHECK(s[Metric::uiq] == Approx(1.0));
  CHECK(s[Metric::sam] == Approx(0.0).margin(1e-6));
  // One channel: no spectral angle.
  CHECK(std::isnan(score_map(ramp(1), ramp(1), {}, MetricConvention::correct)[Metric::sam]));
}

TEST_CASE("The paper-compatible convention cuts the object out and quantises to 8 bits", "[learn]") {
  const matbase::FloatImage truth = ramp(3);
  matbase::FloatImage prediction = truth;
  // Off the mask the prediction is wrong; cut out, that does not count.
  matbase::Mask mask(truth.pixel_count(), 1);
  for (int y = 0; y < 24; ++y) {
    mask[static_cast<size_t>(y * 24)] = 0;
    for (int c = 0; c < 3; ++c) prediction.at(0, y, c) = 1.0f;
  }
  const MetricScores s = score_map(truth, prediction, mask, MetricConvention::paper_compat);
  CHECK(s[Metric::rmse] == 0.0);
  // Without the mask it counts, with the package's max_p of 4095.
  const MetricScores whole = score_map(truth, prediction, {}, MetricConvention::paper_compat);
  CHECK(whole[Metric::rmse] > 0.0);
  CHECK(whole[Metric::rmse] ==
        Approx(paper_compat::rmse(paper_compat::quantize_8bit(truth), paper_compat::quantize_8bit(prediction))));
}

TEST_CASE("Score means skip undefined entries and keep infinities", "[learn]") {
  ScoreMean mean;
  MetricScores a, b;
  a[Metric::rmse] = 0.1;
  b[Metric::rmse] = 0.3;
  a[Metric::sam] = std::numeric_limits<double>::quiet_NaN();
  b[Metric::sam] = 4.0;
  a[Metric::psnr] = std::numeric_limits<double>::infinity();
  b[Metric::psnr] = 30.0;
  mean.add(a);
  mean.add(b);
  CHECK(mean.count() == 2);
  CHECK(mean.mean()[Metric::rmse] == Approx(0.2));
  CHECK(mean.mean()[Metric::sam] == Approx(4.0));
  CHECK(std::isinf(mean.mean()[Metric::psnr]));
  CHECK(std::isnan(ScoreMean().mean()[Metric::ssim]));
  CHECK(metric_name(Metric::issm) == "ISSM");
  CHECK(!higher_is_better(Metric::sam));
}
