// The MTL reader on hostile files: each input becomes the .mtl file a fixed OBJ triangle names
// (its material "m", as the seeds name theirs), read with read_obj; a texture the seeds name,
// matpredict_fuzz_texture.png, lies beside it. The reader may accept the files or throw
// std::runtime_error; anything else is a bug.
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_file.h"
#include "matbase/image/png_encoding.h"
#include "matgeom/io/obj/obj_io.h"

namespace {

// The OBJ beside the .mtl at `mtl`, written once per process.
std::string obj_naming(const std::string& mtl) {
  const std::filesystem::path library(mtl);
  const std::filesystem::path obj = std::filesystem::path(library).replace_extension(".obj");
  std::ofstream(obj) << "mtllib " << library.filename().string()
                     << "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n";
  const matbase::ImagePixels texture{"texture", 2, 2, 3, {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120}};
  std::ofstream(library.parent_path() / "matpredict_fuzz_texture.png", std::ios::binary)
      << matbase::encode_png(texture, "matpredict_fuzz_texture.png");
  return obj.string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_file(data, size, ".mtl", [](const std::string& mtl) {
    static const std::string obj = obj_naming(mtl);
    matgeom::read_obj(obj);
  });
}
