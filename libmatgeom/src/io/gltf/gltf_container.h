#pragma once
// Where a glTF file's JSON is: the whole of a .gltf, or the first chunk of a GLB, whose 12-byte
// header (magic "glTF", version, length) and chunk header (length, type "JSON") are checked with
// reasons before tinygltf sees them (tinygltf says "Invalid glTF binary" for all of them, a GLB of
// glTF 1.0 included).
#include <string>
#include <string_view>

namespace matgeom::gltf {

// The JSON text of `file`, the bytes of `path`; throws std::runtime_error("<path>: <problem>") for
// a GLB header or chunk header that does not hold (a version other than 2, a length beyond the
// file, a first chunk that is not JSON) and for JSON text in UTF-16 or UTF-32 (glTF requires
// UTF-8; a UTF-8 byte-order mark is allowed, and the JSON parsers skip it).
std::string_view gltf_json_text(const std::string& path, std::string_view file, bool binary);

}  // namespace matgeom::gltf
