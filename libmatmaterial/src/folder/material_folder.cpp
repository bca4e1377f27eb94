#include "matmaterial/folder/material_folder.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string_view>
#include <system_error>

#include <nlohmann/json.hpp>
#include <stb_image_resize.h>

#include "matbase/document/document_node.h"
#include "matbase/document/json_document.h"
#include "matbase/file/atomic_file.h"
#include "matbase/file/file_error.h"
#include "matbase/file/input_file.h"
#include "matbase/image/image_file.h"
#include "matbase/image/png_encoding.h"
#include "matbase/text.h"
#include "matbase/text_encoding.h"
#include "matmaterial/material_parameters.h"

namespace matmaterial {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The maps, declared once: the file the writer names each, the words the reader finds it by (in
// priority order: the repository's, then those of common PBR packs), its colour space, and the
// parameter it feeds (none for the normal, height and specular maps).
struct FolderMapInfo {
  FolderMap map;
  const char* file_stem;
  std::array<const char*, 5> keywords;  // unused entries are empty
  ColorSpace space;
  std::optional<MaterialParameter> parameter;
};

constexpr std::array<FolderMapInfo, kFolderMapCount> kFolderMaps = {{
    {FolderMap::BaseColor, "basecolor", {"basecolor", "base_color", "albedo", "diffuse", "color"}, ColorSpace::SRGB,
     MaterialParameter::BaseColor},
    {FolderMap::Roughness, "roughness", {"roughness", "rough", "", "", ""}, ColorSpace::NonColor,
     MaterialParameter::Roughness},
    {FolderMap::Metallic, "metallic", {"metallic", "metalness", "", "", ""}, ColorSpace::NonColor,
     MaterialParameter::Metallic},
    {FolderMap::Normal, "normal", {"normal", "nor_gl", "nor_dx", "", ""}, ColorSpace::NonColor, std::nullopt},
    {FolderMap::Opacity, "opacity", {"opacity", "alpha", "", "", ""}, ColorSpace::NonColor, MaterialParameter::Alpha},
    {FolderMap::Height, "height", {"height", "displacement", "", "", ""}, ColorSpace::NonColor, std::nullopt},
    {FolderMap::Specular, "specular", {"specular", "", "", "", ""}, ColorSpace::NonColor, std::nullopt},
}};

constexpr const char* kMetadataFile = "metadata.json";

// What stb_image decodes (image_file.h).
bool is_image_file(const fs::path& file) {
  const std::string extension = matbase::lowercase_extension(file);
  return extension == ".png" || extension == ".jpg" || extension == ".jpeg" || extension == ".bmp" ||
         extension == ".tga";
}

// Image formats PBR packs also ship maps in, which a folder does not read: a map found only in one
// of them is refused by name rather than left out without a word.
bool is_unread_image_file(const fs::path& file) {
  const std::string extension = matbase::lowercase_extension(file);
  for (const char* unread : {".exr", ".tif", ".tiff", ".hdr", ".webp", ".psd", ".jxl", ".dds", ".ktx2"})
    if (extension == unread) return true;
  return false;
}

// How well a file's lower-case stem names a map: the length of the longest keyword it contains
// (so "specular_color" is a specular map, not a colour one), 0 for none; `rank` receives that
// keyword's priority within the map.
size_t match_length(const std::string& stem, const FolderMapInfo& info, size_t* rank) {
  size_t best = 0;
  for (size_t k = 0; k < info.keywords.size(); ++k) {
    const std::string_view keyword = info.keywords[k];
    if (keyword.empty() || stem.find(keyword) == std::string::npos || keyword.size() <= best) continue;
    best = keyword.size();
    *rank = k;
  }
  return best;
}

// Each image file of the folder goes to the map it names best; each map takes, of its files, one
// whose stem is its keyword, else the one of the highest-priority keyword, else the first by name.
// The map a lower-case file stem names best (kFolderMapCount for none), and that keyword's rank.
size_t map_named(const std::string& stem, size_t* rank) {
  size_t best_length = 0, best_map = kFolderMapCount;
  for (size_t m = 0; m < kFolderMapCount; ++m) {
    size_t keyword_rank = 0;
    const size_t length = match_length(stem, kFolderMaps[m], &keyword_rank);
    if (length > best_length) {
      best_length = length;
      best_map = m;
      *rank = keyword_rank;
    }
  }
  return best_map;
}

// Refuses a folder that has a map only in a format it does not read ("wood_roughness.exr").
void check_unread_maps(const fs::path& folder, const std::array<fs::path, kFolderMapCount>& maps) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (is_unread_image_file(entry.path())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    size_t rank = 0;
    const size_t map = map_named(matbase::lowercase(file.stem().string()), &rank);
    if (map == kFolderMapCount || !maps[map].empty()) continue;
    std::string format = matbase::lowercase_extension(file).substr(1);
    for (char& c : format) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    matbase::fail(folder.string(), matbase::concat("the ", kFolderMaps[map].file_stem, " map ", file.filename().string(), " is in ",
                                                   format, " format, which material folders do not read (PNG, JPEG, BMP or "
                                                   "TGA): convert it, or it would be left out"));
  }
}

std::array<fs::path, kFolderMapCount> find_maps(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (is_image_file(entry.path())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  struct Candidate {
    bool exact;
    size_t rank;
    fs::path file;
  };
  std::array<std::optional<Candidate>, kFolderMapCount> chosen;
  for (const fs::path& file : files) {
    const std::string stem = matbase::lowercase(file.stem().string());
    size_t best_rank = 0;
    const size_t best_map = map_named(stem, &best_rank);
    if (best_map == kFolderMapCount) continue;
    const Candidate candidate{stem == kFolderMaps[best_map].keywords[best_rank], best_rank, file};
    std::optional<Candidate>& slot = chosen[best_map];
    // Files come in name order, so the first of equal standing stays.
    if (!slot || (candidate.exact && !slot->exact) || (candidate.exact == slot->exact && candidate.rank < slot->rank))
      slot = candidate;
  }
  std::array<fs::path, kFolderMapCount> maps;
  for (size_t m = 0; m < kFolderMapCount; ++m)
    if (chosen[m]) maps[m] = chosen[m]->file;
  check_unread_maps(folder, maps);
  return maps;
}

// What metadata.json says: MatSynth's "category" and "physical_size" (centimetres), and ours,
// "normal_convention" and "parameters" (table constants by scene-file key).
struct Metadata {
  std::optional<MaterialClass> material_class;
  std::optional<double> tile_size_m;
  std::optional<NormalConvention> normal_convention;
  std::vector<std::pair<MaterialParameter, glm::dvec3>> parameters;
};

// A table constant as metadata.json gives it: [r, g, b] for a colour, a number for a scalar,
// within the parameter's range.
glm::dvec3 parameter_value(const MaterialParameterInfo& info, const matbase::DocumentNode& value) {
  if (info.kind == ParameterKind::Scalar) return glm::dvec3(value.number_in(info.min, info.max));
  const std::vector<matbase::DocumentNode> rgb = value.items(3, "[r, g, b]");
  return {rgb[0].number_in(info.min, info.max), rgb[1].number_in(info.min, info.max),
          rgb[2].number_in(info.min, info.max)};
}

// MatSynth's categories that are no class of ours: the folder's name decides for them.
constexpr std::array<const char*, 3> kCategoriesWithoutClass = {"ground", "misc", "blends"};

// The class a metadata.json category names (case-insensitively), none for MatSynth's categories
// without one; any other word is refused (a misspelt class would otherwise label the material 0).
std::optional<MaterialClass> category_class(const matbase::DocumentNode& node) {
  const std::string category = node.text();
  const std::string name = matbase::lowercase(category);
  const std::optional<MaterialClass> named = material_class_named(name);
  if (named && named != MaterialClass::Background) return named;
  if (std::find(kCategoriesWithoutClass.begin(), kCategoriesWithoutClass.end(), name) != kCategoriesWithoutClass.end())
    return std::nullopt;
  std::string known;
  for (const MaterialClassInfo& info : kMaterialClasses)
    if (info.id != MaterialClass::Background) known += std::string(known.empty() ? "" : ", ") + info.name;
  for (const char* without_class : kCategoriesWithoutClass) known += std::string(", ") + without_class;
  node.fail("unknown category " + matbase::excerpt(category) + " (known: " + known + ")");
}

// MatSynth's metadata.json holds more keys than these (name, tags, license...), which are left
// alone.
Metadata read_metadata(const fs::path& file) {
  Metadata metadata;
  std::error_code missing;
  if (!fs::exists(file, missing)) return metadata;
  std::string bytes;
  if (const std::optional<std::string> problem = matbase::read_whole_file(file, bytes)) matbase::fail(file.string(), *problem);
  // Saved as UTF-16 by a Windows editor, it is read as the same text in UTF-8.
  std::string text;
  if (const std::optional<std::string> problem = matbase::decode_marked_text(bytes, text)) matbase::fail(file.string(), *problem);
  std::istringstream in(text);
  const matbase::DocumentValue document = matbase::parse_json_document(in, file.string());
  const matbase::DocumentSource source(file.string(), matbase::PathStyle::JsonPointer);
  const matbase::DocumentNode root(document, source);
  if (!root.is_mapping()) root.fail_expected("a JSON object");
  if (const auto category = root.find("category")) metadata.material_class = category_class(*category);
  if (!root.is_null_at("physical_size"))
    if (const auto size = root.find("physical_size")) metadata.tile_size_m = size->positive() / 100.0;  // centimetres
  if (const auto convention = root.find("normal_convention"))
    metadata.normal_convention =
        convention->choice({"opengl", "directx"}) == 0 ? NormalConvention::OpenGL : NormalConvention::DirectX;
  if (const auto parameters = root.find("parameters"))
    for (const auto& [key, value] : parameters->members()) {
      const std::optional<MaterialParameter> p = material_parameter_named(key);
      if (!p) value.fail("unknown material parameter");
      metadata.parameters.emplace_back(*p, parameter_value(material_parameter(*p), value));
    }
  return metadata;
}

// The convention a normal map's file name states ("normal_dx", "NormalGL", "nor_dx"), if any.
std::optional<NormalConvention> convention_in_name(const fs::path& file) {
  const std::string stem = matbase::lowercase(file.stem().string());
  for (const char* dx : {"normaldx", "normal_dx", "normal-dx", "nor_dx", "directx"})
    if (stem.find(dx) != std::string::npos) return NormalConvention::DirectX;
  for (const char* gl : {"normalgl", "normal_gl", "normal-gl", "nor_gl", "opengl"})
    if (stem.find(gl) != std::string::npos) return NormalConvention::OpenGL;
  return std::nullopt;
}

// Resized to width x height: sRGB maps filtered on linear values, data maps on their values.
matbase::ImagePixels resampled(const matbase::ImagePixels& image, int width, int height, ColorSpace space) {
  if (image.width == width && image.height == height) return image;
  matbase::ImagePixels out = image;
  out.width = width;
  out.height = height;
  out.data.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * 4u, 0);
  const int ok = space == ColorSpace::SRGB
                     ? stbir_resize_uint8_srgb(image.data.data(), image.width, image.height, 0, out.data.data(), width,
                                               height, 0, 4, 3, 0)
                     : stbir_resize_uint8(image.data.data(), image.width, image.height, 0, out.data.data(), width,
                                          height, 0, 4);
  if (!ok) throw std::runtime_error(image.name + ": cannot resample the image");
  return out;
}

bool is_grey(const matbase::ImagePixels& rgba) {
  for (size_t i = 0; i + 3 < rgba.data.size(); i += 4)
    if (rgba.data[i] != rgba.data[i + 1] || rgba.data[i] != rgba.data[i + 2]) return false;
  return true;
}

// A data map read through one channel: what Blender feeds a float socket, its luminance.
void to_luminance(matbase::ImagePixels& rgba) {
  for (size_t pixel = 0; pixel < rgba.data.size() / 4; ++pixel) {
    const uint8_t grey = matbase::data_luminance(rgba, pixel);
    for (int c = 0; c < 3; ++c) rgba.data[4 * pixel + static_cast<size_t>(c)] = grey;
  }
}

}  // namespace

FolderMaterial read_material_folder(const std::string& folder_name, const MaterialFolderOptions& options) {
  const fs::path folder(folder_name);
  std::error_code error;
  if (!fs::exists(folder, error)) matbase::fail(folder_name, "no such folder");
  if (!fs::is_directory(folder, error)) matbase::fail(folder_name, "not a folder");
  const std::array<fs::path, kFolderMapCount> files = find_maps(folder);
  // A material of constants only (glossy plastic, clear glass) is a metadata.json alone.
  if (std::all_of(files.begin(), files.end(), [](const fs::path& f) { return f.empty(); }) &&
      !fs::exists(folder / kMetadataFile, error))
    matbase::fail(folder_name,
         "no material map in the folder (PNG, JPEG, BMP or TGA files named basecolor, albedo, diffuse, roughness, "
         "metallic, normal, opacity, height or specular) and no metadata.json");
  const Metadata metadata = read_metadata(folder / kMetadataFile);

  FolderMaterial result;
  const std::string name = folder.filename().empty() ? folder.parent_path().filename().string()
                                                     : folder.filename().string();
  result.material = MaterialInputs(name);
  result.material_class = metadata.material_class ? metadata.material_class : material_class_of_folder(name);
  result.material.label_id = result.material_class ? label_id(*result.material_class) : 0;
  result.tile_size_m = metadata.tile_size_m;

  // Every map at the size of the base colour (or of the first map there is).
  std::array<matbase::ImagePixels, kFolderMapCount> maps;
  int width = 0, height = 0;
  for (size_t m = 0; m < kFolderMapCount; ++m) {
    if (files[m].empty()) continue;
    result.files[m] = files[m].string();
    if (const std::optional<std::string> problem = matbase::decode_image_file(files[m], files[m].string(), maps[m]))
      matbase::fail(files[m].string(), *problem);
    if (width == 0) {
      width = maps[m].width;
      height = maps[m].height;
    }
  }
  for (size_t m = 0; m < kFolderMapCount; ++m) {
    if (files[m].empty()) continue;
    const FolderMapInfo& info = kFolderMaps[m];
    matbase::ImagePixels image = resampled(maps[m], width, height, info.space);
    if (info.map == FolderMap::Normal) {
      if (is_grey(image))
        matbase::fail(files[m].string(), "the normal map is grey (a height or bump map?); a normal map holds directions in RGB");
      const NormalConvention convention = options.normal_convention.value_or(
          metadata.normal_convention.value_or(convention_in_name(files[m]).value_or(NormalConvention::OpenGL)));
      // DirectX's green points down the image: flipped, it points along +v as the renderer reads it.
      if (convention == NormalConvention::DirectX)
        for (size_t i = 1; i < image.data.size(); i += 4) image.data[i] = static_cast<uint8_t>(255 - image.data[i]);
    } else if (info.space == ColorSpace::NonColor && !is_grey(image)) {
      to_luminance(image);
    }
    const int index = static_cast<int>(result.images.size());
    result.images.push_back(std::move(image));
    if (info.parameter) {
      result.material.set(*info.parameter, 1.0);
      result.material.set_image(*info.parameter, index, 0);
    } else if (info.map == FolderMap::Normal) {
      result.material.normal_image = index;
    } else if (info.map == FolderMap::Height) {
      result.height_image = index;
    } else {
      result.specular_image = index;
    }
  }
  for (const auto& [p, value] : metadata.parameters) result.material.set(p, value);
  return result;
}

void write_material_folder(const FolderMaterial& material, const std::string& folder_name) {
  const fs::path folder(folder_name);
  const MaterialInputs& desc = material.material;
  matbase::AtomicFileSet files(folder / kMetadataFile);
  json parameters = json::object();
  const auto write_map = [&](const FolderMapInfo& info, int image) {
    if (image < 0) return;
    if (static_cast<size_t>(image) >= material.images.size())
      throw std::invalid_argument(matbase::concat("write_material_folder: ", info.file_stem, " image ", image, " out of range"));
    const fs::path path = folder / (std::string(info.file_stem) + ".png");
    files.stage(path, matbase::encode_png(material.images[static_cast<size_t>(image)], path.string()));
  };
  for (const MaterialParameterInfo& info : kMaterialParameters) {
    const bool has_map = std::any_of(kFolderMaps.begin(), kFolderMaps.end(),
                                     [&](const FolderMapInfo& map) { return map.parameter == info.id; });
    if (desc[info.id].image >= 0 && !has_map)
      throw std::invalid_argument(matbase::concat("write_material_folder: ", info.name,
                                         " comes from an image, and a material folder has no map for it"));
  }
  for (const FolderMapInfo& info : kFolderMaps) {
    const MaterialInput* input = info.parameter ? &desc[*info.parameter] : nullptr;
    if (input && input->image >= 0 && input->channel != 0)
      throw std::invalid_argument(matbase::concat("write_material_folder: ", material_parameter(*info.parameter).name,
                                         " reads image channel ", input->channel, "; a map file is read from R"));
  }
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) matbase::fail(folder_name, "cannot create the folder (" + error.message() + ")");
  for (const FolderMapInfo& info : kFolderMaps) {
    if (info.parameter) {
      write_map(info, desc[*info.parameter].image);
    } else if (info.map == FolderMap::Normal) {
      write_map(info, desc.normal_image);
    } else {
      write_map(info, info.map == FolderMap::Height ? material.height_image : material.specular_image);
    }
  }
  // Every constant the reader would not make by itself: the factor of a map (1 when read), the
  // table's default otherwise.
  for (const MaterialParameterInfo& info : kMaterialParameters) {
    const MaterialInput& input = desc[info.id];
    const glm::dvec3 reader_value = input.image >= 0 ? glm::dvec3(1.0) : glm::dvec3(info.default_value);
    if (input.value == reader_value) continue;
    parameters[info.name] = info.kind == ParameterKind::Color ? json{input.value.r, input.value.g, input.value.b}
                                                              : json(input.value.x);
  }
  json metadata = {{"name", desc.name}, {"normal_convention", "opengl"}, {"parameters", parameters}};
  if (material.material_class) metadata["category"] = material_class(*material.material_class).name;
  if (material.tile_size_m) metadata["physical_size"] = *material.tile_size_m * 100.0;
  files.stage(folder / kMetadataFile, metadata.dump(2) + "\n");
  files.commit();
}

}  // namespace matmaterial
