#pragma once
// The glTF JSON as written, checked where tinygltf 2.7 would let a value pass unseen: it replaces
// a member of the wrong type (a string "metallicFactor", a fractional "wrapS") by its default
// without a word, takes any integer for a sampler's enums, and reports a data URI's size that
// does not match byteLength by quoting the whole URI.
#include <string>

namespace matgeom::gltf {

// Throws std::runtime_error("<path>: <problem>") for a GLB or text container that does not hold
// (gltf_container.h), JSON that does not parse (with the byte where it stops), a number beyond a
// double, an asset.version other than 2.x (glTF 1.0 named as such), a member whose type is not
// glTF 2.0's (gltf_schema.h), an extensionsRequired the reader does not apply (Draco, meshopt,
// KTX2...), a sampler's wrapS, wrapT, magFilter or minFilter
// outside glTF's enums, a material member of the wrong type (factors, alphaMode, alphaCutoff,
// texture infos), an alphaCutoff that is negative, a data URI of a media type tinygltf does not
// decode (it would look for a file of that name), and a buffer whose base64 data URI does not
// decode to its byteLength. `binary`: the file is a GLB, whose first chunk holds the JSON.
void check_gltf_json(const std::string& path, bool binary);

}  // namespace matgeom::gltf
