#pragma once
// The glTF 2.0 schema's types, checked before tinygltf reads the file: tinygltf 2.7 skips a
// member of the wrong type without a word ("primitives" given as an object reads as a mesh without
// primitives, an extension that is not an object as no extension, "scene": "0" as no scene), so the
// checks that follow it would never see what the file says.
#include <string>

#include <nlohmann/json.hpp>

namespace matgeom::gltf {

// Throws std::runtime_error("<path>: <place>: <problem>") for the first member, in document order of
// the schema's table, whose type is not the one glTF 2.0's JSON schema states (an array of objects,
// a whole number of 0 or more, an array of N numbers...), and for a required member that is
// missing. Every object's "extensions" must be an object of objects. Places are named as the rest of
// the reader names them: "mesh 0 primitives", "node 3 matrix", "accessor 2 count".
void check_gltf_schema(const std::string& path, const nlohmann::json& document);

}  // namespace matgeom::gltf
