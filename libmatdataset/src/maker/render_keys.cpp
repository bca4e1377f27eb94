#include "matdataset/maker/render_keys.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "matdataset/format/dataset_writer.h"
#include "matrender/render_setting_reading.h"

namespace matdataset {
namespace {

// The key's group and its name in the group ("bounces", "max"), or no group.
std::pair<std::string, std::string> split_key(std::string_view key) {
  const size_t dot = key.find('.');
  if (dot == std::string_view::npos) return {"", std::string(key)};
  return {std::string(key.substr(0, dot)), std::string(key.substr(dot + 1))};
}

// The value of dotted `key` ("bounces.max") under `render`, or nothing.
std::optional<matbase::DocumentNode> find_key(const matbase::DocumentNode& render, std::string_view key) {
  const auto [group, name] = split_key(key);
  if (group.empty()) return render.find(name);
  const std::optional<matbase::DocumentNode> parent = render.find(group);
  return parent ? parent->find(name) : std::nullopt;
}

}  // namespace

const std::vector<DatasetRenderKey>& dataset_render_keys() {
  static const std::vector<DatasetRenderKey> keys = {
      {"samples", "spp", kMaxSampleCount, false, "the sample count map holds 16 bits"},
      {"noise_threshold", "noise_threshold", std::nullopt, false, ""},
      {"min_samples", "min_samples", std::nullopt, false, ""},
      {"target_error", "target_error", std::nullopt, false,
       "over a frame's covered pixels: the object and whatever surroundings stand around it"},
      {"seed", "seed", std::nullopt, false,
       "0: each frame's seed follows from the top-level seed alone; another value is mixed into every frame's seed, "
       "giving the same frames (objects, materials, lighting, every draw) independent noise"},
      {"denoise", "denoise", std::nullopt, false, "the data maps are never filtered"},
      {"bounces.max", "max_bounces", std::nullopt, false, ""},
      {"bounces.diffuse", "max_diffuse_bounces", std::nullopt, false, ""},
      {"bounces.glossy", "max_glossy_bounces", std::nullopt, false, ""},
      {"bounces.transmission", "max_transmission_bounces", std::nullopt, false, ""},
      {"ambient_occlusion.error", "ambient_occlusion_error", std::nullopt, true,
       "ORM's R; not 0: metadata.json states the bound each frame meets"},
      {"ambient_occlusion.distance", "ambient_occlusion_distance", std::nullopt, false, ""},
  };
  return keys;
}

nlohmann::ordered_json render_setting_json(const matrender::RenderSettings& settings,
                                           const matrender::RenderSettingDeclaration& setting) {
  const std::string text = matrender::value_text(settings, setting);
  switch (setting.form) {
    case matrender::SettingForm::Switch: return text == "true";
    case matrender::SettingForm::Choice: return text == "false" ? nlohmann::ordered_json(false) : nlohmann::ordered_json(text);
    case matrender::SettingForm::WholeNumber:
    case matrender::SettingForm::Number: break;
  }
  return std::visit([&settings](auto field) { return nlohmann::ordered_json(settings.*field); }, setting.field);
}

matrender::RenderSettingDeclaration dataset_declaration(const DatasetRenderKey& key) {
  matrender::RenderSettingDeclaration setting = matrender::render_setting(key.setting);
  if (key.most) setting.most = std::min(setting.most, *key.most);
  if (key.zero_refused) setting.zero_meaning = {};
  return setting;
}

matrender::RenderSettings dataset_render_defaults() {
  matrender::RenderSettings settings;
  settings.ambient_occlusion_error = 0.02;
  return settings;
}

std::vector<std::string> dataset_render_top_keys() {
  std::vector<std::string> keys;
  for (const DatasetRenderKey& key : dataset_render_keys()) {
    const auto [group, name] = split_key(key.key);
    const std::string top = group.empty() ? name : group;
    if (std::find(keys.begin(), keys.end(), top) == keys.end()) keys.push_back(top);
  }
  return keys;
}

void read_dataset_render_keys(const matbase::DocumentNode& render, matrender::RenderSettings& settings) {
  std::map<std::string, std::vector<const char*>> group_keys;
  for (const DatasetRenderKey& key : dataset_render_keys()) {
    const auto [group, name] = split_key(key.key);
    if (!group.empty()) group_keys[group].push_back(key.key.data() + group.size() + 1);
  }
  for (const auto& [group, names] : group_keys)
    if (const std::optional<matbase::DocumentNode> node = render.find(group)) node->expect_keys(names);
  for (const DatasetRenderKey& key : dataset_render_keys())
    if (const std::optional<matbase::DocumentNode> node = find_key(render, key.key))
      matrender::read_render_setting(*node, dataset_declaration(key), settings);
}

std::string dataset_render_key_row(const DatasetRenderKey& key) {
  const matrender::RenderSettingDeclaration setting = dataset_declaration(key);
  const std::string value = matrender::value_text(dataset_render_defaults(), setting);
  return fmt::format("| `render.{}` | {} | {}: {}{}{} |", key.key, value, matrender::expectation(setting),
                     setting.documentation, key.note.empty() ? "" : "; ", key.note);
}

std::string dataset_render_keys_markdown() {
  std::string table = "| key | default | meaning |\n|---|---|---|\n";
  for (const DatasetRenderKey& key : dataset_render_keys()) table += dataset_render_key_row(key) + "\n";
  return table;
}

}  // namespace matdataset
