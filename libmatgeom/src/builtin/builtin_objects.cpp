#include "matgeom/builtin/builtin_objects.h"

#include <stdexcept>
#include <utility>

#include "builtin/objects.h"

namespace matgeom {
namespace {

using Generator = ObjectAsset (*)(uint32_t);

const std::vector<std::pair<std::string, Generator>>& generators() {
  static const std::vector<std::pair<std::string, Generator>> table = {
      {"basket", builtin::make_basket},   {"bed", builtin::make_bed},
      {"book", builtin::make_book},       {"bottle", builtin::make_bottle},
      {"bowl", builtin::make_bowl},       {"cabinet", builtin::make_cabinet},
      {"chair", builtin::make_chair},     {"desk", builtin::make_desk},
      {"lamp", builtin::make_lamp},       {"mug", builtin::make_mug},
      {"picture_frame", builtin::make_picture_frame}, {"pillow", builtin::make_pillow},
      {"plant_pot", builtin::make_plant_pot}, {"shelf", builtin::make_shelf},
      {"sofa", builtin::make_sofa},       {"stool", builtin::make_stool},
      {"table", builtin::make_table},     {"vase", builtin::make_vase},
  };
  return table;
}

}  // namespace

std::vector<std::string> builtin_object_names() {
  std::vector<std::string> names;
  for (const auto& [name, generator] : generators()) names.push_back(name);
  return names;
}

ObjectAsset make_builtin_object(const std::string& name, uint32_t seed) {
  for (const auto& [candidate, generator] : generators())
    if (candidate == name) return generator(seed);
  std::string known;
  for (const std::string& candidate : builtin_object_names()) known += (known.empty() ? "" : ", ") + candidate;
  throw std::invalid_argument("unknown built-in object '" + name + "' (known: " + known + ")");
}

}  // namespace matgeom
