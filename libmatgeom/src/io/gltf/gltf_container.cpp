#include "io/gltf/gltf_container.h"

#include <cstdint>
#include <cstring>
#include <optional>

#include "matbase/file/file_error.h"
#include "matbase/text_encoding.h"

namespace matgeom::gltf {
namespace {

constexpr size_t kHeaderBytes = 12, kChunkHeaderBytes = 8;

uint32_t little_endian_u32(std::string_view bytes, size_t at) {
  uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<uint8_t>(bytes[at + static_cast<size_t>(k)]);
  return value;
}

std::string_view glb_json_chunk(const std::string& path, std::string_view file) {
  const auto too_short = [&] {
    matbase::fail(path, matbase::concat("a GLB file is at least ", kHeaderBytes + kChunkHeaderBytes,
                                        " bytes (its header and a chunk header); this one has ", file.size()));
  };
  if (file.size() < kHeaderBytes) too_short();
  const uint32_t version = little_endian_u32(file, 4);
  if (version != 2)
    matbase::fail(path, matbase::concat("GLB header: version ", version, version == 1 ? " (glTF 1.0)" : "",
                                        "; only version 2, glTF 2.0, is read"));
  if (file.size() < kHeaderBytes + kChunkHeaderBytes) too_short();
  const uint32_t length = little_endian_u32(file, 8);
  if (length > file.size())
    matbase::fail(path, matbase::concat("GLB header: length ", length, " bytes, but the file has ", file.size(), " (cut short?)"));
  if (file.substr(kHeaderBytes + 4, 4) != "JSON")
    matbase::fail(path, "GLB: the first chunk is of type " + matbase::excerpt(file.substr(kHeaderBytes + 4, 4)) +
                            ", not \"JSON\" (glTF 2.0 requires the JSON chunk first)");
  const uint32_t json_length = little_endian_u32(file, kHeaderBytes);
  if (json_length > file.size() - kHeaderBytes - kChunkHeaderBytes)
    matbase::fail(path, matbase::concat("GLB: the JSON chunk's ", json_length, " bytes run past the end of the file (",
                                        file.size(), " bytes)"));
  return file.substr(kHeaderBytes + kChunkHeaderBytes, json_length);
}

}  // namespace

std::string_view gltf_json_text(const std::string& path, std::string_view file, bool binary) {
  const std::string_view text = binary ? glb_json_chunk(path, file) : file;
  if (const std::optional<std::string> mark = matbase::byte_order_mark(text); mark && *mark != "UTF-8")
    matbase::fail(path, "the JSON is " + *mark + " text (it starts with a byte-order mark); glTF requires UTF-8");
  return text;
}

}  // namespace matgeom::gltf
