#pragma once
// Image files decoded for the dataset's readers and checkers: every channel as floats, colour as
// stored; label maps as the integers written.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "matbase/image/float_image.h"

namespace matdataset {

// Every channel of an image file as floats, colour as stored (not premultiplied by alpha, as
// OpenImageIO would by default); 8-bit values map to [0, 1]; a float format's NaN and infinities
// as stored, for checkers that count them. Throws DatasetError (matdataset/format/dataset_error.h) naming
// the file: missing, a device, declaring more pixels than memory holds, undecodable.
matbase::FloatImage decode(const std::filesystem::path& path);

// decode(), for a value that becomes a network's input or target: also throws DatasetError
// naming the file, the pixel and the channel of the first NaN or infinity (EXR holds them).
matbase::FloatImage decode_finite(const std::filesystem::path& path);

// A label map: one id per pixel, row by row.
struct DecodedIds {
  int width = 0, height = 0;
  std::vector<int32_t> ids;
};

// The ids of a one-channel 8- or 16-bit integer image as written (the dataset writer's 8-bit
// label PNG, render_object's 16-bit one): decode() would scale them to [0, 1], where 7 of 65535
// rounds to 0 on 8 bits. Throws DatasetError naming the file for any other channel count or
// sample format, and for decode()'s reasons.
DecodedIds decode_ids(const std::filesystem::path& path);

// The first `channels` channels from `first` on (a grey image repeated), as PIL's
// convert("RGB") or convert("L").
matbase::FloatImage channels_of(const matbase::FloatImage& d, int first, int channels);

// Throws DatasetError naming `path` when its size (width x height) differs from the sample
// image's.
void check_same_size(int width, int height, const matbase::FloatImage& image, const std::filesystem::path& path);

// Throws DatasetError naming `path` when d has fewer than `channels` channels; `what` says what
// they hold ("roughness in G, metallic in B").
void check_channels(const matbase::FloatImage& d, int channels, const char* what, const std::filesystem::path& path);

}  // namespace matdataset
