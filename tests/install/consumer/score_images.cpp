// The image metrics through the installed libmatlearn_metrics: a map against itself and against
// a copy off by 0.1 everywhere. Exits non-zero if a metric does not give its closed form.
#include <cmath>
#include <cstdio>

#include <matlearn/image_metrics.h>

int main() {
  matbase::FloatImage truth(16, 16, 3, 0.5f), prediction(16, 16, 3, 0.6f);
  const double rmse = matlearn::rmse(truth, prediction, 1.0);
  const double ssim_same = matlearn::ssim(truth, truth, 1.0);
  std::printf("RMSE %f, SSIM of an image with itself %f\n", rmse, ssim_same);
  return std::abs(rmse - 0.1) < 1e-6 && std::abs(ssim_same - 1.0) < 1e-12 ? 0 : 1;
}
