#include "matbase/file/input_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

namespace matbase {

std::optional<std::string> input_file_problem(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) return std::string("no such file");
  if (error) return "cannot inspect the file (" + error.message() + ")";
  if (status.type() == fs::file_type::regular) return std::nullopt;
  if (status.type() == fs::file_type::directory) return std::string("is a directory, not a file");
  return std::string("is a device, FIFO or socket, not a regular file");
}

void require_input_file(const std::string& path) {
  if (const std::optional<std::string> problem = input_file_problem(path)) throw std::runtime_error(path + ": " + *problem);
}

std::optional<std::string> read_whole_file(const std::filesystem::path& file, std::string& bytes) {
  if (std::optional<std::string> problem = input_file_problem(file.string())) return problem;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::string("cannot open the file");
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (in.bad()) return std::string("cannot read the file");
  return std::nullopt;
}

}  // namespace matbase
