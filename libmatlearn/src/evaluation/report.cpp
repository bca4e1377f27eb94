#include "matlearn/evaluation/report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include "matlearn/material_families.h"

namespace matlearn {
namespace {

std::string number(double v) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.precision(5);
  out << v;
  return out.str();
}

void write_atomically(const std::filesystem::path& path, const std::string& text) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, path);
}

// Rows keyed by (group, map) in first-seen order of groups, maps in layout order.
ReportTable table_of(const std::string& title, const std::vector<ScoredMap>& scores,
                     const std::function<bool(const ScoredMap&, std::string&)>& group_of) {
  std::vector<std::string> groups, maps;
  std::map<std::pair<std::string, std::string>, ScoreMean> means;
  for (const ScoredMap& s : scores) {
    std::string group;
    if (!group_of(s, group)) continue;
    if (std::find(groups.begin(), groups.end(), group) == groups.end()) groups.push_back(group);
    if (std::find(maps.begin(), maps.end(), s.map) == maps.end()) maps.push_back(s.map);
    means[{group, s.map}].add(s.scores);
  }
  std::sort(groups.begin(), groups.end());
  ReportTable table{title, {}};
  for (const std::string& group : groups)
    for (const std::string& map : maps) {
      const auto it = means.find({group, map});
      if (it != means.end()) table.rows.push_back({group, map, it->second.count(), it->second.mean()});
    }
  return table;
}

}  // namespace

std::vector<ReportTable> report_tables(const std::vector<ScoredMap>& scores) {
  return {table_of("by material", scores,
                   [](const ScoredMap& s, std::string& g) {
                     if (s.material == kWholeObject) return false;
                     g = material_family_name(s.material);
                     return true;
                   }),
          table_of("by object", scores,
                   [](const ScoredMap& s, std::string& g) {
                     if (s.material != kWholeObject) return false;
                     g = s.sample.object;
                     return true;
                   }),
          table_of("overall", scores, [](const ScoredMap& s, std::string& g) {
            if (s.material != kWholeObject) return false;
            g = "all";
            return true;
          })};
}

void write_report(const std::filesystem::path& folder, const std::vector<ReportTable>& tables,
                  const std::string& preamble) {
  std::filesystem::create_directories(folder);
  std::ostringstream md, csv;
  md << preamble << "\n";
  csv << "table,group,map,maps_scored";
  for (Metric m : kAllMetrics) csv << ',' << metric_name(m);
  csv << '\n';
  nlohmann::json json = {{"about", preamble}, {"tables", nlohmann::json::array()}};
  for (const ReportTable& table : tables) {
    md << "\n## " << table.title << "\n\n| " << (table.title == "by object" ? "object" : table.title == "by material" ? "material" : "scope")
       << " | map | n |";
    for (Metric m : kAllMetrics) md << ' ' << metric_name(m) << (higher_is_better(m) ? " ↑" : " ↓") << " |";
    md << "\n|---|---|---:|";
    for (size_t m = 0; m < kAllMetrics.size(); ++m) md << "---:|";
    md << '\n';
    nlohmann::json rows = nlohmann::json::array();
    for (const ReportRow& row : table.rows) {
      md << "| " << row.group << " | " << row.map << " | " << row.maps_scored << " |";
      csv << table.title << ',' << row.group << ',' << row.map << ',' << row.maps_scored;
      nlohmann::json metrics = nlohmann::json::object();
      for (Metric m : kAllMetrics) {
        md << ' ' << number(row.mean[m]) << " |";
        csv << ',' << number(row.mean[m]);
        // JSON has no NaN or infinity: null and strings.
        const double v = row.mean[m];
        metrics[metric_name(m)] = std::isnan(v) ? nlohmann::json() : std::isinf(v) ? nlohmann::json(number(v)) : nlohmann::json(v);
      }
      md << '\n';
      csv << '\n';
      rows.push_back({{"group", row.group}, {"map", row.map}, {"maps_scored", row.maps_scored}, {"metrics", metrics}});
    }
    json["tables"].push_back({{"title", table.title}, {"rows", rows}});
  }
  write_atomically(folder / "metrics.md", md.str());
  write_atomically(folder / "metrics.csv", csv.str());
  write_atomically(folder / "metrics.json", json.dump(2) + "\n");
}

void write_panel(const std::filesystem::path& path, const SamplePredictions& sample) {
  const int w = sample.input.width, h = sample.input.height;
  const int rows = std::max<int>(1, static_cast<int>(sample.maps.size()));
  const int width = 4 * w, height = rows * h;
  std::vector<uint8_t> pixels(static_cast<size_t>(width) * static_cast<size_t>(height) * 3, 0);
  const auto put = [&](int tile_x, int tile_y, const Image& image, float scale) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          const float v = image.at(x, y, std::min(c, image.channels - 1)) * scale;
          pixels[(static_cast<size_t>(tile_y * h + y) * static_cast<size_t>(width) + static_cast<size_t>(tile_x * w + x)) * 3 +
                 static_cast<size_t>(c)] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
        }
  };
  put(0, 0, sample.input, 1.0f);
  for (size_t m = 0; m < sample.maps.size(); ++m) {
    const Image& truth = sample.truths[m];
    const Image& prediction = sample.predictions[m];
    // The error where it is scored, on the object; black elsewhere.
    Image error(truth.width, truth.height, truth.channels);
    for (size_t i = 0; i < error.values.size(); ++i) {
      const size_t pixel = i / static_cast<size_t>(truth.channels);
      if (sample.mask.empty() || sample.mask[pixel]) error.values[i] = std::abs(truth.values[i] - prediction.values[i]);
    }
    const int row = static_cast<int>(m);
    put(1, row, truth, 1.0f);
    put(2, row, prediction, 1.0f);
    put(3, row, error, 4.0f);
  }
  std::filesystem::create_directories(path.parent_path());
  const std::string temporary = path.string() + ".partial.png";
  auto out = OIIO::ImageOutput::create(temporary);
  if (!out || !out->open(temporary, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)) ||
      !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
    throw std::runtime_error("cannot write " + temporary);
  std::filesystem::rename(temporary, path);
}

}  // namespace matlearn
