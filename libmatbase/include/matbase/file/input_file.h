#pragma once
// The one check every reader makes before it opens a file it was given: the path must name a
// regular file. A directory fails late with an odd message; a device (/dev/zero) or a FIFO can
// block a reader or feed it forever, so neither is ever opened.
#include <filesystem>
#include <optional>
#include <string>

namespace matbase {

// "no such file", "is a directory, not a file", "is a device, FIFO or socket, not a regular
// file" (symbolic links are followed), or nothing for a regular file.
std::optional<std::string> input_file_problem(const std::string& path);

// Throws std::runtime_error "<path>: <problem>" unless `path` names a regular file.
void require_input_file(const std::string& path);

// The whole of the regular file `file` into `bytes`, or the problem (input_file_problem's, or
// that it could not be opened or read).
std::optional<std::string> read_whole_file(const std::filesystem::path& file, std::string& bytes);

}  // namespace matbase
