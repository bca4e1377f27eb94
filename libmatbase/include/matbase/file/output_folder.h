#pragma once
// Whether a tool can write its outputs into a folder, checked before any work: a render of
// minutes, or a dataset's first files, must not end in "cannot create the folder".
#include <optional>
#include <string>

namespace matbase {

// Nothing when `folder` is a folder, or can be made, that this process can write to; else what
// stands in the way: "out.png is a file, not a folder", "results is a file, so no folder can be
// made in it", "/data is not writable (Permission denied)".
std::optional<std::string> output_folder_problem(const std::string& folder);

}  // namespace matbase
