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

// GrabCut's object pixels (255) and background (0) in `image` from `prompt` (a box given).
cv::Mat grabcut_object(const cv::Mat& image, const Prompt& prompt, const GrabCutSettings& settings) {
  const matbase::PixelBox& box = *prompt.box;
  // Outside the box: background; inside: probably the object; the points' discs: certain.
  cv::Mat labels(image.rows, image.cols, CV_8UC1, cv::Scalar(cv::GC_BGD));
  labels(cv::Rect(box.x0, box.y0, box.width(), box.height())).setTo(cv::GC_PR_FGD);
  const int radius = std::max(1, static_cast<int>(std::lround(settings.point_radius_fraction * std::min(image.cols, image.rows))));
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
  cv::grabCut(image, labels, cv::Rect(), background_model, object_model, settings.iterations, cv::GC_INIT_WITH_MASK);
  return (labels == cv::GC_FGD) | (labels == cv::GC_PR_FGD);
}

}  // namespace

matbase::Mask grabcut_mask(const matbase::FloatImage& rgb, const Prompt& given, const GrabCutSettings& settings) {
  const Prompt prompt = given.box ? given : Prompt{default_prompt(rgb.width, rgb.height).box, given.points};
  cv::Mat object;
  const int longer = std::max(rgb.width, rgb.height);
  if (longer <= settings.working_side) {
    object = grabcut_object(bytes_of(rgb), prompt, settings);
  } else {
    // A large photograph is segmented at the working size (area-averaged), and the object's
    // pixels come back by bilinear interpolation of the 0/1 mask, cut at one half.
    const double scale = static_cast<double>(settings.working_side) / longer;
    const int width = std::max(1, static_cast<int>(std::lround(rgb.width * scale)));
    const int height = std::max(1, static_cast<int>(std::lround(rgb.height * scale)));
    cv::Mat small;
    cv::resize(bytes_of(rgb), small, cv::Size(width, height), 0, 0, cv::INTER_AREA);
    cv::Mat small_object = grabcut_object(small, scaled_prompt(prompt, rgb.width, rgb.height, width, height), settings);
    cv::resize(small_object, object, cv::Size(rgb.width, rgb.height), 0, 0, cv::INTER_LINEAR);
    object = object >= 128;
  }
  matbase::Mask mask(rgb.pixel_count());
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x)
      mask[static_cast<size_t>(y) * static_cast<size_t>(rgb.width) + static_cast<size_t>(x)] = object.at<uint8_t>(y, x) != 0 ? 1 : 0;
  return mask;
}

}  // namespace matlearn
