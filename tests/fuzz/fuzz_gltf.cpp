#include "fuzz_file.h"
#include "matgeom/io/gltf/gltf_reader.h"

// ".gltf": the reader takes the GLB container by its magic and JSON otherwise.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".gltf", [](const std::string& path) { matgeom::read_gltf(path); });
}
