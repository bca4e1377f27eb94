#pragma once
// Every render setting declared once: its name, the form and range of its values, and one line
// of documentation, as Mitsuba 3 declares a plugin's properties. Everything that reads a render
// setting goes through its declaration: the scene file's "render" block, make_dataset's
// configuration (its own spellings mapped to these names in one table), render_object's options,
// the Python package, and render() itself for settings a program fills in. So a setting has one
// range and one refusal wording everywhere, and the documentation tables are made from it
// (render_setting_table_row) and tested against it.
//
// Adding a setting: a field of RenderSettings (its initialiser is the default), a declaration in
// render_setting_declarations.cpp, the code that uses it, and its test.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "matrender/render_settings.h"

namespace matrender {

// The least ambient-occlusion error that may be asked for: below it the worst case, 0.25 /
// error^2, exceeds 250,000 rays per pixel. Above the most a pixel's estimate says nothing (the
// value itself lies in [0, 1]).
constexpr double kMinAmbientOcclusionError = 0.001;
constexpr double kMaxAmbientOcclusionError = 0.5;

enum class SettingForm {
  WholeNumber,  // in [least, most]
  Number,       // finite, in [least, most] ((least, most] when least_open), or 0 when zero_meaning is set
  Switch,       // true or false
  Choice,       // one of `choices`
};

// Scene settings describe an image and belong in a scene file; run settings say how a machine
// makes it (the thread count) and are given where the run starts.
enum class SettingScope { Scene, Run };

struct RenderSettingDeclaration {
  using Field = std::variant<int RenderSettings::*, uint32_t RenderSettings::*, double RenderSettings::*,
                             bool RenderSettings::*, LightSelection RenderSettings::*, Denoising RenderSettings::*>;

  std::string_view name;  // the scene file's key; options spell it with hyphens (--max-bounces)
  SettingForm form;
  SettingScope scope;
  Field field;
  double least = 0.0;
  double most = 0.0;
  bool least_open = false;
  // Non-empty: 0 is accepted beside [least, most] and means this ("a fixed ray count").
  std::string_view zero_meaning;
  std::vector<std::string_view> choices;  // Choice, in the order of the field's enumerators
  std::string_view documentation;         // one line: what the setting does, nothing about its range
};

// Every declared setting, in the order the documentation lists them.
const std::vector<RenderSettingDeclaration>& render_setting_declarations();
// The declaration named `name`, or nothing.
const RenderSettingDeclaration* find_render_setting(std::string_view name);
// The declaration named `name`; std::logic_error when none is (a name in the code, not input).
const RenderSettingDeclaration& render_setting(std::string_view name);

// What a value must be, as refusals word it: "a whole number from 1 to 16,777,216", "0 (a fixed
// ray count) or a number from 0.001 to 0.5", "true or false", "one of \"importance\", \"uniform\"".
std::string expectation(const RenderSettingDeclaration& setting);

// A setting's value as text: "64", "0.01", "true", "importance".
std::string value_text(const RenderSettings& settings, const RenderSettingDeclaration& setting);
std::string default_text(const RenderSettingDeclaration& setting);

// What is wrong with `value` for a WholeNumber or Number setting ("expected a whole number from
// 1 to 16,777,216, got 0"), or nothing.
std::optional<std::string> number_problem(const RenderSettingDeclaration& setting, double value);

// Setting a value already checked: a number for WholeNumber and Number settings, a switch, or the
// index of a choice.
void assign_number(RenderSettings& settings, const RenderSettingDeclaration& setting, double value);
void assign_switch(RenderSettings& settings, const RenderSettingDeclaration& setting, bool on);
void assign_choice(RenderSettings& settings, const RenderSettingDeclaration& setting, size_t index);

// Sets `setting` from text as a command line gives it ("64", "0.01", "true", "uniform"), or says
// what is wrong with the text in expectation()'s words, leaving `settings` as it was.
std::optional<std::string> assign_text(RenderSettings& settings, const RenderSettingDeclaration& setting,
                                       const std::string& text);

// Two settings that cannot both be on (a switch true, a choice other than its first), and why.
struct SettingConflict {
  std::string_view first;
  std::string_view second;
  std::string_view reason;
};
const std::vector<SettingConflict>& setting_conflicts();
// The first conflict `settings` has, or nothing.
std::optional<SettingConflict> settings_conflict(const RenderSettings& settings);
// "denoise and cycles_parity exclude each other: Blender 3.4 in Debian has no denoiser", the two
// settings spelled as the reader spells them (a key, an option).
std::string conflict_refusal(const SettingConflict& conflict, std::string_view first, std::string_view second);

// The first thing wrong with `settings`: "spp: expected a whole number from 1 to 16,777,216, got
// 0", "denoise and cycles_parity exclude each other: ...", or nothing.
std::optional<std::string> render_settings_problem(const RenderSettings& settings);

// The setting's row of a Markdown table | `name` | default | value |, as docs/scene_format.md
// lists it: the default in the scene file's JSON spelling, then expectation(): documentation.
std::string render_setting_table_row(const RenderSettingDeclaration& setting);
// The table of every scene setting, header and rows (render_object --list-settings prints it).
std::string render_settings_markdown();

}  // namespace matrender
