#pragma once
// Image files decoded for the dataset's readers and checkers: every channel as floats, colour as
// stored.
#include <filesystem>
#include <vector>

#include "matlearn/image.h"

namespace matlearn {

struct Decoded {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;

  float at(int x, int y, int c) const {
    return values[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) *
                      static_cast<size_t>(channels) + static_cast<size_t>(c)];
  }
};

// Every channel of an image file as floats, colour as stored (not premultiplied by alpha, as
// OpenImageIO would by default); 8-bit values map to [0, 1]. Throws std::runtime_error naming
// the file (missing, a device, declaring more pixels than memory holds, undecodable).
Decoded decode(const std::filesystem::path& path);

// The first `channels` channels from `first` on (a grey image repeated), as PIL's
// convert("RGB") or convert("L").
Image channels_of(const Decoded& d, int first, int channels);

// Throws std::runtime_error naming `path` when d's size differs from the sample image's.
void check_same_size(const Decoded& d, const Decoded& image, const std::filesystem::path& path);

}  // namespace matlearn
