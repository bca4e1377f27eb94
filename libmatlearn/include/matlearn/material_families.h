#pragma once
// The MatPredict repository's material families, the ids its label maps hold
// (docs/matpredict_repository.md, section 3): 0 background, 1 concrete, 2 fabric,
// 3 leather, 4 metal, 5 plastic, 6 stone, 7 wood. A fixed table, so no tool reads every label
// file to count classes (the repository's W16).
#include <array>
#include <cstdint>
#include <string>

namespace matlearn {

constexpr int kMaterialFamilyCount = 8;

// The family's name, or "class <id>" outside the table.
std::string material_family_name(int32_t id);

// The repository's visualisation colour of the family (8-bit RGB); grey outside the table.
std::array<uint8_t, 3> material_family_colour(int32_t id);

}  // namespace matlearn
