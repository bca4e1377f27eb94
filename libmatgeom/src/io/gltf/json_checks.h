#pragma once
// The glTF JSON as written, checked where tinygltf 2.7 would let a value pass unseen: it replaces
// a member of the wrong type (a string "metallicFactor", a fractional "wrapS") by its default
// without a word, takes any integer for a sampler's enums, and reports a data URI's size that
// does not match byteLength by quoting the whole URI.
#include <string>

namespace matgeom::gltf {

// Throws std::runtime_error("<path>: <problem>") for JSON that does not parse (with the byte
// where it stops), a number beyond a double, a sampler's wrapS, wrapT, magFilter or minFilter
// outside glTF's enums, a material member of the wrong type (factors, alphaMode, alphaCutoff,
// texture infos), an alphaCutoff that is negative, a data URI of a media type tinygltf does not
// decode (it would look for a file of that name), and a buffer whose base64 data URI does not
// decode to its byteLength. `binary`: the file is a GLB, whose first chunk holds the JSON; a
// container too damaged to hold one is left to tinygltf's checks.
void check_gltf_json(const std::string& path, bool binary);

}  // namespace matgeom::gltf
