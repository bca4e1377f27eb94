#pragma once
// Evaluation tables shaped like the paper's (one row per material or object, the eight metrics
// per predicted map), written as markdown, CSV and JSON.
#include <filesystem>
#include <string>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matlearn/evaluation/evaluator.h"

namespace matlearn {

struct ReportRow {
  std::string group;  // a material family, an object, or "all"
  std::string map;
  int maps_scored = 0;
  MetricScores mean;
};

struct ReportTable {
  std::string title;  // "by material", "by object", "overall"
  std::vector<ReportRow> rows;
};

// Means over the scored maps: by material family (each family's pixels), by object and over
// everything (whole objects).
std::vector<ReportTable> report_tables(const std::vector<ScoredMap>& scores);

// Writes metrics.md, metrics.csv and metrics.json into `folder`, all three or none (staged into
// `set` when one is given, to appear with its other files); `preamble` (markdown) opens
// metrics.md and goes into the JSON as "about".
void write_report(const std::filesystem::path& folder, const std::vector<ReportTable>& tables,
                  const std::string& preamble, matbase::AtomicFileSet* set = nullptr);

}  // namespace matlearn
