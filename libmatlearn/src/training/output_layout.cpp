#include "matlearn/training/output_layout.h"

#include <stdexcept>

namespace matlearn {

int64_t OutputLayout::regression_channels() const {
  int64_t channels = 0;
  for (const OutputGroup& g : groups) channels += g.channels;
  return channels;
}

int64_t OutputLayout::first_channel(size_t group) const {
  int64_t channel = 0;
  for (size_t g = 0; g < group; ++g) channel += groups[g].channels;
  return channel;
}

OutputLayout OutputLayout::paper() {
  OutputLayout layout;
  layout.groups = {{MapKind::base_color, 3, 1.0}, {MapKind::roughness, 3, 1.0}};
  return layout;
}

bool OutputLayout::predicts(MapKind map) const {
  for (const OutputGroup& g : groups)
    if (g.map == map) return true;
  return false;
}

std::string map_name(MapKind map) {
  switch (map) {
    case MapKind::base_color: return "base_color";
    case MapKind::roughness: return "roughness";
    case MapKind::metallic: return "metallic";
    case MapKind::normal: return "normal";
  }
  throw std::logic_error("unknown map kind");
}

bool is_colour_map(MapKind map) { return map == MapKind::base_color || map == MapKind::normal; }

MapKind map_kind_named(const std::string& name) {
  for (MapKind kind : {MapKind::base_color, MapKind::roughness, MapKind::metallic, MapKind::normal})
    if (map_name(kind) == name) return kind;
  throw std::invalid_argument("unknown map \"" + name + "\" (base_color, roughness, metallic, normal)");
}

void validate(const OutputLayout& layout) {
  for (size_t g = 0; g < layout.groups.size(); ++g) {
    const OutputGroup& group = layout.groups[g];
    const std::string name = map_name(group.map);
    for (size_t h = 0; h < g; ++h)
      if (layout.groups[h].map == group.map) throw std::invalid_argument("output map " + name + " is listed twice");
    if (is_colour_map(group.map) ? group.channels != 3 : group.channels != 1 && group.channels != 3)
      throw std::invalid_argument("output map " + name + " cannot have " + std::to_string(group.channels) +
                                  " channels (base_color and normal 3, roughness and metallic 1 or 3)");
    if (!(group.weight >= 0.0)) throw std::invalid_argument("output map " + name + " has a negative loss weight");
  }
  if (layout.material_classes == 1 || layout.material_classes < 0)
    throw std::invalid_argument("a segmentation head needs at least 2 material classes");
  if (!(layout.material_weight >= 0.0)) throw std::invalid_argument("the material loss weight is negative");
  if (layout.output_channels() == 0) throw std::invalid_argument("the network would predict nothing");
}

std::string describe(const OutputLayout& layout) {
  std::string text;
  for (const OutputGroup& g : layout.groups) {
    if (!text.empty()) text += ",";
    text += map_name(g.map);
    if (!is_colour_map(g.map)) text += ":" + std::to_string(g.channels);
  }
  if (layout.material_classes > 0)
    text += (text.empty() ? "" : " + ") + std::to_string(layout.material_classes) + " classes";
  return text;
}

bool same_channels(const OutputLayout& a, const OutputLayout& b) {
  if (a.groups.size() != b.groups.size() || a.material_classes != b.material_classes) return false;
  for (size_t g = 0; g < a.groups.size(); ++g)
    if (a.groups[g].map != b.groups[g].map || a.groups[g].channels != b.groups[g].channels) return false;
  return true;
}

}  // namespace matlearn
