#include "matmaterial/library/material_library.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "matmaterial/library/periodic_noise.h"
#include "library/recipe_raster.h"
#include "library/styles.h"
#include "matbase/text.h"
#include "matbase/uniform_source.h"

namespace matmaterial {
namespace {

using MC = MaterialClass;
using P = MaterialParameter;

struct Style {
  LibraryStyleInfo info;
  library::Recipe (*make)(matbase::UniformSource& random);
};

// The styles, declared once: the CLI's lists, the docs table and the generator follow from it.
const std::vector<Style>& style_table() {
  using namespace library;
  static const std::vector<Style> table = {
      {{MC::Concrete, "cast", 1.0, "grey cement, speckled, blotched, pitted with air pores"}, cast_concrete},
      {{MC::Concrete, "aggregate", 1.0, "exposed aggregate: pebbles standing out of the cement"}, aggregate_concrete},
      {{MC::Fabric, "plain_weave", 0.05, "cotton-like plain weave, Principled sheen"}, plain_weave_fabric},
      {{MC::Fabric, "twill", 0.05, "2/2 twill (denim's diagonal), Principled sheen"}, twill_fabric},
      {{MC::Fabric, "velvet", 0.2, "pile fabric: a Velvet lobe (glTF sheen) over a dark base"}, velvet_fabric},
      {{MC::Leather, "pebbled", 0.15, "pebbled grain: raised pebbles between creases"}, pebbled_leather},
      {{MC::Leather, "smooth", 0.15, "smooth aniline leather, satin, mottled"}, smooth_leather},
      {{MC::Metal, "brushed", 0.2, "brushed along u: streaked roughness"}, brushed_metal},
      {{MC::Metal, "polished", 0.2, "polished mirror-like metal with faint smudges"}, polished_metal},
      {{MC::Metal, "hammered", 0.3, "hand-hammered dimples"}, hammered_metal},
      {{MC::Metal, "perforated", 0.2, "sheet metal punched with round holes (opacity)"}, perforated_metal},
      {{MC::Plastic, "glossy", 0.2, "moulded glossy plastic: every parameter constant, no maps"}, glossy_plastic},
      {{MC::Plastic, "matte", 0.2, "matte plastic, fine roughness variation"}, matte_plastic},
      {{MC::Plastic, "textured", 0.1, "stippled moulded texture"}, textured_plastic},
      {{MC::Stone, "granite", 0.5, "polished granite: feldspar, quartz and mica grains"}, granite},
      {{MC::Stone, "slate", 0.5, "dark slate with cleavage ridges"}, slate},
      {{MC::Stone, "sandstone", 0.5, "fine-grained sandstone with bedding bands"}, sandstone},
      {{MC::Wood, "raw", 0.6, "planed timber: growth rings and pores, unfinished"}, raw_wood},
      {{MC::Wood, "lacquered", 0.6, "timber under a lacquer (clearcoat)"}, lacquered_wood},
      {{MC::Wood, "painted", 0.6, "painted timber, the grain showing through"}, painted_wood},
      {{MC::Wood, "wicker", 0.25, "basket-woven cane strands"}, wicker},
      {{MC::Marble, "carrara", 0.8, "white marble with grey veins, polished"}, carrara_marble},
      {{MC::Marble, "nero", 0.8, "black marble with white veins, polished"}, nero_marble},
      {{MC::Ceramic, "glazed", 0.2, "coloured glaze, mottled, orange peel, clearcoat"}, glazed_ceramic},
      {{MC::Ceramic, "speckled", 0.2, "speckled stoneware under a clear glaze (clearcoat)"}, speckled_ceramic},
      {{MC::Terracotta, "unglazed", 0.3, "fired clay, mottled and porous"}, terracotta},
      {{MC::Plaster, "trowelled", 1.0, "painted plaster with trowel sweeps"}, trowelled_plaster},
      {{MC::Rubber, "matte", 0.1, "dark rubber with a fine texture"}, matte_rubber},
      {{MC::Rubber, "ribbed", 0.1, "rubber matting with ribs along u"}, ribbed_rubber},
      {{MC::Paper, "sheet", 0.2, "paper: white to cream, fibres"}, paper_sheet},
      {{MC::Paper, "cardboard", 0.12, "kraft corrugated cardboard, the flutes showing"}, corrugated_cardboard},
      {{MC::Paper, "perforated", 0.1, "paper punched with round holes (opacity)"}, perforated_paper},
      {{MC::Glass, "clear", 0.2, "clear glass: transmission 1, IOR 1.47-1.52"}, clear_glass},
      {{MC::Glass, "tinted", 0.2, "green, amber, blue or grey glass"}, tinted_glass},
      {{MC::Glass, "frosted", 0.2, "acid-etched glass: rough refraction"}, frosted_glass},
  };
  return table;
}

// The ranges the styles are written to keep (their palettes and noise amplitudes); the tests hold
// generated maps to them. Dielectric reflectances stay within 0.03-0.9 (charcoal to fresh snow),
// metals' are measured (matmaterial/metal_reflectances.h), glass's base colour is its tint.
const std::vector<ParameterRange>& ranges_of(MaterialClass material_class) {
  static const std::vector<ParameterRange> none;
  static const std::vector<std::vector<ParameterRange>> table = {
      /* background */ {},
      /* concrete */ {{P::BaseColor, 0.05, 0.6}, {P::Roughness, 0.6, 0.95}},
      /* fabric */
      {{P::BaseColor, 0.03, 0.8},
       {P::Roughness, 0.85, 0.95},
       {P::Sheen, 0.0, 1.0},
       {P::SheenTint, 0.5, 0.5},
       {P::VelvetColor, 0.0, 1.0},
       {P::VelvetSigma, 0.3, 1.0}},
      /* leather */ {{P::BaseColor, 0.03, 0.5}, {P::Roughness, 0.3, 0.7}},
      /* metal */ {{P::BaseColor, 0.3, 1.0}, {P::Roughness, 0.04, 0.5}, {P::Metallic, 1.0, 1.0}, {P::Alpha, 0.0, 1.0}},
      /* plastic */ {{P::BaseColor, 0.03, 0.9}, {P::Roughness, 0.05, 0.7}},
      /* stone */ {{P::BaseColor, 0.03, 0.75}, {P::Roughness, 0.2, 0.95}},
      /* wood */
      {{P::BaseColor, 0.03, 0.85}, {P::Roughness, 0.35, 0.85}, {P::Clearcoat, 0.0, 1.0},
       {P::ClearcoatRoughness, 0.02, 0.08}},
      /* marble */ {{P::BaseColor, 0.03, 0.9}, {P::Roughness, 0.05, 0.15}},
      /* ceramic */
      {{P::BaseColor, 0.03, 0.9}, {P::Roughness, 0.1, 0.35}, {P::Clearcoat, 0.8, 1.0},
       {P::ClearcoatRoughness, 0.02, 0.08}},
      /* terracotta */ {{P::BaseColor, 0.03, 0.7}, {P::Roughness, 0.85, 0.95}},
      /* plaster */ {{P::BaseColor, 0.5, 0.85}, {P::Roughness, 0.8, 0.9}},
      /* rubber */ {{P::BaseColor, 0.03, 0.1}, {P::Roughness, 0.75, 0.95}},
      /* paper */ {{P::BaseColor, 0.05, 0.9}, {P::Roughness, 0.85, 0.95}, {P::Alpha, 0.0, 1.0}},
      /* glass */
      {{P::BaseColor, 0.45, 1.0}, {P::Roughness, 0.0, 0.43}, {P::Transmission, 1.0, 1.0}, {P::Ior, 1.47, 1.52}},
  };
  const auto index = static_cast<size_t>(material_class);
  return index < table.size() ? table[index] : none;
}

std::vector<const Style*> styles_of(MaterialClass material_class) {
  std::vector<const Style*> styles;
  for (const Style& style : style_table())
    if (style.info.material_class == material_class) styles.push_back(&style);
  return styles;
}

// The random numbers a spec's material draws: the style choice first, then the style's own.
matbase::UniformSource source_for(const LibraryMaterialSpec& spec) {
  return matbase::UniformSource(library::hash32(spec.seed ^ library::hash32(static_cast<uint32_t>(spec.material_class) + 1u)));
}

const Style& style_for(const LibraryMaterialSpec& spec, matbase::UniformSource& random) {
  const std::vector<const Style*> styles = styles_of(spec.material_class);
  if (styles.empty())
    throw std::invalid_argument(std::string("the material library has no ") +
                                material_class(spec.material_class).name + " materials");
  const Style* picked = styles[random.choice(static_cast<uint32_t>(styles.size()))];
  if (spec.style.empty()) return *picked;
  for (const Style* style : styles)
    if (spec.style == style->info.name) return *style;
  std::string known;
  for (const Style* style : styles) known += std::string(known.empty() ? "" : ", ") + style->info.name;
  throw std::invalid_argument(std::string("no style \"") + spec.style + "\" of " +
                              material_class(spec.material_class).name + " (styles: " + known + ")");
}

std::string format_range(double min, double max) {
  std::ostringstream out;
  out << min;
  if (max != min) out << "-" << max;
  return out.str();
}

}  // namespace

LibraryMaterialSpec parse_library_material(std::string_view text) {
  LibraryMaterialSpec spec;
  std::string_view name = text;
  if (const size_t colon = text.find(':'); colon != std::string_view::npos) {
    name = text.substr(0, colon);
    const std::string_view seed = text.substr(colon + 1);
    const auto [end, error] = std::from_chars(seed.data(), seed.data() + seed.size(), spec.seed);
    if (seed.empty() || error != std::errc() || end != seed.data() + seed.size())
      throw std::invalid_argument("material \"" + std::string(text) + "\": the seed after ':' must be a whole number from 0 to 4294967295");
  }
  std::string_view class_name = name;
  if (const size_t slash = name.find('/'); slash != std::string_view::npos) {
    class_name = name.substr(0, slash);
    spec.style = std::string(name.substr(slash + 1));
  }
  const std::optional<MaterialClass> material_class = material_class_named(matbase::lowercase(std::string(class_name)));
  if (!material_class || *material_class == MaterialClass::Background)
    throw std::invalid_argument("material \"" + std::string(text) + "\": no material class \"" +
                                std::string(class_name) + "\" (render_object --list-materials lists them)");
  spec.material_class = *material_class;
  matbase::UniformSource random = source_for(spec);
  style_for(spec, random);  // throws for a style the class does not have
  return spec;
}

std::string library_material_name(const LibraryMaterialSpec& spec) {
  return std::string(material_class(spec.material_class).name) + "/" + resolved_style(spec).name + ":" +
         std::to_string(spec.seed);
}

const std::vector<LibraryStyleInfo>& library_styles() {
  static const std::vector<LibraryStyleInfo> styles = [] {
    std::vector<LibraryStyleInfo> infos;
    for (const Style& style : style_table()) infos.push_back(style.info);
    return infos;
  }();
  return styles;
}

const LibraryStyleInfo& resolved_style(const LibraryMaterialSpec& spec) {
  matbase::UniformSource random = source_for(spec);
  return style_for(spec, random).info;
}

const std::vector<ParameterRange>& material_class_ranges(MaterialClass material_class) {
  return ranges_of(material_class);
}

FolderMaterial generate_library_material(const LibraryMaterialSpec& spec, const LibraryOptions& options) {
  if (options.resolution < kMinLibraryResolution || options.resolution > kMaxLibraryResolution)
    throw std::invalid_argument("material resolution " + std::to_string(options.resolution) + ": expected " +
                                std::to_string(kMinLibraryResolution) + " to " +
                                std::to_string(kMaxLibraryResolution) + " texels");
  matbase::UniformSource random = source_for(spec);
  const Style& style = style_for(spec, random);
  const std::string name =
      std::string(material_class(spec.material_class).name) + "_" + style.info.name + "_" + std::to_string(spec.seed);
  return library::rasterise_recipe(style.make(random), name, spec.material_class, style.info.tile_size_m,
                                   options.resolution, options.threads, options.cancel);
}

std::string library_styles_markdown() {
  std::ostringstream out;
  out << "| class | id | style | tile (m) | what it models |\n|---|---|---|---|---|\n";
  for (const Style& style : style_table())
    out << "| " << material_class(style.info.material_class).name << " | " << label_id(style.info.material_class)
        << " | " << style.info.name << " | " << style.info.tile_size_m << " | " << style.info.description << " |\n";
  return out.str();
}

std::string library_ranges_markdown() {
  std::ostringstream out;
  out << "| class | base colour (linear) | roughness | metallic | other parameters |\n|---|---|---|---|---|\n";
  for (const MaterialClassInfo& info : kMaterialClasses) {
    if (info.id == MaterialClass::Background) continue;
    std::string base = "-", roughness = "-", metallic = "0", other;
    for (const ParameterRange& range : ranges_of(info.id)) {
      const std::string text = format_range(range.min, range.max);
      if (range.parameter == P::BaseColor) base = text;
      else if (range.parameter == P::Roughness) roughness = text;
      else if (range.parameter == P::Metallic) metallic = text;
      else other += std::string(other.empty() ? "" : ", ") + material_parameter(range.parameter).name + " " + text;
    }
    out << "| " << info.name << " | " << base << " | " << roughness << " | " << metallic << " | "
        << (other.empty() ? "-" : other) << " |\n";
  }
  return out.str();
}

}  // namespace matmaterial
