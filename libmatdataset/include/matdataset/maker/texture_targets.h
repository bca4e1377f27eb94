#pragma once
// The paper's texture-target layout as an option of make_dataset (`paper_texture_layout: true`):
// beside the repository's layout, <output>/paper_textures/ holds every frame's screenshot cropped
// onto white under rendered_cropped/<object>/<material>/ and each candidate material's flat maps
// under ground_truth_basecolour/ and the others (matdataset/format/texture_target_writer.h).
#include <filesystem>

#include "matdataset/format/texture_target_writer.h"
#include "matdataset/maker/dataset_config.h"
#include "matmaterial/folder/material_folder.h"

namespace matdataset {

std::filesystem::path texture_target_root(const DatasetConfig& config);

// A material's flat maps as the paper stores them: each parameter's image times its factor, or a
// 64 x 64 swatch of its constant.
MaterialReferences material_references(const matmaterial::FolderMaterial& material);

// Writes the reference maps of every candidate material of the configuration (generating or
// reading each once). Throws matbase::InputError for a folder that cannot be read.
void write_material_references(const DatasetConfig& config);

}  // namespace matdataset
