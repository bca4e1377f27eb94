// frame_strip: dataset images side by side, for the README's study sheets (the paper's Figures
// 3-5 reproduced from configs/paper_studies.yaml): each image's straight-alpha colour over the
// preview's grey, in the order given, 2-pixel gaps; all images of one size.
//
//   frame_strip --output strip.png studies/pillow_uv_scale/var000/images/007.png ...
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "matbase/image/image_writing.h"
#include "matdataset/format/decoded_image.h"

int main(int argc, char** argv) {
  CLI::App app{"frame_strip: dataset images (8-bit sRGB PNGs with alpha) side by side over grey, in one PNG"};
  std::string output;
  std::vector<std::string> frames;
  app.add_option("--output", output, "the PNG written")->required();
  app.add_option("frames", frames, "the images, left to right")->required()->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  constexpr float kGrey = 0.16f, kGap = 0.06f;
  constexpr int kGapPixels = 2;
  try {
    std::vector<matbase::FloatImage> images;
    for (const std::string& frame : frames) images.push_back(matdataset::decode(frame));
    const int w = images.front().width, h = images.front().height;
    for (size_t k = 0; k < images.size(); ++k)
      if (images[k].width != w || images[k].height != h || images[k].channels < 3)
        throw std::runtime_error(frames[k] + ": not a colour image of the first one's size");
    const int strip_w = static_cast<int>(images.size()) * (w + kGapPixels) + kGapPixels, strip_h = h + 2 * kGapPixels;
    std::vector<float> pixels(static_cast<size_t>(strip_w) * strip_h * 3, kGap);
    for (size_t k = 0; k < images.size(); ++k)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const matbase::FloatImage& image = images[k];
          const float a = image.channels > 3 ? image.at(x, y, 3) : 1.0f;
          const size_t p = (static_cast<size_t>(y + kGapPixels) * strip_w +
                            static_cast<size_t>(kGapPixels + static_cast<int>(k) * (w + kGapPixels) + x)) * 3;
          for (int c = 0; c < 3; ++c) pixels[p + static_cast<size_t>(c)] = image.at(x, y, c) * a + kGrey * (1.0f - a);
        }
    // Over grey in the images' own encoding, as the preview draws them.
    matbase::write_data_png(output, strip_w, strip_h, 3, pixels.data(), 255.0, 0.0, false);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frame_strip: %s\n", e.what());
    return 1;
  }
}
