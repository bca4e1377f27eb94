#include "common/output_folder.h"

#include <stdexcept>
#include <system_error>
#include <utility>

namespace app_support {

OutputFolder::OutputFolder(std::filesystem::path path) : path_(std::move(path)) {
  std::error_code error;
  made_ = std::filesystem::create_directories(path_, error);
  if (error) throw std::runtime_error(path_.string() + ": cannot create the folder: " + error.message());
}

OutputFolder::~OutputFolder() {
  std::error_code ignored;
  if (made_) std::filesystem::remove(path_, ignored);  // fails, as it should, unless empty
}

}  // namespace app_support
