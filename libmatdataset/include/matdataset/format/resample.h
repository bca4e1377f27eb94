#pragma once
// Resizing the maps of a sample. resize_bilinear is Pillow's BILINEAR resize (a triangle filter
// widened by the downscale factor, so shrinking averages instead of aliasing), which the
// repository's loader applies to every map; resize_bilinear_weighted is the same filter as a
// normalised convolution, sum w m v / sum w m, so that pixels outside the object (m = 0) do not
// darken the targets along its silhouette (weak point W16); resize_nearest is Pillow's NEAREST,
// for label ids. Segment Anything's input is resized with resize_bilinear too, as its official
// predictor resizes with Pillow.
#include <cstdint>
#include <vector>

#include "matbase/image/float_image.h"

namespace matdataset {

matbase::FloatImage resize_bilinear(const matbase::FloatImage& image, int width, int height);
// weights: one per pixel of `image`. Output pixels whose footprint has no weight get 0.
matbase::FloatImage resize_bilinear_weighted(const matbase::FloatImage& image, const std::vector<float>& weights, int width, int height);
// 0.5 n + 0.5 encoded unit vectors (a normal map), resized as vectors: decoded, resized as
// resize_bilinear_weighted does, renormalised and encoded again, so a resized normal still has
// length 1 (0.5 where no weight reaches). `encoded` has 3 channels.
matbase::FloatImage resize_unit_vectors(const matbase::FloatImage& encoded, const std::vector<float>& weights, int width, int height);
std::vector<int32_t> resize_nearest(const std::vector<int32_t>& ids, int in_width, int in_height, int width, int height);

}  // namespace matdataset
