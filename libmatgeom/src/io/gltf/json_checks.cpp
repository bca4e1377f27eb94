#include "io/gltf/json_checks.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "matbase/file/file_error.h"
#include "matbase/file/input_file.h"
#include "io/gltf/extensions.h"
#include "io/gltf/gltf_container.h"
#include "io/gltf/gltf_schema.h"

namespace matgeom::gltf {
namespace {

using nlohmann::json;

// The bytes tinygltf's base64 decoder makes of a data URI's payload: it stops at the first '=' or
// character outside the alphabet.
size_t decoded_base64_size(std::string_view payload) {
  const auto in_alphabet = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
  };
  size_t characters = 0;
  while (characters < payload.size() && in_alphabet(payload[characters])) ++characters;
  return characters / 4 * 3 + (characters % 4 == 0 ? 0 : characters % 4 - 1);
}

// glTF 2.0's sampler enums (spec section 5.26) by the names the spec gives them.
using NamedValue = std::pair<int, const char*>;
constexpr std::array<NamedValue, 3> kWrapModes = {{{33071, "CLAMP_TO_EDGE"}, {33648, "MIRRORED_REPEAT"}, {10497, "REPEAT"}}};
constexpr std::array<NamedValue, 2> kMagFilters = {{{9728, "NEAREST"}, {9729, "LINEAR"}}};
constexpr std::array<NamedValue, 6> kMinFilters = {{{9728, "NEAREST"},
                                                    {9729, "LINEAR"},
                                                    {9984, "NEAREST_MIPMAP_NEAREST"},
                                                    {9985, "LINEAR_MIPMAP_NEAREST"},
                                                    {9986, "NEAREST_MIPMAP_LINEAR"},
                                                    {9987, "LINEAR_MIPMAP_LINEAR"}}};

// Messages name a member by its element and path: "material 2 pbrMetallicRoughness.metallicFactor".
// `prefix` is the element's name and a blank, or an object's path and a dot.
std::string member_name(const std::string& prefix, const char* member) { return prefix + member; }
std::string element_name(const std::string& prefix) { return prefix.substr(0, prefix.size() - 1); }

class JsonChecker {
 public:
  explicit JsonChecker(const std::string& path) : path_(path) {}

  [[noreturn]] void fail_at(const std::string& name, const std::string& problem) const {
    matbase::fail(path_, name + ": " + problem);
  }

  // The member's value for a message: as the JSON writes it, cut short.
  static std::string shown(const json& value) { return matbase::cut_short(value.dump()); }

  void number(const json& object, const char* member, const std::string& where) const {
    const auto found = object.find(member);
    if (found != object.end() && !found->is_number()) fail_at(member_name(where, member), shown(*found) + " is not a number");
  }

  void numbers(const json& object, const char* member, size_t count, const std::string& where) const {
    const auto found = object.find(member);
    if (found == object.end()) return;
    bool valid = found->is_array() && found->size() == count;
    for (size_t i = 0; valid && i < count; ++i) valid = (*found)[i].is_number();
    if (!valid) fail_at(member_name(where, member), matbase::concat(shown(*found), " is not an array of ", count, " numbers"));
  }

  void non_negative_integer(const json& object, const char* member, const std::string& where) const {
    const auto found = object.find(member);
    if (found == object.end()) return;
    if (!found->is_number_integer() || found->get<int64_t>() < 0)
      fail_at(member_name(where, member), shown(*found) + " is not a whole number of 0 or more");
  }

  void of_type(const json& object, const char* member, json::value_t type, const char* what,
               const std::string& where) const {
    const auto found = object.find(member);
    if (found != object.end() && found->type() != type) fail_at(member_name(where, member), shown(*found) + " is not " + what);
  }

  // A textureInfo (or normalTextureInfo, occlusionTextureInfo): an object with an index, and
  // the scale or strength `factor` names.
  void texture_info(const json& object, const char* member, const char* factor, const std::string& where) const {
    const auto found = object.find(member);
    if (found == object.end()) return;
    const std::string inner = member_name(where, member) + ".";
    if (!found->is_object() || !found->contains("index")) fail_at(member_name(where, member), "is not an object with an index");
    non_negative_integer(*found, "index", inner);
    non_negative_integer(*found, "texCoord", inner);
    if (factor) number(*found, factor, inner);
  }

  template <size_t N>
  void enum_value(const json& object, const char* member, const std::array<NamedValue, N>& values,
                  const std::string& where) const {
    const auto found = object.find(member);
    if (found == object.end()) return;
    for (const auto& [value, name] : values)
      if (found->is_number_integer() && found->get<int64_t>() == value) return;
    std::string allowed;
    for (const auto& [value, name] : values) allowed += matbase::concat(allowed.empty() ? "" : ", ", value, " (", name, ")");
    fail_at(member_name(where, member), shown(*found) + " is not one of glTF's values: " + allowed);
  }

  void material(const json& material, const std::string& where) const {
    if (!material.is_object()) fail_at(element_name(where), "is not an object");
    if (const auto pbr = material.find("pbrMetallicRoughness"); pbr != material.end()) {
      const std::string inner = member_name(where, "pbrMetallicRoughness.");
      if (!pbr->is_object()) fail_at(member_name(where, "pbrMetallicRoughness"), "is not an object");
      numbers(*pbr, "baseColorFactor", 4, inner);
      number(*pbr, "metallicFactor", inner);
      number(*pbr, "roughnessFactor", inner);
      texture_info(*pbr, "baseColorTexture", nullptr, inner);
      texture_info(*pbr, "metallicRoughnessTexture", nullptr, inner);
    }
    texture_info(material, "normalTexture", "scale", where);
    texture_info(material, "occlusionTexture", "strength", where);
    texture_info(material, "emissiveTexture", nullptr, where);
    numbers(material, "emissiveFactor", 3, where);
    of_type(material, "alphaMode", json::value_t::string, "a string", where);
    of_type(material, "doubleSided", json::value_t::boolean, "true or false", where);
    number(material, "alphaCutoff", where);
    // The spec's minimum; Cycles ignores the cutoff (convert_material in gltf_reader.cpp).
    if (const auto cutoff = material.find("alphaCutoff"); cutoff != material.end() && cutoff->get<double>() < 0.0)
      fail_at(member_name(where, "alphaCutoff"), shown(*cutoff) + " is negative (glTF's alphaCutoff is 0 or more)");
  }

  // A data URI `uri` member, if any, of a media type tinygltf decodes: of any other it would take
  // the whole URI for a file name.
  std::optional<std::string_view> data_uri(const json& object, std::initializer_list<std::string_view> media_types,
                                           const std::string& where) const {
    const auto uri = object.find("uri");
    if (uri == object.end() || !uri->is_string() || uri->get_ref<const std::string&>().rfind("data:", 0) != 0)
      return std::nullopt;
    const std::string_view text = uri->get_ref<const std::string&>();
    const std::string_view header = text.substr(0, text.find(',') + 1);
    for (const std::string_view type : media_types)
      if (header == matbase::concat("data:", type, ";base64,")) return text;
    std::string readable;
    for (const std::string_view type : media_types) readable += matbase::concat(readable.empty() ? "" : ", ", type);
    fail_at(member_name(where, "uri"), matbase::concat("a data URI starting ", matbase::excerpt(header.empty() ? text : header),
                                              "; the data URIs read are base64 of ", readable));
  }

  void image(const json& image, const std::string& where) const {
    if (!image.is_object()) fail_at(element_name(where), "is not an object");
    data_uri(image, {"image/png", "image/jpeg", "image/bmp", "image/gif"}, where);
  }

  void buffer(const json& buffer, const std::string& where) const {
    if (!buffer.is_object()) fail_at(element_name(where), "is not an object");
    const std::optional<std::string_view> text =
        data_uri(buffer, {"application/octet-stream", "application/gltf-buffer"}, where);
    const auto length = buffer.find("byteLength");
    if (!text || length == buffer.end() || !length->is_number_unsigned()) return;
    const size_t comma = text->find(',');
    const size_t decoded = decoded_base64_size(text->substr(comma + 1));
    if (decoded != length->get<uint64_t>()) {
      fail_at(element_name(where), matbase::concat("byteLength ", length->get<uint64_t>(), ", but its data URI (",
                                          matbase::excerpt(text->substr(0, comma + 1)), " and ", text->size() - comma - 1,
                                          " characters) decodes to ", decoded, " bytes"));
    }
  }

  // Every element of the top-level array `member`, with its name for messages ("materials[2].").
  template <typename Check>
  void each(const json& doc, const char* member, const char* singular, Check check) const {
    const auto found = doc.find(member);
    if (found == doc.end() || !found->is_array()) return;
    for (size_t i = 0; i < found->size(); ++i) check((*found)[i], matbase::concat(singular, " ", i, " "));
  }

 private:
  const std::string& path_;
};

// The document, or the problem in our words: nlohmann's own texts name its internals.
json parsed_json(const std::string& path, std::string_view text) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& error) {
    matbase::fail(path, matbase::concat("not valid JSON (at byte ", error.byte, ")"));
  } catch (const json::out_of_range& error) {
    // "number overflow parsing '1e999'": the number as written is between the quotes.
    const std::string_view what = error.what();
    const size_t open = what.find('\''), close = what.rfind('\'');
    const std::string_view number =
        open < close && close != std::string_view::npos ? what.substr(open + 1, close - open - 1) : what;
    matbase::fail(path, "the JSON holds the number " + matbase::excerpt(number) + ", beyond the range of a double");
  }
}

// asset.version (and minVersion) as "<major>.<minor>": glTF 1.0 files, which tinygltf reads as a
// glTF without meshes, are refused as what they are, those without an "asset" (the earliest
// exporters wrote none) too.
void check_version(const std::string& path, const json& doc) {
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) {
    const bool gltf_1 = doc.contains("meshes") && doc["meshes"].is_object();  // glTF 1.0 kept its lists in objects
    matbase::fail(path, std::string("no \"asset\" object with a \"version\"") +
                            (gltf_1 ? ": a glTF 1.0 file (its meshes are an object); only glTF 2.0 is read" : "; glTF 2.0 requires one"));
  }
  for (const char* member : {"version", "minVersion"}) {
    const auto found = asset->find(member);
    if (found == asset->end() || !found->is_string()) continue;
    const std::string& version = found->get_ref<const std::string&>();
    const size_t dot = version.find('.');
    const std::string major = version.substr(0, dot);
    if (major != "2" || dot == std::string::npos)
      matbase::fail(path, matbase::concat("asset.", member, " ", matbase::excerpt(version),
                                          major == "1" ? ": a glTF 1.0 file" : ": not glTF 2.x", "; only glTF 2.0 is read"));
  }
}

// extensionsRequired names only extensions the reader applies (extensions.h).
void check_required_extensions(const std::string& path, const json& doc) {
  const auto required = doc.find("extensionsRequired");
  if (required == doc.end()) return;
  for (const json& extension : *required) {
    const std::string& name = extension.get_ref<const std::string&>();
    if (std::find(kReadExtensions.begin(), kReadExtensions.end(), name) != kReadExtensions.end()) continue;
    const char* what = name == "KHR_draco_mesh_compression"       ? " (Draco-compressed geometry)"
                       : name == "EXT_meshopt_compression"        ? " (meshopt-compressed geometry)"
                       : name == "KHR_texture_basisu"             ? " (KTX2 textures)"
                       : name == "EXT_texture_webp"               ? " (WebP textures)"
                       : "";
    matbase::fail(path, "extensionsRequired: the file requires the glTF extension " + matbase::excerpt(name) + what +
                            ", which is not supported; decompress or convert it first");
  }
}

}  // namespace

void check_gltf_json(const std::string& path, bool binary) {
  std::string file;
  if (const std::optional<std::string> problem = matbase::read_whole_file(path, file)) matbase::fail(path, *problem);
  const json doc = parsed_json(path, gltf_json_text(path, file, binary));
  if (!doc.is_object()) matbase::fail(path, "the JSON is not an object");
  check_version(path, doc);
  check_gltf_schema(path, doc);
  check_required_extensions(path, doc);
  const JsonChecker checker(path);
  checker.each(doc, "samplers", "sampler", [&](const json& sampler, const std::string& where) {
    if (!sampler.is_object()) checker.fail_at(element_name(where), "is not an object");
    checker.enum_value(sampler, "wrapS", kWrapModes, where);
    checker.enum_value(sampler, "wrapT", kWrapModes, where);
    checker.enum_value(sampler, "magFilter", kMagFilters, where);
    checker.enum_value(sampler, "minFilter", kMinFilters, where);
  });
  checker.each(doc, "materials", "material",
               [&](const json& material, const std::string& where) { checker.material(material, where); });
  checker.each(doc, "images", "image",
               [&](const json& image, const std::string& where) { checker.image(image, where); });
  checker.each(doc, "buffers", "buffer",
               [&](const json& buffer, const std::string& where) { checker.buffer(buffer, where); });
}

}  // namespace matgeom::gltf
