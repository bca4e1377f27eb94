#pragma once
// PBR materials stored as a folder of image maps, the way MatSynth's materials are exported and
// common PBR packs ship them: basecolor.png, roughness.png, normal.png, ... and, optionally, a
// metadata.json (MatSynth's per-material metadata). The reader finds maps by name, reads each in
// its colour space, turns DirectX normal maps into OpenGL ones, resamples maps of other sizes to
// the base colour's and fills in missing maps with the table's defaults; the writer writes the
// same layout, which the procedural library uses, so one reader reads both (docs/scene_format.md,
// "Material folders").
#include <optional>
#include <string>
#include <vector>

#include "matbase/image/image_pixels.h"
#include "matmaterial/material_classes.h"
#include "matmaterial/material_inputs.h"

namespace matmaterial {

// Which way a tangent-space normal map's green channel points: +v (OpenGL, Blender's and
// MatSynth's) or -v (DirectX).
enum class NormalConvention { OpenGL, DirectX };

// The maps a folder may hold, in the order the writer writes and the docs list them.
enum class FolderMap { BaseColor, Roughness, Metallic, Normal, Opacity, Height, Specular };
constexpr size_t kFolderMapCount = 7;

struct FolderMaterial {
  // Named after the folder, labelled with its class (0 without one); its images index `images`.
  MaterialInputs material;
  std::vector<matbase::ImagePixels> images;
  // From metadata.json's category, else the folder's name (material_class_of_folder).
  std::optional<MaterialClass> material_class;
  // The length one repeat of the maps covers on a surface, in metres (metadata.json), which sets
  // how densely the UV pass lays them out.
  std::optional<double> tile_size_m;
  // The height and specular maps are kept but shade nothing: the renderer has no displacement,
  // and MatSynth's specular colour has no Principled input of its own. -1 when absent.
  int height_image = -1;
  int specular_image = -1;
  // The file each map was read from (empty when the folder has none), by FolderMap.
  std::array<std::string, kFolderMapCount> files;
};

struct MaterialFolderOptions {
  // Overrides what metadata.json and the normal map's file name say; OpenGL when nothing does.
  std::optional<NormalConvention> normal_convention;
};

// Reads the material in `folder`. Throws std::runtime_error starting with the folder, or with the
// file at fault, and naming the problem: no such folder, no map in it, an image that cannot be
// decoded, a normal map with no colour in it, a metadata.json that is not what it should be.
FolderMaterial read_material_folder(const std::string& folder, const MaterialFolderOptions& options = {});

// Writes `material` into `folder` (created if missing; nothing else in it is touched) as the
// reader reads it: one PNG per textured map, OpenGL normals, and a metadata.json with the class,
// the tile size and every constant of the material table that is not its default. The files
// appear together or not at all.
void write_material_folder(const FolderMaterial& material, const std::string& folder);

}  // namespace matmaterial
