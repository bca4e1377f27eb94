#include "metrics/image_pair.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace matlearn {
namespace {

std::string shape(const matbase::FloatImage& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

}  // namespace

void check_image_pair(const char* metric, const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask) {
  const std::string name(metric);
  if (truth.width < 1 || truth.height < 1 || truth.channels < 1 ||
      truth.values.size() != truth.pixel_count() * static_cast<size_t>(truth.channels))
    throw std::invalid_argument(name + ": the true image is empty or its values do not match " + shape(truth));
  if (prediction.width != truth.width || prediction.height != truth.height || prediction.channels != truth.channels)
    throw std::invalid_argument(name + ": the prediction is " + shape(prediction) + " but the truth is " +
                                shape(truth) + " (width x height x channels)");
  if (prediction.values.size() != truth.values.size())
    throw std::invalid_argument(name + ": the prediction's values do not match its shape " + shape(prediction));
  if (mask.empty()) return;
  if (mask.size() != truth.pixel_count())
    throw std::invalid_argument(name + ": the mask has " + std::to_string(mask.size()) + " entries for " +
                                std::to_string(truth.pixel_count()) + " pixels");
  if (std::none_of(mask.begin(), mask.end(), [](uint8_t m) { return m != 0; }))
    throw std::invalid_argument(name + ": the mask covers no pixel");
}

void check_data_range(const char* metric, double data_range) {
  if (!(data_range > 0.0) || !std::isfinite(data_range))
    throw std::invalid_argument(std::string(metric) + ": the data range must be positive and finite, got " +
                                std::to_string(data_range));
}

}  // namespace matlearn
