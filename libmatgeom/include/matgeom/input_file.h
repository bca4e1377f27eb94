#pragma once
// The one check every reader makes before it opens a file it was given: the path must name a
// regular file. A directory fails late with an odd message; a device (/dev/zero) or a FIFO can
// block a reader or feed it forever, so neither is ever opened.
#include <optional>
#include <string>

namespace matgeom {

// "no such file", "is a directory, not a file", "is a device, FIFO or socket, not a regular
// file" (symbolic links are followed), or nothing for a regular file.
std::optional<std::string> input_file_problem(const std::string& path);

// Throws std::runtime_error "<path>: <problem>" unless `path` names a regular file.
void require_input_file(const std::string& path);

}  // namespace matgeom
