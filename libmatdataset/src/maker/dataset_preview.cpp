#include "matdataset/maker/dataset_preview.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "matbase/file/atomic_file.h"
#include "matbase/image/image_writing.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/format/decoded_image.h"
#include "matdataset/maker/lighting_panorama.h"
#include "matmaterial/material_classes.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

constexpr float kBackground = 0.16f;  // grey where the object is not
constexpr float kGap = 0.06f;         // between cells
constexpr int kGapPixels = 2;
constexpr int64_t kMaxSide = 65536;  // a frame side transforms.json may state (16 bits' worth)

using Map = matbase::FloatImage;

using Rgb = std::array<float, 3>;

// One column of the sheet: what it shows of a frame at a pixel, given the frame's maps.
struct Column {
  const char* name;
  const char* folder;
  const char* extension;
};
constexpr std::array<Column, 12> kColumns = {{{"image", "images", ".png"},
                                             {"albedo", "albedo", ".png"},
                                             {"roughness", "ORM", ".png"},
                                             {"metallic", "ORM", ".png"},
                                             {"occlusion", "ORM", ".png"},
                                             {"normal (world)", "normal_obj", ".png"},
                                             {"normal (map)", "normal_mat", ".png"},
                                             {"depth", "depth", ".exr"},
                                             {"label", "label", ".png"},
                                             {"region", "region", ".png"},
                                             {"samples", "sample_count", ".png"},
                                             {"lighting", "", ""}}};
// The last column is drawn from transforms.json's record of the frame's lighting, not a map.
constexpr size_t kLightingColumn = kColumns.size() - 1;

// A heat map of t in [0, 1], dark purple (few) through red to pale yellow (many): five
// display-encoded stops of matplotlib's "inferno", linearly interpolated.
Rgb heat(float t) {
  constexpr std::array<Rgb, 5> kStops = {{{0.001f, 0.000f, 0.014f},
                                          {0.258f, 0.039f, 0.406f},
                                          {0.735f, 0.216f, 0.330f},
                                          {0.988f, 0.645f, 0.040f},
                                          {0.988f, 1.000f, 0.645f}}};
  const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(kStops.size() - 1);
  const size_t k = std::min(kStops.size() - 2, static_cast<size_t>(x));
  const float f = x - static_cast<float>(k);
  Rgb rgb;
  for (size_t c = 0; c < 3; ++c) rgb[c] = kStops[k][c] + f * (kStops[k + 1][c] - kStops[k][c]);
  return rgb;
}

// A map of a frame, or nothing when it cannot be decoded or is not the frame's size; then its
// file and why go to `damaged`.
std::optional<Map> read_map(const fs::path& file, int width, int height, std::vector<std::string>& damaged) {
  try {
    Map map = decode(file);
    if (map.width == width && map.height == height) return map;
    damaged.push_back(fmt::format("{}: {} x {}, not the frame's {} x {}", file.string(), map.width, map.height, width,
                                  height));
  } catch (const std::exception& e) {
    std::string reason = e.what();
    std::replace(reason.begin(), reason.end(), '\n', ';');
    damaged.push_back(reason.rfind(file.string(), 0) == 0 ? reason : file.string() + ": " + reason);
  }
  return std::nullopt;
}

// Red and black stripes: a cell whose map could not be read.
Rgb broken_tile(int x, int y) { return ((x + y) / 4) % 2 ? Rgb{0.85f, 0.1f, 0.1f} : Rgb{0.05f, 0.05f, 0.05f}; }

// A frame of width x height drawn as the columns show it, RGB per column. A map that cannot be
// read is drawn as a broken tile and named in `damaged`. The data maps are drawn where a surface
// is (the depth map's coverage: the object's, and its surroundings' where it has any), the label
// where the object is (the label's pixels); depth is normalised over the object's pixels. The
// region map, where a variant has one, shows the target in orange and its surroundings in blue.
// The sample counts are drawn as a heat map of the fraction of
// max_samples (the render's; 0: unknown, the frame's most) each pixel took, over the background
// too; a dataset without them (the repository's) leaves that column grey.
std::vector<std::vector<Rgb>> draw_frame(const fs::path& variant, const std::string& stem, int w, int h,
                                         int max_samples, std::vector<std::string>& damaged) {
  std::map<std::string, std::optional<Map>> maps;
  const bool sample_counts = fs::is_directory(variant / "sample_count");
  const bool regions = fs::is_directory(variant / "region");
  for (const Column& column : kColumns)
    if (*column.folder && !maps.count(column.folder) &&
        (sample_counts || std::string(column.folder) != "sample_count") &&
        (regions || std::string(column.folder) != "region"))
      maps[column.folder] = read_map(variant / column.folder / (stem + column.extension), w, h, damaged);
  const std::optional<Map>& label = maps.at("label");
  const std::optional<Map>& depth = maps.at("depth");
  const auto is_object = [&](int x, int y) {
    if (label) return label->at(x, y, 0) > 0.0f;
    return depth && depth->at(x, y, 3) > 0.0f;
  };
  const auto is_surface = [&](int x, int y) { return depth ? depth->at(x, y, 3) > 0.0f : is_object(x, y); };
  float most_samples = static_cast<float>(max_samples);
  const std::optional<Map>* counts = sample_counts ? &maps.at("sample_count") : nullptr;
  if (counts && counts->has_value() && max_samples <= 0)
    for (const float count : (*counts)->values)
      most_samples = std::max(most_samples, count * static_cast<float>(kMaxSampleCount));
  // Depth normalised over the object: near bright, far dark.
  float near = INFINITY, far = -INFINITY;
  if (depth)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (is_object(x, y)) near = std::min(near, depth->at(x, y, 0)), far = std::max(far, depth->at(x, y, 0));
  const Rgb background{kBackground, kBackground, kBackground};
  std::vector<std::vector<Rgb>> columns(kColumns.size(), std::vector<Rgb>(static_cast<size_t>(w) * static_cast<size_t>(h)));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
      const bool object = is_object(x, y), surface = is_surface(x, y);
      const auto over = [&](const std::optional<Map>& m) {  // straight-alpha colour over the background
        if (!m) return broken_tile(x, y);
        const float a = m->at(x, y, 3);
        return Rgb{m->at(x, y, 0) * a + kBackground * (1 - a), m->at(x, y, 1) * a + kBackground * (1 - a),
                   m->at(x, y, 2) * a + kBackground * (1 - a)};
      };
      const auto grey = [&](const std::optional<Map>& m, int channel) {
        if (!m) return broken_tile(x, y);
        const float v = m->at(x, y, channel);
        return surface ? Rgb{v, v, v} : background;
      };
      const auto rgb = [&](const std::optional<Map>& m) {
        if (!m) return broken_tile(x, y);
        return surface ? Rgb{m->at(x, y, 0), m->at(x, y, 1), m->at(x, y, 2)} : background;
      };
      const std::optional<Map>& orm = maps.at("ORM");
      columns[0][p] = over(maps.at("images"));
      columns[1][p] = over(maps.at("albedo"));
      columns[2][p] = grey(orm, 1);
      columns[3][p] = grey(orm, 2);
      columns[4][p] = grey(orm, 0);
      columns[5][p] = rgb(maps.at("normal_obj"));
      columns[6][p] = rgb(maps.at("normal_mat"));
      if (!depth) columns[7][p] = broken_tile(x, y);
      else {
        const float d = depth->at(x, y, 0);
        const float shade = far > near ? std::clamp(0.15f + 0.85f * (far - d) / (far - near), 0.05f, 1.0f) : 1.0f;
        columns[7][p] = surface ? Rgb{shade, shade, shade} : background;
      }
      if (!label) columns[8][p] = broken_tile(x, y);
      else {
        const std::array<uint8_t, 3> colour = matmaterial::label_colour(static_cast<int>(std::lround(label->at(x, y, 0) * 255.0f)));
        columns[8][p] = object ? Rgb{colour[0] / 255.0f, colour[1] / 255.0f, colour[2] / 255.0f} : background;
      }
      if (!regions) columns[9][p] = background;
      else if (!maps.at("region")) columns[9][p] = broken_tile(x, y);
      else {
        const long region = std::lround(maps.at("region")->at(x, y, 0) * 255.0f);
        columns[9][p] = region == 2 ? Rgb{0.95f, 0.55f, 0.15f} : region == 1 ? Rgb{0.25f, 0.45f, 0.8f} : background;
      }
      if (!counts) columns[10][p] = background;
      else if (!counts->has_value()) columns[10][p] = broken_tile(x, y);
      else
        columns[10][p] = heat((*counts)->at(x, y, 0) * static_cast<float>(kMaxSampleCount) /
                             std::max(1.0f, most_samples));
    }
  return columns;
}

// The area average of `image` (w x h) over each pixel of a cw x ch cell.
std::vector<Rgb> shrink(const std::vector<Rgb>& image, int w, int h, int cw, int ch) {
  std::vector<Rgb> cell(static_cast<size_t>(cw) * static_cast<size_t>(ch));
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x) {
      const int x0 = x * w / cw, x1 = std::max(x0 + 1, (x + 1) * w / cw);
      const int y0 = y * h / ch, y1 = std::max(y0 + 1, (y + 1) * h / ch);
      Rgb sum{0, 0, 0};
      for (int sy = y0; sy < y1; ++sy)
        for (int sx = x0; sx < x1; ++sx)
          for (int c = 0; c < 3; ++c)
            sum[static_cast<size_t>(c)] += image[static_cast<size_t>(sy) * static_cast<size_t>(w) + static_cast<size_t>(sx)][static_cast<size_t>(c)];
      const float n = static_cast<float>((x1 - x0) * (y1 - y0));
      cell[static_cast<size_t>(y) * static_cast<size_t>(cw) + static_cast<size_t>(x)] = {sum[0] / n, sum[1] / n, sum[2] / n};
    }
  return cell;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw std::runtime_error(file.string() + ": not a JSON object");
  return json;
}

struct VariantSheet {
  std::string object, variant, file;
  size_t frames = 0;
  std::vector<std::string> stems;  // the rows
  std::string materials;           // "all: wood_raw_1 (wood)"
  std::string settings;            // "128 x 128, 32 spp"
  int max_samples = 0;             // the render's samples per pixel, where metadata.json says
  int cell_width = 0;              // pixels, for the page's column headings
  std::vector<std::string> damaged;  // maps drawn as broken tiles: file and why
};

// The frames' stems and the frame size transforms.json states; std::runtime_error naming the
// file for a list or size that is not there or not usable.
struct FrameList {
  std::vector<std::string> stems;
  std::vector<nlohmann::json> lighting;  // each frame's "lighting" record, or null
  int width = 0, height = 0;
};
FrameList read_frame_list(const fs::path& file) {
  const nlohmann::json transforms = read_json(file);
  FrameList list;
  for (const char* key : {"w", "h"}) {
    const auto side = transforms.find(key);
    if (side == transforms.end() || !side->is_number_integer() || side->get<int64_t>() < 1 ||
        side->get<int64_t>() > kMaxSide)
      throw std::runtime_error(fmt::format("{}: {} is not a whole number of pixels from 1 to {}", file.string(), key,
                                           kMaxSide));
    (std::string(key) == "w" ? list.width : list.height) = side->get<int>();
  }
  const auto frames = transforms.find("frames");
  if (frames == transforms.end() || !frames->is_array()) throw std::runtime_error(file.string() + ": no frames list");
  for (const nlohmann::json& frame : *frames) {
    if (!frame.is_object() || !frame.contains("file_path") || !frame["file_path"].is_string())
      throw std::runtime_error(file.string() + ": a frame has no file_path");
    const std::string path = frame["file_path"].get<std::string>();
    list.stems.push_back(path.substr(path.rfind('/') + 1));
    list.lighting.push_back(frame.value("lighting", nlohmann::json()));
  }
  if (list.stems.empty()) throw std::runtime_error(file.string() + ": lists no frame");
  return list;
}

// A string member of a JSON object, or "?" where it has none: the page shows what the file says.
std::string text_or_unknown(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : "?";
}

// What the page says of a variant from its metadata.json: its materials and render settings.
void describe_variant(const nlohmann::json& metadata, VariantSheet& sheet) {
  if (const auto used = metadata.find("used_materials"); used != metadata.end() && used->is_object())
    for (const auto& [slot, material] : used->items())
      if (material.is_object())
        sheet.materials += (sheet.materials.empty() ? "" : "; ") + slot + ": " + text_or_unknown(material, "material") +
                           " (" + text_or_unknown(material, "material_family") + ")";
  const nlohmann::json::json_pointer width("/render_summary/resolution/width"),
      height("/render_summary/resolution/height"), samples("/render_summary/samples");
  if (metadata.contains(samples) && metadata[samples].is_number_integer() && metadata.contains(width) &&
      metadata[width].is_number_integer() && metadata.contains(height) && metadata[height].is_number_integer()) {
    sheet.max_samples = metadata[samples].get<int>();
    sheet.settings = fmt::format("{} x {}, {} spp", metadata[width].get<int>(), metadata[height].get<int>(),
                                 sheet.max_samples);
  }
}

// The object's bounding sphere, where metadata.json records it (provenance.lights.bounds).
std::optional<matgeom::Sphere> lighting_bounds(const nlohmann::json& metadata) {
  const nlohmann::json::json_pointer center("/provenance/lights/bounds/center"), radius("/provenance/lights/bounds/radius");
  if (!metadata.contains(center) || !metadata.contains(radius) || !metadata[radius].is_number()) return std::nullopt;
  const nlohmann::json& c = metadata[center];
  if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number()) return std::nullopt;
  return matgeom::Sphere{glm::dvec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()), metadata[radius].get<double>()};
}

// The lighting column's cell: the frame's lighting panorama (lighting_panorama.h), twice as wide
// as high, across the middle of a w x h cell of the background; the background alone for a frame
// whose lighting is not recorded (the repository's datasets, the rig's before lighting setups).
std::vector<Rgb> draw_lighting(const nlohmann::json& lighting, const std::optional<matgeom::Sphere>& bounds,
                               const fs::path& variant, int w, int h, std::vector<std::string>& damaged) {
  std::vector<Rgb> cell(static_cast<size_t>(w) * static_cast<size_t>(h), Rgb{kBackground, kBackground, kBackground});
  if (!lighting.is_object() || !bounds) return cell;
  const int band = std::max(1, std::min(h, w / 2)), top = (h - band) / 2;
  try {
    const std::vector<Rgb> panorama = draw_lighting_panorama(lighting, *bounds, variant, w, band);
    std::copy(panorama.begin(), panorama.end(), cell.begin() + static_cast<std::ptrdiff_t>(top) * w);
  } catch (const std::exception& e) {
    damaged.push_back((variant / "transforms.json").string() + ": a frame's lighting: " + e.what());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) cell[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] = broken_tile(x, y);
  }
  return cell;
}

// Writes the variant's sheet into `out`; returns what the page says of it.
VariantSheet write_sheet(const fs::path& variant, const fs::path& out, const PreviewOptions& options) {
  VariantSheet sheet;
  sheet.object = variant.parent_path().filename().string();
  sheet.variant = variant.filename().string();
  sheet.file = sheet.object + "__" + sheet.variant + ".png";
  const FrameList list = read_frame_list(variant / "transforms.json");
  const std::vector<std::string>& stems = list.stems;
  sheet.frames = stems.size();
  const size_t rows = std::min<size_t>(stems.size(), static_cast<size_t>(options.views));
  std::vector<const nlohmann::json*> lightings;
  for (size_t r = 0; r < rows; ++r) {
    const size_t frame = rows == 1 ? 0 : r * (stems.size() - 1) / (rows - 1);
    sheet.stems.push_back(stems[frame]);
    lightings.push_back(&list.lighting[frame]);
  }
  std::optional<matgeom::Sphere> bounds;
  if (fs::is_regular_file(variant / "metadata.json")) {
    const nlohmann::json metadata = read_json(variant / "metadata.json");
    describe_variant(metadata, sheet);
    bounds = lighting_bounds(metadata);
  }

  const int w = list.width, h = list.height;
  const int cw = w >= h ? options.cell : std::max(1, options.cell * w / h);
  const int ch = w >= h ? std::max(1, options.cell * h / w) : options.cell;
  sheet.cell_width = cw;
  const int sheet_w = static_cast<int>(kColumns.size()) * (cw + kGapPixels) + kGapPixels;
  const int sheet_h = static_cast<int>(rows) * (ch + kGapPixels) + kGapPixels;
  std::vector<float> pixels(static_cast<size_t>(sheet_w) * static_cast<size_t>(sheet_h) * 3, kGap);
  for (size_t r = 0; r < rows; ++r) {
    std::vector<std::vector<Rgb>> columns = draw_frame(variant, sheet.stems[r], w, h, sheet.max_samples, sheet.damaged);
    columns[kLightingColumn] = draw_lighting(*lightings[r], bounds, variant, w, h, sheet.damaged);
    for (size_t c = 0; c < columns.size(); ++c) {
      const std::vector<Rgb> cell = shrink(columns[c], w, h, cw, ch);
      const int ox = kGapPixels + static_cast<int>(c) * (cw + kGapPixels);
      const int oy = kGapPixels + static_cast<int>(r) * (ch + kGapPixels);
      for (int y = 0; y < ch; ++y)
        for (int x = 0; x < cw; ++x)
          for (int k = 0; k < 3; ++k)
            pixels[(static_cast<size_t>(oy + y) * static_cast<size_t>(sheet_w) + static_cast<size_t>(ox + x)) * 3 +
                   static_cast<size_t>(k)] =
                cell[static_cast<size_t>(y) * static_cast<size_t>(cw) + static_cast<size_t>(x)][static_cast<size_t>(k)];
    }
  }
  // The maps are display-encoded or data already: written as they are drawn.
  matbase::write_data_png((out / sheet.file).string(), sheet_w, sheet_h, 3, pixels.data(), 255.0, 0.0, false);
  return sheet;
}

std::string index_html(const fs::path& root, const std::vector<VariantSheet>& sheets) {
  std::map<std::string, std::vector<const VariantSheet*>> by_object;
  size_t frames = 0;
  for (const VariantSheet& sheet : sheets) by_object[sheet.object].push_back(&sheet), frames += sheet.frames;
  std::string columns;
  for (const Column& column : kColumns) columns += (columns.empty() ? "" : ", ") + std::string(column.name);
  std::string html = fmt::format(R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{0} — dataset preview</title>
<style>
body {{ font-family: sans-serif; background: #1b1b1b; color: #ddd; margin: 2em; }}
h2 {{ border-bottom: 1px solid #555; }}
figure {{ margin: 0 0 2em 0; }}
figcaption {{ margin: 0.3em 0; }}
img {{ display: block; image-rendering: pixelated; }}
.ok {{ color: #7c7; }} .broken {{ color: #f66; font-weight: bold; }} .damaged {{ color: #f66; }}
.heads {{ display: flex; padding-left: 2px; font-size: 11px; color: #aaa; }}
.heads span {{ overflow: hidden; white-space: nowrap; }}
</style>
</head>
<body>
<h1>{0}</h1>
<p>{1} objects, {2} variants, {3} frames. Each sheet's rows are views spread over the variant's
frames; its columns: {4}.</p>
<p id="image-check">checking that every image loads…</p>
)",
                                 html_escape(root.filename().string().empty() ? root.string() : root.filename().string()),
                                 by_object.size(), sheets.size(), frames, columns);
  for (const auto& [object, list] : by_object) {
    html += "<h2>" + html_escape(object) + "</h2>\n";
    for (const VariantSheet* sheet : list) {
      std::string rows;
      for (const std::string& stem : sheet->stems) rows += (rows.empty() ? "" : ", ") + stem;
      std::string heads;
      for (const Column& column : kColumns)
        heads += fmt::format("<span style=\"width: {}px\">{}</span>", sheet->cell_width + kGapPixels, column.name);
      std::string damaged;
      for (const std::string& problem : sheet->damaged) damaged += "<br>" + html_escape(problem);
      html += fmt::format("<figure>\n<figcaption><b>{}</b> — {} frames{}{}; rows: views {}{}</figcaption>\n"
                          "<div class=\"heads\">{}</div>\n"
                          "<a href=\"{}\"><img src=\"{}\" alt=\"{} {}\"></a>\n</figure>\n",
                          html_escape(sheet->variant), sheet->frames,
                          sheet->materials.empty() ? "" : "; " + html_escape(sheet->materials),
                          sheet->settings.empty() ? "" : "; " + html_escape(sheet->settings), html_escape(rows),
                          damaged.empty() ? "" : "<br><span class=\"damaged\">damaged maps, drawn as red and black "
                                                 "stripes:" + damaged + "</span>",
                          heads,
                          html_escape(sheet->file), html_escape(sheet->file), html_escape(sheet->object),
                          html_escape(sheet->variant));
    }
  }
  html += R"(<script>
// Says in the page whether every image loaded (a browser test reads it).
window.addEventListener("load", () => {
  const images = Array.from(document.images);
  const broken = images.filter((image) => !(image.complete && image.naturalWidth > 0));
  const check = document.getElementById("image-check");
  check.textContent = `images: ${images.length - broken.length} of ${images.length} loaded` +
      (broken.length ? `; broken: ${broken.map((image) => image.getAttribute("src")).join(", ")}` : "");
  check.className = broken.length ? "broken" : "ok";
});
</script>
</body>
</html>
)";
  return html;
}

// Replaces `folder` by `staged` (a complete folder beside it): a reader sees the old folder or the
// new one, never a mix, and a failed swap leaves the old one.
void replace_folder(const fs::path& folder, const fs::path& staged) {
  const fs::path old = staged.string() + "-old";
  fs::remove_all(old);
  const bool existed = fs::exists(folder);
  if (existed) fs::rename(folder, old);
  try {
    fs::rename(staged, folder);
  } catch (...) {
    if (existed) fs::rename(old, folder);
    throw;
  }
  fs::remove_all(old);
}

}  // namespace

PreviewSummary write_preview(const fs::path& root, const PreviewOptions& options) {
  const std::vector<fs::path> variants = variant_folders(root, "transforms.json");
  const fs::path out = root / kPreviewFolder;
  // Every sheet and the page are made in a hidden folder beside preview/, which replaces it only
  // when all are written: after an error the old preview stays whole, with nothing new in it.
  const fs::path staged = matbase::temporary_path(out);
  fs::remove_all(staged);
  PreviewSummary summary;
  try {
    fs::create_directories(staged);
    std::vector<VariantSheet> sheets;
    for (const fs::path& variant : variants) {
      sheets.push_back(write_sheet(variant, staged, options));
      summary.damaged.insert(summary.damaged.end(), sheets.back().damaged.begin(), sheets.back().damaged.end());
    }
    matbase::write_file_atomically(staged / "index.html", index_html(root, sheets));
    replace_folder(out, staged);
    summary.sheets = sheets.size();
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staged, ignored);
    throw;
  }
  summary.index = out / "index.html";
  return summary;
}

}  // namespace matdataset
