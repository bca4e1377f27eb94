#pragma once
// libFuzzer entry points for the mesh loaders, which read paths: each input is written to a
// file of the loader's extension and read. A loader may accept the bytes or throw
// std::runtime_error; anything else (another exception, a crash, a sanitizer report) is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

template <class Read>
int fuzz_file(const uint8_t* data, size_t size, const char* extension, Read read) {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("matpredict_fuzz_" + std::to_string(::getpid()) + extension))
                                      .string();
  if (std::FILE* file = std::fopen(path.c_str(), "wb")) {
    if (size > 0) std::fwrite(data, 1, size, file);
    std::fclose(file);
  }
  try {
    read(path);
  } catch (const std::runtime_error&) {
    // a clear rejection: the expected outcome for most inputs
  }
  return 0;
}
