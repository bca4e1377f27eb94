#pragma once
// A material make_dataset may put on a surface: a library material ("wood/raw:3") or a
// MatSynth-style folder, as the configuration names it, and what the renderer and a scene file
// make of it.
#include <filesystem>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "matbase/document/document_node.h"
#include "matmaterial/library/material_library.h"
#include "matrender/scene_description.h"

namespace matdataset {

struct MaterialCandidate {
  std::string spelled;  // as the configuration gives it ("wood/raw:3", "materials/oak_01")
  std::variant<matmaterial::LibraryMaterialSpec, std::string> source;  // the folder path, resolved
  std::string name;  // its name in the dataset: "wood_raw_3" (library), the folder's name
  bool seed_given = false;  // a library material spelled with its ":seed"
};

// A candidate as the configuration spells it: a library material's text or {matsynth: FOLDER},
// the folder resolved against `base`. Fails at `node` naming the problem (an unknown class or
// style, a folder that is not there).
MaterialCandidate read_material_candidate(const matbase::DocumentNode& node, const std::filesystem::path& base);

// The library material `spec` as a candidate named as read_material_candidate names it.
MaterialCandidate library_candidate(const matmaterial::LibraryMaterialSpec& spec, std::string spelled);

// The scene material of a candidate: generated at `resolution` texels a side, or read from its folder.
matrender::MaterialDescription candidate_scene_material(const MaterialCandidate& candidate, int resolution,
                                                        const matrender::Origin& origin);

// The candidate as a scene file's material: {"class", "style", "seed", "resolution"} or {"matsynth"}.
nlohmann::ordered_json candidate_scene_json(const MaterialCandidate& candidate, int resolution);

}  // namespace matdataset
