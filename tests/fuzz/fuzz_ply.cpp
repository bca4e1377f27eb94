#include "fuzz_file.h"
#include "matgeom/io/ply/ply_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".ply", [](const std::string& path) { matgeom::read_ply(path); });
}
