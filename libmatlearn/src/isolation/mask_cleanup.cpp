#include "matlearn/isolation/mask_cleanup.h"

#include <algorithm>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace matlearn {
namespace {

// The mask as an 8-bit OpenCV image over the same memory.
cv::Mat view_of(const matbase::Mask& mask, int width, int height) {
  if (mask.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("mask cleanup: the mask does not have width x height entries");
  return cv::Mat(height, width, CV_8UC1, const_cast<uint8_t*>(mask.data()));
}

// Each pixel's region number (0 outside the mask) and the number of regions including 0.
int region_labels(const matbase::Mask& mask, int width, int height, int connectivity, cv::Mat& labels) {
  cv::Mat binary;
  cv::compare(view_of(mask, width, height), 0, binary, cv::CMP_NE);
  return cv::connectedComponents(binary, labels, connectivity, CV_32S);
}

matbase::Mask pixels_of_regions(const cv::Mat& labels, const std::vector<bool>& kept) {
  matbase::Mask out(static_cast<size_t>(labels.rows) * static_cast<size_t>(labels.cols), 0);
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      out[static_cast<size_t>(y) * static_cast<size_t>(labels.cols) + static_cast<size_t>(x)] =
          kept[static_cast<size_t>(labels.at<int32_t>(y, x))] ? 1 : 0;
  return out;
}

}  // namespace

matbase::Mask largest_component(const matbase::Mask& mask, int width, int height) {
  cv::Mat labels;
  const int regions = region_labels(mask, width, height, 8, labels);
  std::vector<size_t> area(static_cast<size_t>(regions), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) ++area[static_cast<size_t>(labels.at<int32_t>(y, x))];
  std::vector<bool> kept(static_cast<size_t>(regions), false);
  if (regions > 1) kept[static_cast<size_t>(std::max_element(area.begin() + 1, area.end()) - area.begin())] = true;
  return pixels_of_regions(labels, kept);
}

matbase::Mask components_holding(const matbase::Mask& mask, int width, int height, const std::vector<PromptPoint>& points) {
  cv::Mat labels;
  const int regions = region_labels(mask, width, height, 8, labels);
  std::vector<bool> kept(static_cast<size_t>(regions), false);
  for (const PromptPoint& point : points)
    if (point.x >= 0 && point.y >= 0 && point.x < width && point.y < height)
      kept[static_cast<size_t>(labels.at<int32_t>(point.y, point.x))] = true;
  kept[0] = false;  // a point outside the mask holds no region
  return pixels_of_regions(labels, kept);
}

matbase::Mask filled_holes(const matbase::Mask& mask, int width, int height) {
  matbase::Mask outside(mask.size());
  for (size_t p = 0; p < mask.size(); ++p) outside[p] = mask[p] == 0;
  cv::Mat labels;
  const int regions = region_labels(outside, width, height, 4, labels);
  std::vector<bool> reaches_border(static_cast<size_t>(regions), false);
  for (int x = 0; x < width; ++x)
    reaches_border[static_cast<size_t>(labels.at<int32_t>(0, x))] = reaches_border[static_cast<size_t>(labels.at<int32_t>(height - 1, x))] = true;
  for (int y = 0; y < height; ++y)
    reaches_border[static_cast<size_t>(labels.at<int32_t>(y, 0))] = reaches_border[static_cast<size_t>(labels.at<int32_t>(y, width - 1))] = true;
  matbase::Mask out(mask.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
      const int region = labels.at<int32_t>(y, x);
      out[p] = mask[p] != 0 || (region > 0 && !reaches_border[static_cast<size_t>(region)]) ? 1 : 0;
    }
  return out;
}

matbase::Mask cleaned_object_mask(const matbase::Mask& mask, int width, int height, const Prompt& prompt) {
  std::vector<PromptPoint> foreground;
  for (const PromptPoint& point : prompt.points)
    if (point.foreground) foreground.push_back(point);
  matbase::Mask object = components_holding(mask, width, height, foreground);
  if (std::none_of(object.begin(), object.end(), [](uint8_t v) { return v != 0; }))
    object = largest_component(mask, width, height);
  return filled_holes(object, width, height);
}

}  // namespace matlearn
