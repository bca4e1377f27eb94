#include "matlearn/isolation/grabcut.h"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "matbase/input_error.h"
#include "matbase/image/unorm.h"

namespace matlearn {
namespace {

cv::Mat bytes_of(const matbase::FloatImage& rgb) {
  cv::Mat image(rgb.height, rgb.width, CV_8UC3);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x)
      for (int c = 0; c < 3; ++c)
        image.at<cv::Vec3b>(y, x)[c] = matbase::unorm8(rgb.at(x, y, std::min(c, rgb.channels - 1)));
  return image;
}

}  // namespace

matbase::Mask grabcut_mask(const matbase::FloatImage& rgb, const Prompt& given, const GrabCutSettings& settings) {
  const Prompt prompt = given.box ? given : Prompt{default_prompt(rgb.width, rgb.height).box, given.points};
  const matbase::PixelBox& box = *prompt.box;
  // Outside the box: background; inside: probably the object; the points' discs: certain.
  cv::Mat labels(rgb.height, rgb.width, CV_8UC1, cv::Scalar(cv::GC_BGD));
  labels(cv::Rect(box.x0, box.y0, box.width(), box.height())).setTo(cv::GC_PR_FGD);
  const int radius = std::max(1, static_cast<int>(std::lround(settings.point_radius_fraction * std::min(rgb.width, rgb.height))));
  for (const PromptPoint& point : prompt.points)
    cv::circle(labels, cv::Point(point.x, point.y), radius, point.foreground ? cv::GC_FGD : cv::GC_BGD, cv::FILLED);
  // Each colour model is a mixture of 5 Gaussians, seeded by k-means: 5 pixels of each at least.
  constexpr int kLeastPixelsPerModel = 5;
  if (cv::countNonZero(labels == cv::GC_BGD) < kLeastPixelsPerModel)
    throw matbase::InputError("GrabCut learns the background from what lies outside the box: this box covers the whole "
                              "image and no point is marked background; give a tighter box or a background point (X,Y,0)");
  if (cv::countNonZero(labels == cv::GC_PR_FGD) + cv::countNonZero(labels == cv::GC_FGD) < kLeastPixelsPerModel)
    throw matbase::InputError("GrabCut learns the object from what lies inside the box: this box holds fewer than 5 pixels");
  // GrabCut seeds its colour models by k-means from OpenCV's per-thread generator: reset it, so
  // that the mask depends on the image and prompt alone.
  cv::theRNG().state = 0x2545F4914F6CDD1DULL;
  cv::Mat background_model, object_model;
  cv::grabCut(bytes_of(rgb), labels, cv::Rect(), background_model, object_model, settings.iterations, cv::GC_INIT_WITH_MASK);
  matbase::Mask mask(rgb.pixel_count());
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) {
      const uint8_t label = labels.at<uint8_t>(y, x);
      mask[static_cast<size_t>(y) * static_cast<size_t>(rgb.width) + static_cast<size_t>(x)] =
          label == cv::GC_FGD || label == cv::GC_PR_FGD ? 1 : 0;
    }
  return mask;
}

}  // namespace matlearn
