#include "fuzz_file.h"
#include "matrender/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".json", [](const std::string& path) { matrender::read_scene_file(path); });
}
