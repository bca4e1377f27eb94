// The material folder reader on hostile files: the first byte picks the file the rest becomes
// (metadata.json, a normal map or a roughness map) in a folder that also holds a valid base
// colour map. The reader may accept the folder or throw std::runtime_error; anything else is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "matbase/image/png_encoding.h"
#include "matmaterial/folder/material_folder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("matpredict_fuzz_folder_" + std::to_string(::getpid())) / "wood_1";
  static const bool made = [] {
    std::filesystem::create_directories(folder);
    const matbase::ImagePixels base{"base", 2, 2, 3, {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120}};
    std::ofstream(folder / "basecolor.png", std::ios::binary) << matbase::encode_png(base, "basecolor.png");
    return true;
  }();
  (void)made;
  if (size == 0) return 0;
  const char* names[] = {"metadata.json", "normal.png", "roughness.png"};
  const std::string name = names[data[0] % 3];
  for (const char* other : names) std::filesystem::remove(folder / other);
  std::ofstream(folder / name, std::ios::binary).write(reinterpret_cast<const char*>(data + 1),
                                                       static_cast<std::streamsize>(size - 1));
  try {
    matmaterial::read_material_folder(folder.string());
  } catch (const std::runtime_error&) {
    // a clear rejection: the expected outcome for most inputs
  }
  return 0;
}
