#include "io/gltf/gltf_schema.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "matbase/file/file_error.h"

namespace matgeom::gltf {
namespace {

using nlohmann::json;

// What a member holds, in the words of glTF 2.0's JSON schema (its *.schema.json files).
enum class Kind {
  Index,        // a whole number of 0 or more (glTFid and counts)
  Integer,      // any whole number (enums the reader checks against its values)
  Number,
  String,
  Boolean,
  Object,       // any object
  Numbers,      // an array of numbers (`count` of them when count > 0)
  Indices,      // an array of whole numbers of 0 or more
  Strings,      // an array of strings
  Child,        // an object of schema `schema`
  Children,     // an array of objects of schema `schema`
  IndexMap,     // an object whose every value is a whole number of 0 or more (attributes)
  IndexMaps,    // an array of such objects (morph targets)
};

struct Schema;

struct Member {
  const char* name;
  Kind kind;
  bool required = false;
  size_t count = 0;                // Numbers: the length, 0 for any
  const Schema* schema = nullptr;  // Child, Children
  const char* element = nullptr;   // Children: how one element is named ("mesh")
};

struct Schema {
  std::vector<Member> members;
};

// The parts of the glTF 2.0 schema the reader reads or passes through tinygltf. Materials and
// samplers hold more than their types (ranges, enums): json_checks.cpp checks those members.
const Schema kAsset{{{"version", Kind::String, true}, {"minVersion", Kind::String}, {"generator", Kind::String},
                     {"copyright", Kind::String}}};
const Schema kScene{{{"nodes", Kind::Indices}, {"name", Kind::String}}};
const Schema kNode{{{"children", Kind::Indices},
                    {"mesh", Kind::Index},
                    {"camera", Kind::Index},
                    {"skin", Kind::Index},
                    {"matrix", Kind::Numbers, false, 16},
                    {"rotation", Kind::Numbers, false, 4},
                    {"scale", Kind::Numbers, false, 3},
                    {"translation", Kind::Numbers, false, 3},
                    {"weights", Kind::Numbers},
                    {"name", Kind::String}}};
const Schema kPrimitive{{{"attributes", Kind::IndexMap, true},
                         {"indices", Kind::Index},
                         {"material", Kind::Index},
                         {"mode", Kind::Integer},
                         {"targets", Kind::IndexMaps}}};
const Schema kMesh{{{"primitives", Kind::Children, true, 0, &kPrimitive, "primitive"},
                    {"weights", Kind::Numbers},
                    {"name", Kind::String}}};
const Schema kAccessor{{{"bufferView", Kind::Index},
                        {"byteOffset", Kind::Index},
                        {"componentType", Kind::Integer, true},
                        {"normalized", Kind::Boolean},
                        {"count", Kind::Index, true},
                        {"type", Kind::String, true},
                        {"max", Kind::Numbers},
                        {"min", Kind::Numbers},
                        {"sparse", Kind::Object},
                        {"name", Kind::String}}};
const Schema kBufferView{{{"buffer", Kind::Index, true},
                          {"byteOffset", Kind::Index},
                          {"byteLength", Kind::Index, true},
                          {"byteStride", Kind::Index},
                          {"target", Kind::Integer},
                          {"name", Kind::String}}};
const Schema kBuffer{{{"uri", Kind::String}, {"byteLength", Kind::Index, true}, {"name", Kind::String}}};
const Schema kImage{{{"uri", Kind::String}, {"mimeType", Kind::String}, {"bufferView", Kind::Index}, {"name", Kind::String}}};
const Schema kTexture{{{"sampler", Kind::Index}, {"source", Kind::Index}, {"name", Kind::String}}};
const Schema kNamed{{{"name", Kind::String}}};
const Schema kSkin{{{"inverseBindMatrices", Kind::Index}, {"skeleton", Kind::Index}, {"joints", Kind::Indices, true}, {"name", Kind::String}}};
const Schema kAnimation{{{"channels", Kind::Children, true, 0, &kNamed, "channel"},
                         {"samplers", Kind::Children, true, 0, &kNamed, "sampler"},
                         {"name", Kind::String}}};
const Schema kCamera{{{"type", Kind::String, true}, {"name", Kind::String}}};
// The top-level arrays of objects, each with how one element is named in messages.
constexpr Member children(const char* name, const Schema& schema, const char* element) {
  return {name, Kind::Children, false, 0, &schema, element};
}

const Schema kRoot{{{"asset", Kind::Child, true, 0, &kAsset},
                    {"extensionsUsed", Kind::Strings},
                    {"extensionsRequired", Kind::Strings},
                    {"scene", Kind::Index},
                    children("scenes", kScene, "scene"), children("nodes", kNode, "node"),
                    children("meshes", kMesh, "mesh"), children("accessors", kAccessor, "accessor"),
                    children("bufferViews", kBufferView, "bufferView"), children("buffers", kBuffer, "buffer"),
                    children("materials", kNamed, "material"), children("textures", kTexture, "texture"),
                    children("images", kImage, "image"), children("samplers", kNamed, "sampler"),
                    children("skins", kSkin, "skin"), children("animations", kAnimation, "animation"),
                    children("cameras", kCamera, "camera")}};

bool is_index(const json& value) { return value.is_number_unsigned() || (value.is_number_integer() && value.get<int64_t>() >= 0); }

// The kinds of one JSON value: what each takes, and how a refusal says it.
struct ScalarKind {
  Kind kind;
  bool (*accepts)(const json&);
  const char* expected;
};
constexpr std::array<ScalarKind, 5> kScalarKinds = {{
    {Kind::Index, is_index, "a whole number of 0 or more"},
    {Kind::Integer, [](const json& v) { return v.is_number_integer(); }, "a whole number"},
    {Kind::Number, [](const json& v) { return v.is_number(); }, "a number"},
    {Kind::String, [](const json& v) { return v.is_string(); }, "a string"},
    {Kind::Boolean, [](const json& v) { return v.is_boolean(); }, "true or false"},
}};

bool all_of(const json& array, bool (*test)(const json&)) {
  for (const json& item : array)
    if (!test(item)) return false;
  return true;
}

class SchemaChecker {
 public:
  explicit SchemaChecker(const std::string& path) : path_(path) {}

  // `place`: the object's name for messages with a trailing blank ("mesh 0 "), or empty at the root.
  void object(const json& value, const Schema& schema, const std::string& place) const {
    for (const Member& member : schema.members) {
      const auto found = value.find(member.name);
      if (found == value.end()) {
        if (member.required) fail(place + member.name, "is missing (glTF 2.0 requires it)");
        continue;
      }
      check(*found, member, place + member.name);
    }
    extensions(value, place);
  }

 private:
  [[noreturn]] void fail(const std::string& place, const std::string& problem) const {
    matbase::fail(path_, place + ": " + problem);
  }
  [[noreturn]] void fail_value(const std::string& place, const json& value, const std::string& expected) const {
    fail(place, matbase::cut_short(value.dump()) + " is not " + expected);
  }

  // An object's "extensions": an object of objects, whatever the extensions are.
  void extensions(const json& value, const std::string& place) const {
    const auto found = value.find("extensions");
    if (found == value.end()) return;
    if (!found->is_object()) fail_value(place + "extensions", *found, "an object");
    for (const auto& [name, extension] : found->items())
      if (!extension.is_object()) fail_value(place + "extensions." + name, extension, "an object");
  }

  void check(const json& value, const Member& member, const std::string& place) const {
    for (const ScalarKind& scalar : kScalarKinds) {
      if (scalar.kind != member.kind) continue;
      if (!scalar.accepts(value)) fail_value(place, value, scalar.expected);
      return;
    }
    switch (member.kind) {
      case Kind::Object:
        if (!value.is_object()) fail_value(place, value, "an object");
        extensions(value, place + ".");
        return;
      case Kind::Numbers:
        if (!value.is_array() || (member.count > 0 && value.size() != member.count) ||
            !all_of(value, [](const json& item) { return item.is_number(); }))
          fail_value(place, value, member.count > 0 ? matbase::concat("an array of ", member.count, " numbers") : "an array of numbers");
        return;
      case Kind::Indices:
        if (!value.is_array() || !all_of(value, is_index)) fail_value(place, value, "an array of whole numbers of 0 or more");
        return;
      case Kind::Strings:
        if (!value.is_array() || !all_of(value, [](const json& item) { return item.is_string(); }))
          fail_value(place, value, "an array of strings");
        return;
      case Kind::Child:
        if (!value.is_object()) fail_value(place, value, "an object");
        object(value, *member.schema, place + ".");
        return;
      case Kind::Children:
        if (!value.is_array()) fail_value(place, value, "an array of objects");
        for (size_t i = 0; i < value.size(); ++i) {
          const std::string element = place.substr(0, place.rfind(' ') + 1) + matbase::concat(member.element, " ", i);
          if (!value[i].is_object()) fail_value(element, value[i], "an object");
          object(value[i], *member.schema, element + " ");
        }
        return;
      case Kind::IndexMap:
        index_map(value, place);
        return;
      case Kind::IndexMaps:
        if (!value.is_array()) fail_value(place, value, "an array of objects");
        for (size_t i = 0; i < value.size(); ++i) index_map(value[i], matbase::concat(place, "[", i, "]"));
        return;
      default:  // the scalar kinds, checked above
        return;
    }
  }

  void index_map(const json& value, const std::string& place) const {
    if (!value.is_object()) fail_value(place, value, "an object");
    for (const auto& [name, index] : value.items())
      if (!is_index(index)) fail_value(place + "." + name, index, "a whole number of 0 or more");
  }

  const std::string& path_;
};

}  // namespace

void check_gltf_schema(const std::string& path, const json& document) { SchemaChecker(path).object(document, kRoot, ""); }

}  // namespace matgeom::gltf
