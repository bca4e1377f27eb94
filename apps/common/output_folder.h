#pragma once
// A folder an app makes for its outputs, removed again (if still empty) unless keep() is called:
// a run whose writes failed leaves no trace, not even an empty folder.
#include <filesystem>

namespace app_support {

class OutputFolder {
 public:
  // Creates `path` and any missing parents; std::runtime_error naming it on failure.
  explicit OutputFolder(std::filesystem::path path);
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  ~OutputFolder();

  // The outputs are in place: the folder stays.
  void keep() { made_ = false; }

 private:
  std::filesystem::path path_;
  bool made_ = false;  // this object created the folder
};

}  // namespace app_support
