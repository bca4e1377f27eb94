// Every render setting has one range and one refusal wording: the scene file, a command line's
// text (assign_text) and render() itself refuse the same values in the same words, taken from the
// declaration; and the documentation's table rows are the declaration's.
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "matbase/input_error.h"
#include "matrender/render.h"
#include "matrender/render_setting_declarations.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

namespace {

using matrender::RenderSettingDeclaration;
using matrender::SettingForm;

// A scene file whose render block holds `key: value` (JSON text).
std::string scene_with(std::string_view key, const std::string& value) {
  return fmt::format(R"({{"camera": {{"position": [1, -1, 0.5], "look_at": [0, 0, 0.15]}}, "lights": {{"rig": {{}}}},
                         "objects": [{{"builtin": "vase"}}], "render": {{"{}": {}}}}})",
                     key, value);
}

// The message of the InputError reading `json` throws, or "".
std::string scene_refusal(const std::string& json) {
  try {
    matrender::read_scene_text(json, "s.json", ".");
  } catch (const matbase::InputError& e) {
    return e.what();
  }
  return "";
}

// What render() says of `settings` on a tiny scene, or "".
std::string render_refusal(const matrender::RenderSettings& settings) {
  static matrender::BuiltScene built = matrender::build_scene(matrender::read_scene_text(scene_with("spp", "1"), "s.json", "."));
  matrender::Camera camera = built.camera;
  camera.width = camera.height = 2;
  matrender::FrameBuffers frame;
  try {
    matrender::render(built.scene, camera, settings, frame);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Values just outside a number setting's range.
std::vector<std::string> outside(const RenderSettingDeclaration& setting) {
  if (setting.form == SettingForm::WholeNumber)
    return {fmt::format("{}", setting.least - 1.0), fmt::format("{}", setting.most + 1.0)};
  const double step = (setting.most - setting.least) * 1e-6;
  return {fmt::format("{}", setting.least_open ? setting.least : setting.least - step),
          fmt::format("{}", setting.most + step)};
}

}  // namespace

TEST_CASE("every default is accepted by its declaration") {
  CHECK_FALSE(matrender::render_settings_problem(matrender::RenderSettings()));
  for (const RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    INFO(setting.name);
    matrender::RenderSettings settings;
    CHECK_FALSE(matrender::assign_text(settings, setting, matrender::default_text(setting)));
    CHECK(matrender::value_text(settings, setting) == matrender::default_text(setting));
    CHECK(matrender::find_render_setting(setting.name) == &setting);
    CHECK_FALSE(setting.documentation.empty());
  }
  CHECK(matrender::find_render_setting("samples") == nullptr);
  CHECK_THROWS_AS(matrender::render_setting("samples"), std::logic_error);
}

TEST_CASE("the scene file, command-line text and render() refuse a number outside its range alike") {
  for (const RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    if (setting.form != SettingForm::WholeNumber && setting.form != SettingForm::Number) continue;
    for (const std::string& value : outside(setting)) {
      INFO(setting.name << " = " << value);
      const std::string problem = "expected " + matrender::expectation(setting) + ", got " + value;
      matrender::RenderSettings settings;
      const std::optional<std::string> text_problem = matrender::assign_text(settings, setting, value);
      REQUIRE(text_problem);
      CHECK(*text_problem == problem);
      CHECK(matrender::value_text(settings, setting) == matrender::default_text(setting));  // left as it was
      if (setting.scope == matrender::SettingScope::Scene)
        CHECK(scene_refusal(scene_with(setting.name, value)) == fmt::format("s.json: /render/{}: {}", setting.name, problem));
      else
        CHECK(scene_refusal(scene_with(setting.name, value)).find("unknown key") != std::string::npos);
      // A program's settings: where the field can hold the value (not a uint32_t seed of -1).
      matrender::assign_number(settings, setting, std::stod(value));
      if (matrender::value_text(settings, setting) == value)
        CHECK(render_refusal(settings) == fmt::format("render: {}: {}", setting.name, problem));
    }
  }
}

TEST_CASE("range ends are accepted by every reader") {
  for (const RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    if (setting.form != SettingForm::WholeNumber && setting.form != SettingForm::Number) continue;
    const double least = setting.least_open ? std::nextafter(setting.least, 1e300) : setting.least;
    for (double value : {least, setting.most}) {
      const std::string text = fmt::format("{}", value);
      INFO(setting.name << " = " << text);
      matrender::RenderSettings settings;
      CHECK_FALSE(matrender::assign_text(settings, setting, text));
      CHECK(matrender::value_text(settings, setting) == text);
      CHECK_FALSE(matrender::render_settings_problem(settings));
      if (setting.scope == matrender::SettingScope::Scene) {
        const matrender::SceneDescription scene = matrender::read_scene_text(scene_with(setting.name, text), "s.json", ".");
        CHECK(matrender::value_text(scene.settings, setting) == text);
      }
    }
  }
}

TEST_CASE("0 is accepted beside the range where it has a meaning") {
  const RenderSettingDeclaration& error = matrender::render_setting("ambient_occlusion_error");
  REQUIRE_FALSE(error.zero_meaning.empty());
  CHECK(matrender::expectation(error) == "0 (" + std::string(error.zero_meaning) + ") or a number from 0.001 to 0.5");
  matrender::RenderSettings settings;
  settings.ambient_occlusion_error = 0.1;
  CHECK_FALSE(matrender::assign_text(settings, error, "0"));
  CHECK(settings.ambient_occlusion_error == 0.0);
  CHECK(matrender::read_scene_text(scene_with("ambient_occlusion_error", "0"), "s.json", ".").settings.ambient_occlusion_error == 0.0);
}

TEST_CASE("switches and choices are read by their declaration") {
  const RenderSettingDeclaration& mipmaps = matrender::render_setting("mipmaps");
  CHECK(scene_refusal(scene_with("mipmaps", "1")) == "s.json: /render/mipmaps: expected true or false, got 1");
  matrender::RenderSettings settings;
  CHECK(*matrender::assign_text(settings, mipmaps, "yes") == "expected true or false, got yes");
  CHECK(matrender::read_scene_text(scene_with("mipmaps", "false"), "s.json", ".").settings.mipmaps == false);
  const RenderSettingDeclaration& selection = matrender::render_setting("light_selection");
  CHECK(scene_refusal(scene_with("light_selection", "\"even\"")) ==
        R"(s.json: /render/light_selection: expected one of "importance", "uniform", got "even")");
  CHECK(*matrender::assign_text(settings, selection, "even") == R"(expected one of "importance", "uniform", got even)");
  CHECK(matrender::read_scene_text(scene_with("light_selection", "\"uniform\""), "s.json", ".").settings.light_selection ==
        matrender::LightSelection::Uniform);
  // denoise's "false" is JSON's false too; true (which meant the filter before there were two
  // denoisers) is refused with the choices.
  CHECK(matrender::read_scene_text(scene_with("denoise", "false"), "s.json", ".").settings.denoise ==
        matrender::Denoising::Off);
  CHECK(matrender::read_scene_text(scene_with("denoise", "\"filter\""), "s.json", ".").settings.denoise ==
        matrender::Denoising::Filter);
  CHECK(scene_refusal(scene_with("denoise", "true")) ==
        R"(s.json: /render/denoise: expected one of "false", "filter", "learned", got true)");
}

TEST_CASE("settings that exclude each other are refused by the scene file and by render()") {
  const std::string json = fmt::format(
      R"({{"camera": {{"position": [1, -1, 0.5], "look_at": [0, 0, 0.15]}}, "lights": {{"rig": {{}}}},
           "objects": [{{"builtin": "vase"}}], "render": {{"denoise": "filter", "cycles_parity": true}}}})");
  const std::string reason = "denoise and cycles_parity exclude each other: Blender 3.4 in Debian has no denoiser";
  CHECK(scene_refusal(json) == "s.json: /render: " + reason);
  matrender::RenderSettings settings;
  settings.denoise = matrender::Denoising::Filter;
  settings.cycles_parity = true;
  CHECK(render_refusal(settings) == "render: " + reason);
  settings.cycles_parity = false;
  CHECK(render_refusal(settings).empty());
}

TEST_CASE("docs/scene_format.md's render table is the declarations' rows") {
  std::ifstream file(std::string(MATPREDICT_DOCS) + "/scene_format.md");
  REQUIRE(file);
  std::stringstream text;
  text << file.rdbuf();
  const std::string doc = text.str();
  const size_t table = doc.find("## Render\n");
  REQUIRE(table != std::string::npos);
  const std::string section = doc.substr(table, doc.find("\n## ", table + 1) - table);
  size_t rows = 0;
  for (const RenderSettingDeclaration& setting : matrender::render_setting_declarations()) {
    if (setting.scope != matrender::SettingScope::Scene) continue;
    INFO("docs/scene_format.md needs the row of " << setting.name << " that render_object --list-settings prints");
    CHECK(section.find(matrender::render_setting_table_row(setting) + "\n") != std::string::npos);
    ++rows;
  }
  // No row for a key the reader does not take: the declared ones, and the display exposure.
  std::istringstream lines(section);
  size_t key_rows = 0;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("| `", 0) == 0) ++key_rows;
  CHECK(key_rows == rows + 1);
}
