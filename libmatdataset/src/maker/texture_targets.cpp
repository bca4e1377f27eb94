#include "matdataset/maker/texture_targets.h"

#include <exception>
#include <set>

#include "matbase/image/image_pixels.h"
#include "matbase/image/srgb.h"
#include "matbase/image/unorm.h"
#include "matdataset/format/dataset_folders.h"
#include "matmaterial/library/material_library.h"

namespace matdataset {
namespace {

using matmaterial::MaterialParameter;
constexpr int kSwatch = 64;

// The parameter's value at every texel, three channels: an image's texels times the factor, or
// the constant; colours are sRGB-encoded, scalars linear.
matbase::ImagePixels reference(const matmaterial::FolderMaterial& folder, MaterialParameter parameter, bool colour) {
  const matmaterial::MaterialInput& input = folder.material[parameter];
  const matbase::ImagePixels* image =
      input.image >= 0 && static_cast<size_t>(input.image) < folder.images.size() ? &folder.images[static_cast<size_t>(input.image)]
                                                                                  : nullptr;
  matbase::ImagePixels out = matbase::blank_image(matmaterial::material_parameter(parameter).name,
                                                  image ? image->width : kSwatch, image ? image->height : kSwatch, 3);
  const size_t texels = static_cast<size_t>(out.width) * static_cast<size_t>(out.height);
  for (size_t t = 0; t < texels; ++t)
    for (int c = 0; c < 3; ++c) {
      const double factor = input.value[colour ? c : 0];
      double linear = factor;
      if (image) {
        const double stored = matbase::texel_channel(*image, t, colour ? c : input.channel) / 255.0;
        linear = factor * (colour ? matbase::srgb_to_linear(stored) : stored);
      }
      out.data[3 * t + static_cast<size_t>(c)] = matbase::unorm8(colour ? matbase::linear_to_srgb(linear) : linear);
    }
  return out;
}

}  // namespace

std::filesystem::path texture_target_root(const DatasetConfig& config) {
  return std::filesystem::path(config.output) / kPaperTexturesFolder;
}

MaterialReferences material_references(const matmaterial::FolderMaterial& folder) {
  MaterialReferences references;
  references.base_color = reference(folder, MaterialParameter::BaseColor, true);
  references.roughness = reference(folder, MaterialParameter::Roughness, false);
  references.metallic = reference(folder, MaterialParameter::Metallic, false);
  const int normal = folder.material.normal_image;
  if (normal >= 0 && static_cast<size_t>(normal) < folder.images.size()) {
    const matbase::ImagePixels& image = folder.images[static_cast<size_t>(normal)];
    matbase::ImagePixels map{"normal", image.width, image.height, 3, {}};
    for (size_t t = 0; t < static_cast<size_t>(image.width) * static_cast<size_t>(image.height); ++t)
      for (int c = 0; c < 3; ++c) map.data.push_back(matbase::texel_channel(image, t, c));
    references.normal = std::move(map);
  }
  return references;
}

void write_material_references(const DatasetConfig& config) {
  std::set<std::string> written;
  for (size_t o = 0; o < config.objects.size(); ++o)
    for (const SlotConfig& slot : config.objects[o].slots)
      for (const MaterialCandidate& candidate : slot.candidates) {
        if (!written.insert(candidate.name).second) continue;
        matmaterial::FolderMaterial material;
        try {
          if (const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&candidate.source))
            material = matmaterial::generate_library_material(*spec, {config.render.material_resolution, 0});
          else
            material = matmaterial::read_material_folder(std::get<std::string>(candidate.source));
        } catch (const std::exception& e) {
          throw matbase::InputError(config.source + ": objects." + std::to_string(o) + ".materials." + slot.key + ": " + e.what());
        }
        write_texture_target_references(texture_target_root(config), candidate.name,
                                        material_references(material));
      }
}

}  // namespace matdataset
