#pragma once
// Textures: the image files MTL materials name, decoded into the asset's images, and the
// roughness and metallic maps packed into one metallic-roughness image.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "matgeom/object_asset.h"

namespace matgeom::obj {

// A texture an MTL material names, and how error messages refer to it.
struct TextureSource {
  std::string name;  // as the .mtl writes it
  std::filesystem::path file;
  std::string what;  // "<mtl>: material \"<name>\" map_Kd"
};

// The decoded textures the asset's materials reference, each decoded once.
class TextureTable {
 public:
  explicit TextureTable(std::string obj_path) : obj_path_(std::move(obj_path)) {}

  int color_texture(const TextureSource& source);

  // The luminance of the image (data_luminance, what Blender's float inputs read of a colour), one
  // channel.
  int luminance_texture(const TextureSource& source);

  // Roughness (the luminance of map_Pr) into G and metallic (of map_Pm) into B of one image, R
  // unused (0): glTF's layout, so the glTF writer stores it as it is. A channel without a map is
  // 255 (a factor of 1); materials read only the mapped channels.
  int metallic_roughness_texture(const TextureSource* roughness, const TextureSource* metallic);

  std::vector<matbase::ImagePixels> take_images() { return std::move(images_); }

 private:
  matbase::ImagePixels pack_metallic_roughness(const TextureSource* roughness_source,
                                      const TextureSource* metallic_source) const;

  std::string obj_path_;
  std::map<std::string, int> index_of_file_;
  std::map<std::pair<std::string, std::string>, int> index_of_packed_;
  std::map<std::string, int> index_of_luminance_;
  std::vector<matbase::ImagePixels> images_;
};

}  // namespace matgeom::obj
