#include "matdataset/maker/material_candidate.h"

#include <stdexcept>

#include <fmt/format.h>

namespace matdataset {

namespace fs = std::filesystem;

MaterialCandidate library_candidate(const matmaterial::LibraryMaterialSpec& spec, std::string spelled) {
  MaterialCandidate candidate;
  candidate.spelled = std::move(spelled);
  candidate.source = spec;
  candidate.name = fmt::format("{}_{}_{}", matmaterial::material_class(spec.material_class).name,
                               matmaterial::resolved_style(spec).name, spec.seed);
  return candidate;
}

MaterialCandidate read_material_candidate(const matbase::DocumentNode& v, const fs::path& base) {
  if (v.is_text()) {
    try {
      MaterialCandidate candidate = library_candidate(matmaterial::parse_library_material(v.text()), v.text());
      candidate.seed_given = v.text().find(':') != std::string::npos;
      return candidate;
    } catch (const std::invalid_argument& e) {
      v.fail(e.what());
    }
  }
  v.expect_keys({"matsynth"});
  const matbase::DocumentNode folder_node = v.required("matsynth");
  const std::string folder = folder_node.text();
  const fs::path path = fs::path(folder).is_absolute() ? fs::path(folder) : base / folder;
  if (!fs::is_directory(path)) folder_node.fail("no folder at " + path.string());
  MaterialCandidate candidate;
  candidate.spelled = folder;
  candidate.source = path.lexically_normal().string();
  candidate.name = path.lexically_normal().filename().string();
  if (candidate.name.empty()) candidate.name = path.lexically_normal().parent_path().filename().string();
  return candidate;
}

matrender::MaterialDescription candidate_scene_material(const MaterialCandidate& candidate, int resolution,
                                                        const matrender::Origin& origin) {
  matrender::MaterialDescription material;
  if (const auto* spec = std::get_if<matmaterial::LibraryMaterialSpec>(&candidate.source))
    material.library = matrender::LibraryMaterialRequest{*spec, resolution, origin};
  else
    material.folder = matrender::MaterialFolderFile{std::get<std::string>(candidate.source), origin};
  return material;
}

nlohmann::ordered_json candidate_scene_json(const MaterialCandidate& candidate, int resolution) {
  if (const auto* folder = std::get_if<std::string>(&candidate.source)) return {{"matsynth", *folder}};
  const auto& spec = std::get<matmaterial::LibraryMaterialSpec>(candidate.source);
  return {{"class", matmaterial::material_class(spec.material_class).name},
          {"style", matmaterial::resolved_style(spec).name},
          {"seed", spec.seed},
          {"resolution", resolution}};
}

}  // namespace matdataset
