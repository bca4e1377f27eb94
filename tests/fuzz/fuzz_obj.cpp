#include "fuzz_file.h"
#include "matgeom/io/obj/obj_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".obj", [](const std::string& path) { matgeom::read_obj(path); });
}
