#pragma once
// make_dataset --preview: a dataset a person can look at. One contact sheet per object and
// variant (rows: views spread over the grid; columns: the image and each map, drawn for the eye:
// data maps over grey where nothing is, depth normalised near-bright, labels in their class
// colours) and one index.html linking them with each variant's materials, frame count and
// render settings. The page checks in the browser that every image loaded and says so.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace matdataset {

struct PreviewOptions {
  int views = 8;   // rows per sheet at most, spread evenly over the variant's frames
  int cell = 96;   // pixels of a cell's longer side
};

struct PreviewSummary {
  size_t sheets = 0;
  std::filesystem::path index;        // the page
  std::vector<std::string> damaged;  // maps that could not be read, drawn as broken tiles: file and why
};

// Writes <root>/preview/<object>__<variant>.png for every variant and <root>/preview/index.html,
// replacing the folder whole once everything is written. A map that cannot be read is drawn as a
// broken tile and named on the page and in the summary. Throws matbase::InputError when `root` holds no
// dataset, std::runtime_error when a variant's records cannot be read or a file written; then
// the preview folder is as it was.
PreviewSummary write_preview(const std::filesystem::path& root, const PreviewOptions& options = {});

}  // namespace matdataset
