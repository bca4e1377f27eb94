#include "dataset_preview.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dataset_folders.h"
#include "matgeom/atomic_file.h"
#include "matgeom/image_writing.h"
#include "matgeom/material_classes.h"
#include "matlearn/dataset_writer.h"
#include "matlearn/decoded_image.h"

namespace make_dataset {
namespace {

namespace fs = std::filesystem;

constexpr float kBackground = 0.16f;  // grey where the object is not
constexpr float kGap = 0.06f;         // between cells
constexpr int kGapPixels = 2;

using Map = matlearn::Decoded;

using Rgb = std::array<float, 3>;

// One column of the sheet: what it shows of a frame at a pixel, given the frame's maps.
struct Column {
  const char* name;
  const char* folder;
  const char* extension;
};
constexpr std::array<Column, 10> kColumns = {{{"image", "images", ".png"},
                                             {"albedo", "albedo", ".png"},
                                             {"roughness", "ORM", ".png"},
                                             {"metallic", "ORM", ".png"},
                                             {"occlusion", "ORM", ".png"},
                                             {"normal (world)", "normal_obj", ".png"},
                                             {"normal (map)", "normal_mat", ".png"},
                                             {"depth", "depth", ".exr"},
                                             {"label", "label", ".png"},
                                             {"samples", "sample_count", ".png"}}};

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

// A frame drawn as the columns show it: width x height RGB per column. The sample counts are
// drawn as a heat map of the fraction of max_samples (the render's; 0: unknown, the frame's
// most) each pixel took, over the background too; a dataset without them (the repository's)
// leaves that column grey.
std::vector<std::vector<Rgb>> draw_frame(const fs::path& variant, const std::string& stem, int max_samples) {
  std::map<std::string, Map> maps;
  const bool sample_counts = fs::is_directory(variant / "sample_count");
  for (const Column& column : kColumns)
    if (!maps.count(column.folder) && (sample_counts || std::string(column.folder) != "sample_count"))
      maps[column.folder] = matlearn::decode(variant / column.folder / (stem + column.extension));
  const Map& label = maps.at("label");
  const Map& depth = maps.at("depth");
  const int w = label.width, h = label.height;
  for (const auto& [folder, map] : maps)
    if (map.width != w || map.height != h)
      throw std::runtime_error((variant / folder / stem).string() + ": its size differs from the frame's label map");
  float most_samples = static_cast<float>(max_samples);
  if (sample_counts && max_samples <= 0)
    for (const float count : maps.at("sample_count").values)
      most_samples = std::max(most_samples, count * static_cast<float>(matlearn::kMaxSampleCount));
  // Depth normalised over the object: near bright, far dark.
  float near = INFINITY, far = -INFINITY;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (label.at(x, y, 0) > 0.0f) near = std::min(near, depth.at(x, y, 0)), far = std::max(far, depth.at(x, y, 0));
  std::vector<std::vector<Rgb>> columns(kColumns.size(), std::vector<Rgb>(static_cast<size_t>(w) * static_cast<size_t>(h)));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
      const int id = static_cast<int>(std::lround(label.at(x, y, 0) * 255.0f));
      const bool object = id > 0;
      const auto over = [&](const Map& m) {  // straight-alpha colour over the background
        const float a = m.at(x, y, 3);
        return Rgb{m.at(x, y, 0) * a + kBackground * (1 - a), m.at(x, y, 1) * a + kBackground * (1 - a),
                   m.at(x, y, 2) * a + kBackground * (1 - a)};
      };
      const auto grey = [&](float v) { return object ? Rgb{v, v, v} : Rgb{kBackground, kBackground, kBackground}; };
      const auto rgb = [&](const Map& m) {
        return object ? Rgb{m.at(x, y, 0), m.at(x, y, 1), m.at(x, y, 2)} : Rgb{kBackground, kBackground, kBackground};
      };
      const Map& orm = maps.at("ORM");
      columns[0][p] = over(maps.at("images"));
      columns[1][p] = over(maps.at("albedo"));
      columns[2][p] = grey(orm.at(x, y, 1));
      columns[3][p] = grey(orm.at(x, y, 2));
      columns[4][p] = grey(orm.at(x, y, 0));
      columns[5][p] = rgb(maps.at("normal_obj"));
      columns[6][p] = rgb(maps.at("normal_mat"));
      columns[7][p] = grey(far > near ? 0.15f + 0.85f * (far - depth.at(x, y, 0)) / (far - near) : 1.0f);
      const std::array<uint8_t, 3> colour = matgeom::label_colour(id);
      columns[8][p] = object ? Rgb{colour[0] / 255.0f, colour[1] / 255.0f, colour[2] / 255.0f}
                             : Rgb{kBackground, kBackground, kBackground};
      columns[9][p] = sample_counts ? heat(maps.at("sample_count").at(x, y, 0) *
                                           static_cast<float>(matlearn::kMaxSampleCount) / std::max(1.0f, most_samples))
                                    : Rgb{kBackground, kBackground, kBackground};
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
};

// Writes the variant's sheet into `out`; returns what the page says of it.
VariantSheet write_sheet(const fs::path& variant, const fs::path& out, const PreviewOptions& options) {
  VariantSheet sheet;
  sheet.object = variant.parent_path().filename().string();
  sheet.variant = variant.filename().string();
  sheet.file = sheet.object + "__" + sheet.variant + ".png";
  const nlohmann::json transforms = read_json(variant / "transforms.json");
  std::vector<std::string> stems;
  for (const nlohmann::json& frame : transforms.at("frames")) {
    const std::string path = frame.at("file_path").get<std::string>();
    stems.push_back(path.substr(path.rfind('/') + 1));
  }
  sheet.frames = stems.size();
  if (stems.empty()) throw std::runtime_error((variant / "transforms.json").string() + ": lists no frame");
  const size_t rows = std::min<size_t>(stems.size(), static_cast<size_t>(options.views));
  for (size_t r = 0; r < rows; ++r)
    sheet.stems.push_back(stems[rows == 1 ? 0 : r * (stems.size() - 1) / (rows - 1)]);
  if (fs::is_regular_file(variant / "metadata.json")) {
    const nlohmann::json metadata = read_json(variant / "metadata.json");
    const nlohmann::json used_materials = metadata.value("used_materials", nlohmann::json::object());
    for (const auto& [slot, used] : used_materials.items())
      sheet.materials += (sheet.materials.empty() ? "" : "; ") + slot + ": " + used.value("material", "?") + " (" +
                         used.value("material_family", "?") + ")";
    const nlohmann::json summary = metadata.value("render_summary", nlohmann::json::object());
    if (summary.contains("resolution") && summary.contains("samples") && summary["samples"].is_number_integer()) {
      sheet.max_samples = summary["samples"].get<int>();
      sheet.settings = fmt::format("{} x {}, {} spp", summary["resolution"].value("width", 0),
                                   summary["resolution"].value("height", 0), sheet.max_samples);
    }
  }

  const int w = transforms.at("w").get<int>(), h = transforms.at("h").get<int>();
  const int cw = w >= h ? options.cell : std::max(1, options.cell * w / h);
  const int ch = w >= h ? std::max(1, options.cell * h / w) : options.cell;
  sheet.cell_width = cw;
  const int sheet_w = static_cast<int>(kColumns.size()) * (cw + kGapPixels) + kGapPixels;
  const int sheet_h = static_cast<int>(rows) * (ch + kGapPixels) + kGapPixels;
  std::vector<float> pixels(static_cast<size_t>(sheet_w) * static_cast<size_t>(sheet_h) * 3, kGap);
  for (size_t r = 0; r < rows; ++r) {
    const std::vector<std::vector<Rgb>> columns =
        draw_frame(variant, sheet.stems[r], sheet.max_samples);
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
  matgeom::write_data_png((out / sheet.file).string(), sheet_w, sheet_h, 3, pixels.data(), 255.0, 0.0, false);
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
.ok {{ color: #7c7; }} .broken {{ color: #f66; font-weight: bold; }}
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
      html += fmt::format("<figure>\n<figcaption><b>{}</b> — {} frames{}{}; rows: views {}</figcaption>\n"
                          "<div class=\"heads\">{}</div>\n"
                          "<a href=\"{}\"><img src=\"{}\" alt=\"{} {}\"></a>\n</figure>\n",
                          html_escape(sheet->variant), sheet->frames,
                          sheet->materials.empty() ? "" : "; " + html_escape(sheet->materials),
                          sheet->settings.empty() ? "" : "; " + html_escape(sheet->settings), html_escape(rows), heads,
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

}  // namespace

PreviewSummary write_preview(const fs::path& root, const PreviewOptions& options) {
  const std::vector<fs::path> variants = variant_folders(root, "transforms.json");
  const fs::path out = root / kPreviewFolder;
  fs::create_directories(out);
  std::vector<VariantSheet> sheets;
  for (const fs::path& variant : variants) sheets.push_back(write_sheet(variant, out, options));
  PreviewSummary summary;
  summary.sheets = sheets.size();
  summary.index = out / "index.html";
  matgeom::write_file_atomically(summary.index, index_html(root, sheets));
  return summary;
}

}  // namespace make_dataset
