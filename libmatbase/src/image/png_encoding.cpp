#include "matbase/image/png_encoding.h"

#include <vector>

#include <tiny_gltf.h>

#include "matbase/file/file_error.h"

namespace matbase {
namespace {

bool capture_file(std::string*, const std::string&, const std::vector<unsigned char>& contents,
                  void* destination) {
  static_cast<std::vector<unsigned char>*>(destination)->assign(contents.begin(), contents.end());
  return true;
}

}  // namespace

std::string encode_png(const ImagePixels& pixels, const std::string& path) {
  tinygltf::Image image;
  image.width = pixels.width;
  image.height = pixels.height;
  image.component = pixels.channels;
  image.bits = 8;
  image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image.image = pixels.data;
  std::vector<unsigned char> png;
  tinygltf::FsCallbacks callbacks = {};
  callbacks.WriteWholeFile = capture_file;
  callbacks.user_data = &png;
  const std::string base_directory;
  const std::string file_name = "image.png";  // the extension selects the encoder
  std::string uri;
  if (!tinygltf::WriteImageData(&base_directory, &file_name, &image, /*embedImages=*/false, &uri,
                                &callbacks) ||
      png.empty()) {
    fail(path, "cannot encode image " + pixels.name + " as PNG");
  }
  return std::string(png.begin(), png.end());
}

}  // namespace matbase
