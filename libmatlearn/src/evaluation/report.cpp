#include "matlearn/evaluation/report.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "matbase/file/atomic_file.h"
#include "matmaterial/material_classes.h"

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
                     g = matmaterial::label_name(s.material);
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
                  const std::string& preamble, matbase::AtomicFileSet* set) {
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
  matbase::AtomicFileSet own(folder / "metrics.json");
  matbase::AtomicFileSet& files = set ? *set : own;
  files.stage(folder / "metrics.md", md.str());
  files.stage(folder / "metrics.csv", csv.str());
  files.stage(folder / "metrics.json", json.dump(2) + "\n");
  if (!set) own.commit();
}

}  // namespace matlearn
