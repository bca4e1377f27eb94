#include "matlearn/material_families.h"

namespace matlearn {
namespace {

struct Family {
  const char* name;
  std::array<uint8_t, 3> colour;
};

constexpr std::array<Family, kMaterialFamilyCount> kFamilies = {{{"background", {30, 30, 30}},
                                                                 {"concrete", {230, 85, 13}},
                                                                 {"fabric", {49, 130, 189}},
                                                                 {"leather", {227, 26, 28}},
                                                                 {"metal", {106, 61, 154}},
                                                                 {"plastic", {255, 127, 0}},
                                                                 {"stone", {177, 89, 40}},
                                                                 {"wood", {51, 160, 44}}}};

bool in_table(int32_t id) { return id >= 0 && id < kMaterialFamilyCount; }

}  // namespace

std::string material_family_name(int32_t id) {
  return in_table(id) ? kFamilies[static_cast<size_t>(id)].name : "class " + std::to_string(id);
}

std::array<uint8_t, 3> material_family_colour(int32_t id) {
  return in_table(id) ? kFamilies[static_cast<size_t>(id)].colour : std::array<uint8_t, 3>{128, 128, 128};
}

}  // namespace matlearn
