#include "io/obj/mtl_textures.h"

#include <cstddef>
#include <cstdint>
#include <optional>

#include "io/obj/obj_loading.h"
#include "matbase/file/file_error.h"
#include "matbase/image/image_file.h"
#include "matbase/image/image_pixels.h"
#include "matbase/text.h"

namespace matgeom::obj {
namespace {

// Linux's PATH_MAX: no longer path names a file that can be opened.
constexpr size_t kMaxPathShown = 4096;

matbase::ImagePixels decode_texture(const std::string& obj_path, const TextureSource& source) {
  matbase::ImagePixels pixels;
  if (const std::optional<std::string> problem = matbase::decode_image_file(source.file, source.name, pixels))
    // The file name is the rest of an MTL line, which may be megabytes long.
    matbase::fail(obj_path, matbase::concat(source.what, ": texture ", matbase::cut_short(source.file.string(), kMaxPathShown), ": ", *problem));
  return pixels;
}

}  // namespace

int TextureTable::color_texture(const TextureSource& source) {
  const auto found = index_of_file_.find(source.file.string());
  if (found != index_of_file_.end()) return found->second;
  images_.push_back(decode_texture(obj_path_, source));
  const int index = static_cast<int>(images_.size()) - 1;
  index_of_file_.emplace(source.file.string(), index);
  return index;
}

int TextureTable::luminance_texture(const TextureSource& source) {
  const auto found = index_of_luminance_.find(source.file.string());
  if (found != index_of_luminance_.end()) return found->second;
  const matbase::ImagePixels rgba = decode_texture(obj_path_, source);
  matbase::ImagePixels luminance = matbase::blank_image(rgba.name + "#luminance", rgba.width, rgba.height, 1);
  for (size_t i = 0; i < luminance.data.size(); ++i) luminance.data[i] = matbase::data_luminance(rgba, i);
  images_.push_back(std::move(luminance));
  const int index = static_cast<int>(images_.size()) - 1;
  index_of_luminance_.emplace(source.file.string(), index);
  return index;
}

int TextureTable::metallic_roughness_texture(const TextureSource* roughness,
                                             const TextureSource* metallic) {
  const std::pair<std::string, std::string> key(roughness ? roughness->file.string() : "",
                                                metallic ? metallic->file.string() : "");
  const auto found = index_of_packed_.find(key);
  if (found != index_of_packed_.end()) return found->second;
  images_.push_back(pack_metallic_roughness(roughness, metallic));
  const int index = static_cast<int>(images_.size()) - 1;
  index_of_packed_.emplace(key, index);
  return index;
}

matbase::ImagePixels TextureTable::pack_metallic_roughness(const TextureSource* roughness_source,
                                                  const TextureSource* metallic_source) const {
  matbase::ImagePixels roughness, metallic;
  if (roughness_source) roughness = decode_texture(obj_path_, *roughness_source);
  if (metallic_source) metallic = decode_texture(obj_path_, *metallic_source);
  if (roughness_source && metallic_source &&
      (roughness.width != metallic.width || roughness.height != metallic.height)) {
    matbase::fail(obj_path_, matbase::concat(roughness_source->what, " (", roughness.width, "x", roughness.height,
                           ") and map_Pm (", metallic.width, "x", metallic.height,
                           ") differ in size; they cannot be packed into one image"));
  }
  const matbase::ImagePixels& shape = roughness_source ? roughness : metallic;
  matbase::ImagePixels packed = matbase::blank_image(
      (roughness_source ? roughness.name : "") + "+" + (metallic_source ? metallic.name : ""), shape.width, shape.height, 3);
  const size_t pixel_count = static_cast<size_t>(shape.width) * static_cast<size_t>(shape.height);
  for (size_t i = 0; i < pixel_count; ++i) {
    packed.data[3 * i + 1] = roughness_source ? matbase::data_luminance(roughness, i) : 255;
    packed.data[3 * i + 2] = metallic_source ? matbase::data_luminance(metallic, i) : 255;
  }
  return packed;
}

}  // namespace matgeom::obj
