#pragma once
// The procedural material library: 14 material classes in one or more styles each (wood: raw,
// lacquered, painted, wicker; metal: brushed, polished, hammered, perforated; ...), every one a
// seeded family of materials generated from nothing but code. A material comes out as a
// material folder holds it (matmaterial/folder/material_folder.h), so write_material_folder stores it the
// way MatSynth's materials are stored and one reader reads both. Maps are seamless, their values
// inside the class's stated physical ranges, and their bytes the same for a seed whatever the
// thread count (docs/material_library.md).
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "matbase/cancellation.h"
#include "matmaterial/folder/material_folder.h"
#include "matmaterial/material_classes.h"
#include "matmaterial/material_parameters.h"

namespace matmaterial {

// One material of the library.
struct LibraryMaterialSpec {
  MaterialClass material_class = MaterialClass::Wood;
  std::string style;  // one of the class's styles; empty: the seed picks one
  uint32_t seed = 0;
};

// Reads "CLASS[/STYLE][:SEED]": "wood", "wood:3", "wood/wicker", "wood/wicker:3". Throws
// std::invalid_argument naming what is wrong (an unknown class or style, a bad seed).
LibraryMaterialSpec parse_library_material(std::string_view text);

// The canonical spelling of a spec, with the style its seed picks: "wood/wicker:3".
std::string library_material_name(const LibraryMaterialSpec& spec);

struct LibraryStyleInfo {
  MaterialClass material_class;
  const char* name;
  double tile_size_m;       // the length one repeat of the maps covers on a surface
  const char* description;  // what it models, one line
};

// Every style, class by class in the class table's order.
const std::vector<LibraryStyleInfo>& library_styles();

// The style a spec stands for: its own, or the one its seed picks among its class's.
const LibraryStyleInfo& resolved_style(const LibraryMaterialSpec& spec);

// The range a parameter keeps across a class's styles and seeds: linear values, every channel of
// a colour, every texel of a map.
struct ParameterRange {
  MaterialParameter parameter;
  double min, max;
};

// The parameters a class's materials may set, with their ranges; every other parameter keeps the
// material table's default. Empty for Background.
const std::vector<ParameterRange>& material_class_ranges(MaterialClass material_class);

constexpr int kMinLibraryResolution = 8;
constexpr int kMaxLibraryResolution = 8192;

struct LibraryOptions {
  int resolution = 1024;  // texels along each side of every map (datasets use 512 to 4096)
  int threads = 0;        // worker threads (matbase::worker_threads): 0, every hardware thread
  const std::atomic<bool>* cancel = nullptr;  // when set, generation throws matbase::Cancelled
};

// Generates the material, named "<class>_<style>_<seed>" (which material_class_of_folder reads
// back as its class) and labelled with its class. Throws std::invalid_argument for Background, an
// unknown style or a resolution outside [kMinLibraryResolution, kMaxLibraryResolution], and
// matbase::Cancelled (matbase/cancellation.h) within a row of options.cancel being set.
FolderMaterial generate_library_material(const LibraryMaterialSpec& spec, const LibraryOptions& options = {});

// The styles, and the classes' ranges, as the markdown tables of docs/material_library.md (a test
// holds the docs to them).
std::string library_styles_markdown();
std::string library_ranges_markdown();

}  // namespace matmaterial
