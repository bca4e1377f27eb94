// make_dataset's `render:` keys read through the renderer's declarations (render_keys.h): every
// key refuses what its declaration refuses, in its words, narrowed only where the table says, and
// sets the declared setting; docs/make_dataset.md's rows are the table's.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/render_keys.h"

namespace fs = std::filesystem;
using matdataset::DatasetRenderKey;
using matrender::RenderSettingDeclaration;
using matrender::SettingForm;

namespace {

const std::string kOneVase = "objects:\n  - {name: vase, builtin: vase, materials: {all: [wood/raw:1]}}\n";

// The configuration with `render.KEY` set to `value` by --set, or its refusal.
std::variant<matdataset::DatasetConfig, std::string> with_key(const DatasetRenderKey& key, const std::string& value) {
  try {
    return matdataset::parse_config(kOneVase, "test.yaml", fs::current_path(),
                                    {{"render." + std::string(key.key), value, "--set"}});
  } catch (const matbase::InputError& e) {
    return std::string(e.what());
  }
}

}  // namespace

TEST_CASE("Every render key reads its declared setting, in range, and refuses outside it in the declaration's words",
          "[dataset]") {
  for (const DatasetRenderKey& key : matdataset::dataset_render_keys()) {
    const RenderSettingDeclaration setting = matdataset::dataset_declaration(key);
    const RenderSettingDeclaration& declared = matrender::render_setting(key.setting);
    INFO(key.key);
    // Narrowed, never widened.
    CHECK(setting.least == declared.least);
    CHECK(setting.most <= declared.most);
    if (setting.form == SettingForm::Switch) {
      const auto config = with_key(key, "true");
      REQUIRE(std::holds_alternative<matdataset::DatasetConfig>(config));
      CHECK(matrender::value_text(std::get<matdataset::DatasetConfig>(config).render.settings, setting) == "true");
      CHECK(std::get<std::string>(with_key(key, "2")) ==
            fmt::format("--set (render.{}): expected true or false, got 2", key.key));
      continue;
    }
    if (setting.form == SettingForm::Choice) {
      // Each choice by its name (a choice named "false" as YAML's false too); anything else refused.
      for (const std::string_view choice : setting.choices) {
        const auto config = with_key(key, std::string(choice));
        if (choice == "learned") {  // this program has no learned denoiser
          CHECK(std::get<std::string>(config).find("\"learned\" needs the learned denoiser") != std::string::npos);
          continue;
        }
        REQUIRE(std::holds_alternative<matdataset::DatasetConfig>(config));
        CHECK(matrender::value_text(std::get<matdataset::DatasetConfig>(config).render.settings, setting) == choice);
      }
      CHECK(std::get<std::string>(with_key(key, "2")) ==
            fmt::format("--set (render.{}): expected {}, got 2", key.key, matrender::expectation(setting)));
      continue;
    }
    REQUIRE((setting.form == SettingForm::WholeNumber || setting.form == SettingForm::Number));
    const std::string most = fmt::format("{}", setting.most);
    const auto config = with_key(key, most);
    REQUIRE(std::holds_alternative<matdataset::DatasetConfig>(config));
    CHECK(matrender::value_text(std::get<matdataset::DatasetConfig>(config).render.settings, setting) == most);
    const std::string above =
        fmt::format("{}", setting.form == SettingForm::WholeNumber ? setting.most + 1 : setting.most * 1.000001);
    CHECK(std::get<std::string>(with_key(key, above)) ==
          fmt::format("--set (render.{}): expected {}, got {}", key.key, matrender::expectation(setting), above));
    // 0 where the declaration gives it a meaning the dataset keeps.
    if (!declared.zero_meaning.empty())
      CHECK(std::holds_alternative<matdataset::DatasetConfig>(with_key(key, "0")) == !key.zero_refused);
  }
}

TEST_CASE("A dataset's render settings default to the renderer's but for ORM's ambient occlusion bound", "[dataset]") {
  const matrender::RenderSettings dataset = matdataset::dataset_render_defaults();
  for (const RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    INFO(setting.name);
    if (setting.name == "ambient_occlusion_error")
      CHECK(matrender::value_text(dataset, setting) == "0.02");
    else
      CHECK(matrender::value_text(dataset, setting) == matrender::default_text(setting));
  }
  CHECK_FALSE(matrender::render_settings_problem(dataset));
}

TEST_CASE("docs/make_dataset.md lists every render key as the table declares it", "[dataset]") {
  std::ifstream file(MATPREDICT_MAKE_DATASET_DOC);
  REQUIRE(file);
  std::stringstream text;
  text << file.rdbuf();
  for (const DatasetRenderKey& key : matdataset::dataset_render_keys()) {
    INFO("docs/make_dataset.md needs the row of render." << key.key << " that make_dataset --list-render-keys prints");
    CHECK(text.str().find(matdataset::dataset_render_key_row(key) + "\n") != std::string::npos);
  }
}
