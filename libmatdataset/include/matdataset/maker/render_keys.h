#pragma once
// make_dataset's `render:` keys that are render settings, in one table: the configuration's own
// spelling, the declared setting it sets (matrender/render_setting_declarations.h), and where a
// dataset narrows the declaration. Reading, refusals and the rows of docs/make_dataset.md all
// follow from it; the maker sets the other settings per frame (the seed, the threads, the
// transparent background, the AOVs).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "matbase/document/document_node.h"
#include "matrender/render_setting_declarations.h"

namespace matdataset {

struct DatasetRenderKey {
  std::string_view key;      // under `render:`, dotted: "samples", "bounces.max"
  std::string_view setting;  // the declared name: "spp", "max_bounces"
  // Narrower than the declaration, for the dataset's files (why: `note`).
  std::optional<double> most;
  bool zero_refused = false;
  std::string_view note;  // what the dataset adds to the declaration's documentation; may be empty
};

const std::vector<DatasetRenderKey>& dataset_render_keys();

// The declaration as the dataset reads `key`: narrowed where the table says.
matrender::RenderSettingDeclaration dataset_declaration(const DatasetRenderKey& key);

// The settings a dataset renders with before its configuration says otherwise: the renderer's
// defaults, and ORM's R (ambient occlusion) within a standard error of 0.02.
matrender::RenderSettings dataset_render_defaults();

// Reads every key of the table present under `render` into `settings`. The keys of the table's
// groups ("bounces": max, diffuse, ...) are checked here; `render`'s own keys are the caller's,
// who adds dataset_render_top_keys() to the others it allows.
void read_dataset_render_keys(const matbase::DocumentNode& render, matrender::RenderSettings& settings);
std::vector<std::string> dataset_render_top_keys();

// A setting's value as a scene file's render block and metadata.json spell it: a number, true or
// false, or a choice's name (JSON's false for a choice named "false", denoise's).
nlohmann::ordered_json render_setting_json(const matrender::RenderSettings& settings,
                                           const matrender::RenderSettingDeclaration& setting);

// The key's row of docs/make_dataset.md's table: | `render.KEY` | default | value |.
std::string dataset_render_key_row(const DatasetRenderKey& key);
// Every key's row under the table's header (make_dataset --list-render-keys prints it).
std::string dataset_render_keys_markdown();

}  // namespace matdataset
