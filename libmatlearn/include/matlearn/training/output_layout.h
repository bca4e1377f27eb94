#pragma once
// Which maps a regressor predicts, in which channels, and how much each weighs in the loss (the
// paper's extensibility section: T = [B | R | M | N], L = sum_c w_c ||T_hat_c - T_c||^2). The
// paper's default is base colour (3) + roughness (3, the grey map repeated, as it stacks RGB
// maps) = 6 channels. The normal (3) is the dataset's normal_obj map as stored, 0.5 n + 0.5, so
// that it shares the sigmoid output and the loss of the other maps. The segmentation head of the repository's second task adds one channel per
// material class after the maps.
#include <cstdint>
#include <string>
#include <vector>

namespace matlearn {

enum class MapKind { base_color, roughness, metallic, normal };

struct OutputGroup {
  MapKind map;
  int64_t channels;  // 3 for base colour and normal; 1 or 3 for roughness and metallic
  double weight = 1.0;
};

struct OutputLayout {
  std::vector<OutputGroup> groups;
  int64_t material_classes = 0;  // 0: no segmentation head
  double material_weight = 1.0;

  int64_t regression_channels() const;
  int64_t output_channels() const { return regression_channels() + material_classes; }
  // Channel index of the group's first channel.
  int64_t first_channel(size_t group) const;
  // Base colour 3 + roughness 3, both weight 1.
  static OutputLayout paper();
  bool predicts(MapKind map) const;
};

std::string map_name(MapKind map);  // "base_color", "roughness", "metallic", "normal"
// Base colour and normal always have 3 channels; roughness and metallic 1, or 3 repeated.
bool is_colour_map(MapKind map);
// The kind of a map_name; throws std::invalid_argument naming it when there is none.
MapKind map_kind_named(const std::string& name);
// Throws std::invalid_argument naming the bad entry: a map twice, base colour or normal not 3
// channels, roughness or metallic not 1 or 3, a negative weight, 1 material class, no output at all.
void validate(const OutputLayout& layout);
// The layout in train_regressor's --outputs syntax, classes after: "base_color,roughness:3 + 8 classes".
std::string describe(const OutputLayout& layout);
// Whether a network trained for one layout predicts the same thing in every channel of the other:
// the same maps in the same order with the same channel counts, and the same classes. Loss weights
// may differ (fine-tuning with other weights is a use, not a mistake).
bool same_channels(const OutputLayout& a, const OutputLayout& b);

}  // namespace matlearn
