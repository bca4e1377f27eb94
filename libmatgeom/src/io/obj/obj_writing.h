#pragma once
// Writing: the checks on an asset before it is written, the OBJ and MTL text, and the PNG files
// its materials' maps need.
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "matgeom/mesh.h"
#include "matgeom/object_asset.h"

namespace matgeom::obj {

// Names in OBJ and MTL end at whitespace (tinyobjloader's "usemtl" and "g" read one word,
// Blender trims), so blanks and control characters become '_'; an empty name becomes `fallback`.
std::string obj_safe_name(const std::string& name, const std::string& fallback);

// Hands out names no earlier call returned, appending _2, _3... to repeats.
class UniqueNames {
 public:
  std::string claim(const std::string& wanted);

 private:
  std::set<std::string> taken_;
};

void check_writable(const ObjectAsset& asset);

// A written PNG: its file name beside the .obj and its pixels.
struct ImageFile {
  std::string name;
  matbase::ImagePixels pixels;
};

// The file names of a material's maps ("" for none).
struct MaterialMaps {
  std::string base_color, roughness, metallic, normal;
};

// The PNG files the materials need, each asset image written once: base colour and normal
// images as they are; roughness and metallic as the grey map_Pr and map_Pm MTL has, each the
// channel of its image that the material reads.
class ImageFiles {
 public:
  ImageFiles(const std::vector<matbase::ImagePixels>& images, std::string stem)
      : images_(images), stem_(std::move(stem)) {}

  MaterialMaps maps_of(const matmaterial::MaterialInputs& material);

  const std::vector<ImageFile>& files() const { return files_; }

 private:
  std::string image_file(int image);
  std::string channel_file(int image, int channel, const char* what);
  std::string add(const std::string& name, const matbase::ImagePixels& pixels);

  const std::vector<matbase::ImagePixels>& images_;
  std::string stem_;
  std::set<std::string> written_;
  std::vector<ImageFile> files_;
};

// Materials in the order of the asset, with MTL-safe unique names and their map files.
struct NamedMaterial {
  std::string name;
  const matmaterial::MaterialInputs* desc;
  MaterialMaps maps;
};

// The inverse of MaterialConverter, each map placed by -o and -s (check_writable refused what they
// cannot say). read_obj, like Blender, lets a map replace its factor, so a
// factor other than 1 beside a map does not survive a round trip (it is still written, for
// readers that multiply). MaterialInputs's wrap, specular tint, IOR, a specular image and the label
// id are not written: Blender's importer reads no MTL statement for them.
std::string mtl_text(const std::vector<NamedMaterial>& materials);

std::string obj_text(const TriangleMesh& mesh, const std::string& library,
                     const std::vector<std::string>& group_names,
                     const std::vector<NamedMaterial>& materials);

}  // namespace matgeom::obj
