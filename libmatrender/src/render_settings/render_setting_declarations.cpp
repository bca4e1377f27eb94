#include "matrender/render_setting_declarations.h"

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "matbase/document/document_node.h"
#include "matbase/number_text.h"
#include "matbase/threads.h"
#include "matrender/scene_limits.h"

namespace matrender {
namespace {

// Cycles 3.4's own limits (its properties.py): at most 2^24 samples and 1024 bounces, a filter
// width from 0.01 to 10 px.
constexpr double kMaxSamplesPerPixel = 16777216.0;
constexpr double kMaxBounceLimit = 1024.0;
constexpr double kMinFilterWidth = 0.01, kMaxFilterWidth = 10.0;
// At this many rays per hit ambient occlusion's stratified estimate is within 0.016 at one sample.
constexpr double kMaxAmbientOcclusionRays = 1024.0;

using S = RenderSettings;

RenderSettingDeclaration whole_number(std::string_view name, int S::*field, double least, double most,
                                      std::string_view documentation, SettingScope scope = SettingScope::Scene) {
  return {name, SettingForm::WholeNumber, scope, field, least, most, false, {}, {}, documentation};
}

RenderSettingDeclaration seed(std::string_view name, uint32_t S::*field, std::string_view documentation) {
  return {name, SettingForm::WholeNumber, SettingScope::Scene, field, 0.0, 4294967295.0, false, {}, {}, documentation};
}

RenderSettingDeclaration number(std::string_view name, double S::*field, double least, double most, bool least_open,
                                std::string_view zero_meaning, std::string_view documentation) {
  return {name, SettingForm::Number, SettingScope::Scene, field, least, most, least_open, zero_meaning, {}, documentation};
}

RenderSettingDeclaration on_off(std::string_view name, bool S::*field, std::string_view documentation) {
  return {name, SettingForm::Switch, SettingScope::Scene, field, 0.0, 0.0, false, {}, {}, documentation};
}

std::vector<RenderSettingDeclaration> declare_settings() {
  return {
      whole_number("spp", &S::samples_per_pixel, 1, kMaxSamplesPerPixel,
                   "samples per pixel; with a noise threshold, the most a pixel takes"),
      number("filter_width", &S::filter_width, kMinFilterWidth, kMaxFilterWidth, false, {},
             "the pixel filter's width in pixels (Blender's Film > Pixel Filter > Width): each camera sample leaves "
             "through a point drawn from a Blackman-Harris window spanning this many pixels either side of the "
             "pixel's centre"),
      number("noise_threshold", &S::noise_threshold, 0.0, 1.0, false, {},
             "adaptive sampling as Cycles' Noise Threshold: a pixel stops once its relative error estimate is "
             "below it and its neighbours' are too (Blender's default is 0.01); 0 = off, every pixel takes every sample. "
             "docs/conventions.md, \"Adaptive sampling\", gives the rule"),
      whole_number("min_samples", &S::min_samples, 0, kMaxSamplesPerPixel,
                   "with a noise threshold: samples before a pixel is first checked; 0 = Cycles' automatic "
                   "max(4, ceil(16 / threshold^0.3)). With a target error: the samples every pixel takes first; "
                   "0 = 16"),
      number("target_error", &S::target_error, 0.0, 1.0, false, {},
             "render to an error, not to a sample count: the relative RMSE over the pixels a surface covers "
             "(the RMSE of their colour over its mean) the frame may have; each pixel's error is estimated from its two "
             "half estimates and its neighbours', and pixels sample in rounds until the frame's predicted error is "
             "at or below it, `spp` the most a pixel takes; with `denoise`, the denoised frame's error; 0 = off. "
             "docs/conventions.md, \"Rendering to an error\", gives the rule"),
      {"denoise", SettingForm::Choice, SettingScope::Scene, &S::denoise, 0.0, 0.0, false, {},
       {"false", "filter", "learned"},
       "denoise the colour after rendering: `false`, not at all; `filter`, the a-trous filter guided by the base "
       "colour, normal, depth, label and the colour's variance; `learned`, the network trained on our own renders, "
       "guided by the base colour and normal, in programs built with libmatlearn (docs/conventions.md, "
       "\"Denoising\")"},
      seed("seed", &S::seed, "sampler seed. The image depends only on the seed, not on the thread count"),
      whole_number("max_bounces", &S::max_bounces, 0, kMaxBounceLimit, "bounces of every kind together"),
      whole_number("max_diffuse_bounces", &S::max_diffuse_bounces, 0, kMaxBounceLimit, "diffuse bounces"),
      whole_number("max_glossy_bounces", &S::max_glossy_bounces, 0, kMaxBounceLimit, "glossy bounces"),
      whole_number("max_transmission_bounces", &S::max_transmission_bounces, 0, kMaxBounceLimit,
                   "refractions through glass"),
      whole_number("max_transparent_bounces", &S::max_transparent_bounces, 0, kMaxBounceLimit,
                   "surfaces of alpha below 1 a camera, path or shadow ray passes through (they are no bounces)"),
      on_off("transparent_background", &S::transparent_background,
             "camera rays that miss give 0 instead of the background. The background still lights the scene"),
      on_off("cycles_parity", &S::cycles_parity,
             "reproduce Cycles 3.4's own estimators where they do not converge to the integral of its BSDF: the "
             "clearcoat's sampling and the multiscatter GGX walk (docs/conventions.md, \"Principled BSDF\"), and "
             "pick lights uniformly as Cycles does (a biased estimator's image depends on that choice). For parity "
             "with images made in Blender"),
      {"light_selection", SettingForm::Choice, SettingScope::Scene, &S::light_selection, 0.0, 0.0, false, {},
       {"importance", "uniform"},
       "how each shading point picks the one light it samples: `importance`, in proportion to a bound on the "
       "irradiance each light can give it (0 behind a lamp, outside a spot's cone, below the surface), or "
       "`uniform`, each light equally, as Cycles 3.4. Only the noise differs"},
      on_off("mipmaps", &S::mipmaps,
             "filter textures over each camera ray's footprint (a ray cone, continued through mirrors, glass and "
             "transparent surfaces) from their mip levels, so that a large texture seen from afar does not alias; "
             "off: bilinear at the hit point only, as Cycles 3.4 on the CPU (and always with `cycles_parity`)"),
      number("ambient_occlusion_distance", &S::ambient_occlusion_distance, 0.0, kMaxSceneCoordinate, true, {},
             "metres within which a surface occludes, for the ambient occlusion AOV (Cycles' AO node: 1 m)"),
      number("ambient_occlusion_error", &S::ambient_occlusion_error, kMinAmbientOcclusionError,
             kMaxAmbientOcclusionError, false, "a fixed ray count: `ambient_occlusion_rays` per hit",
             "the standard error the ambient occlusion AOV may have at most: each pixel traces as many rays as its "
             "own trials show it needs"),
      whole_number("ambient_occlusion_rays", &S::ambient_occlusion_rays, 1, kMaxAmbientOcclusionRays,
                   "with `ambient_occlusion_error` 0: the occlusion rays each camera sample that hits traces (a "
                   "pixel's standard error is then at most 0.5 / sqrt(hits x rays))"),
      whole_number("threads", &S::threads, 0, matbase::kMaxThreadRequest,
                   "render threads, 0 = all hardware threads, more are capped to them (the image does not depend "
                   "on it)",
                   SettingScope::Run),
  };
}

double number_value(const RenderSettings& settings, const RenderSettingDeclaration& setting) {
  return std::visit(
      [&](auto field) -> double {
        using Value = std::remove_cv_t<std::remove_reference_t<decltype(settings.*field)>>;
        if constexpr (std::is_enum_v<Value>) return static_cast<double>(static_cast<int>(settings.*field));
        else return static_cast<double>(settings.*field);
      },
      setting.field);
}

bool accepted(const RenderSettingDeclaration& setting, double value) {
  if (setting.form == SettingForm::Switch) return value == 0.0 || value == 1.0;
  if (setting.form == SettingForm::Choice) return value >= 0.0 && value < setting.choices.size() && std::trunc(value) == value;
  if (!std::isfinite(value)) return false;
  if (!setting.zero_meaning.empty() && value == 0.0) return true;
  if (setting.form == SettingForm::WholeNumber && std::trunc(value) != value) return false;
  return (setting.least_open ? value > setting.least : value >= setting.least) && value <= setting.most;
}

std::string number_text(double value) { return fmt::format("{}", value); }

}  // namespace

const std::vector<RenderSettingDeclaration>& render_setting_declarations() {
  static const std::vector<RenderSettingDeclaration> declarations = declare_settings();
  return declarations;
}

const RenderSettingDeclaration* find_render_setting(std::string_view name) {
  for (const RenderSettingDeclaration& setting : render_setting_declarations())
    if (setting.name == name) return &setting;
  return nullptr;
}

const RenderSettingDeclaration& render_setting(std::string_view name) {
  if (const RenderSettingDeclaration* setting = find_render_setting(name)) return *setting;
  throw std::logic_error("no render setting is named \"" + std::string(name) + "\"");
}

std::string expectation(const RenderSettingDeclaration& setting) {
  switch (setting.form) {
    case SettingForm::WholeNumber:
      return matbase::whole_number_expectation(static_cast<int64_t>(setting.least), static_cast<int64_t>(setting.most));
    case SettingForm::Number: {
      const std::string range = matbase::number_expectation(setting.least, setting.most, setting.least_open);
      return setting.zero_meaning.empty() ? range : fmt::format("0 ({}) or {}", setting.zero_meaning, range);
    }
    case SettingForm::Switch: return "true or false";
    case SettingForm::Choice: {
      std::vector<std::string> names(setting.choices.begin(), setting.choices.end());
      return "one of " + matbase::quoted_list(names);
    }
  }
  return "";
}

std::string value_text(const RenderSettings& settings, const RenderSettingDeclaration& setting) {
  const double value = number_value(settings, setting);
  switch (setting.form) {
    case SettingForm::Switch: return value != 0.0 ? "true" : "false";
    case SettingForm::Choice: return std::string(setting.choices.at(static_cast<size_t>(value)));
    case SettingForm::WholeNumber:
    case SettingForm::Number: return number_text(value);
  }
  return "";
}

std::string default_text(const RenderSettingDeclaration& setting) { return value_text(RenderSettings(), setting); }

std::optional<std::string> number_problem(const RenderSettingDeclaration& setting, double value) {
  if (accepted(setting, value)) return std::nullopt;
  return "expected " + expectation(setting) + ", got " + number_text(value);
}

void assign_number(RenderSettings& settings, const RenderSettingDeclaration& setting, double value) {
  std::visit(
      [&](auto field) {
        using Value = std::remove_reference_t<decltype(settings.*field)>;
        if constexpr (std::is_enum_v<Value>) settings.*field = static_cast<Value>(static_cast<int>(value));
        else settings.*field = static_cast<Value>(value);
      },
      setting.field);
}

void assign_switch(RenderSettings& settings, const RenderSettingDeclaration& setting, bool on) {
  settings.*std::get<bool S::*>(setting.field) = on;
}

void assign_choice(RenderSettings& settings, const RenderSettingDeclaration& setting, size_t index) {
  assign_number(settings, setting, static_cast<double>(index));
}

std::optional<std::string> assign_text(RenderSettings& settings, const RenderSettingDeclaration& setting,
                                       const std::string& text) {
  const std::string refusal = "expected " + expectation(setting) + ", got " + matbase::shown_value(text);
  switch (setting.form) {
    case SettingForm::WholeNumber: {
      const std::optional<int64_t> value = matbase::whole_number(text);
      if (!value || !accepted(setting, static_cast<double>(*value))) return refusal;
      assign_number(settings, setting, static_cast<double>(*value));
      return std::nullopt;
    }
    case SettingForm::Number: {
      const std::optional<double> value = matbase::finite_number(text);
      if (!value || !accepted(setting, *value)) return refusal;
      assign_number(settings, setting, *value);
      return std::nullopt;
    }
    case SettingForm::Switch:
      if (text != "true" && text != "false") return refusal;
      assign_switch(settings, setting, text == "true");
      return std::nullopt;
    case SettingForm::Choice:
      for (size_t i = 0; i < setting.choices.size(); ++i)
        if (text == setting.choices[i]) {
          assign_choice(settings, setting, i);
          return std::nullopt;
        }
      return refusal;
  }
  return refusal;
}

const std::vector<SettingConflict>& setting_conflicts() {
  static const std::vector<SettingConflict> conflicts = {
      {"denoise", "cycles_parity", "Blender 3.4 in Debian has no denoiser"},
      {"target_error", "noise_threshold", "both decide where sampling stops; give one"},
      {"target_error", "cycles_parity", "Cycles 3.4 has no such rule; its noise threshold is `noise_threshold`"},
  };
  return conflicts;
}

std::optional<SettingConflict> settings_conflict(const RenderSettings& settings) {
  auto on = [&settings](std::string_view name) { return number_value(settings, render_setting(name)) != 0.0; };
  for (const SettingConflict& conflict : setting_conflicts())
    if (on(conflict.first) && on(conflict.second)) return conflict;
  return std::nullopt;
}

std::string conflict_refusal(const SettingConflict& conflict, std::string_view first, std::string_view second) {
  return fmt::format("{} and {} exclude each other: {}", first, second, conflict.reason);
}

std::optional<std::string> render_settings_problem(const RenderSettings& settings) {
  for (const RenderSettingDeclaration& setting : render_setting_declarations())
    if (!accepted(setting, number_value(settings, setting)))
      return std::string(setting.name) + ": expected " + expectation(setting) + ", got " +
             number_text(number_value(settings, setting));
  if (const std::optional<SettingConflict> conflict = settings_conflict(settings))
    return conflict_refusal(*conflict, conflict->first, conflict->second);
  return std::nullopt;
}

std::string render_setting_table_row(const RenderSettingDeclaration& setting) {
  // A choice is a JSON string, but for the choices spelled as JSON's booleans (denoise's false).
  const std::string text = default_text(setting);
  const bool bare = setting.form != SettingForm::Choice || text == "false" || text == "true";
  const std::string shown_default = bare ? text : "\"" + text + "\"";
  std::string exclusions;
  for (const SettingConflict& conflict : setting_conflicts()) {
    if (conflict.first == setting.name) exclusions += fmt::format("; not with `{}`", conflict.second);
    if (conflict.second == setting.name) exclusions += fmt::format("; not with `{}`", conflict.first);
  }
  return fmt::format("| `{}` | `{}` | {}: {}{} |", setting.name, shown_default, expectation(setting),
                     setting.documentation, exclusions);
}

std::string render_settings_markdown() {
  std::string table = "| key | default | value |\n|---|---|---|\n";
  for (const RenderSettingDeclaration& setting : render_setting_declarations())
    if (setting.scope == SettingScope::Scene) table += render_setting_table_row(setting) + "\n";
  return table;
}

}  // namespace matrender
