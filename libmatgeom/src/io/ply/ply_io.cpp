#include "matgeom/io/ply/ply_io.h"


#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matbase/file/file_error.h"
#include "matbase/file/input_file.h"
#include "matbase/image/srgb.h"
#include "matbase/text_encoding.h"
#include "matgeom/shading_normals.h"

// Reading a PLY file is three steps: the whole file is loaded and its header parsed into element
// and property declarations, which are checked against the file size before anything is
// allocated for them; the body is read item by item (ASCII tokens, or binary values in either
// byte order), keeping elements "vertex" and "face" and reading every other element and property
// only to find where the next one starts; the faces' id property becomes the parts.

namespace matgeom {
namespace {

std::string load_file(const std::string& path) {
  if (const std::optional<std::string> problem = matbase::input_file_problem(path)) matbase::fail(path, *problem);
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) matbase::fail(path, "cannot open the file (" + error.message() + ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) matbase::fail(path, "cannot open the file");
  std::string bytes(static_cast<size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<uintmax_t>(in.gcount()) != size) matbase::fail(path, "cannot read the whole file");
  return bytes;
}

// ---------------------------------------------------------------------------------------------
// Types

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

// Both spellings the PLY world uses: Bourke's original names and the sized ones.
std::optional<PlyType> parse_type(std::string_view name) {
  static const std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::Uint8},
      {"uint8", PlyType::Uint8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::Uint16},  {"uint16", PlyType::Uint16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},    {"uint", PlyType::Uint32},     {"uint32", PlyType::Uint32},
      {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [spelling, type] : kNames) {
    if (name == spelling) return type;
  }
  return std::nullopt;
}

struct TypeTraits {
  const char* name;
  size_t size;
  int64_t lowest;  // integer types only: the range, which fits in an int64_t for every one
  int64_t highest;
};

const TypeTraits& traits(PlyType type) {
  // In the order of PlyType.
  static const TypeTraits kTraits[] = {{"char", 1, INT8_MIN, INT8_MAX},
                                       {"uchar", 1, 0, UINT8_MAX},
                                       {"short", 2, INT16_MIN, INT16_MAX},
                                       {"ushort", 2, 0, UINT16_MAX},
                                       {"int", 4, INT32_MIN, INT32_MAX},
                                       {"uint", 4, 0, UINT32_MAX},
                                       {"float", 4, 0, 0},
                                       {"double", 8, 0, 0}};
  return kTraits[static_cast<size_t>(type)];
}

size_t type_size(PlyType type) { return traits(type).size; }

bool is_integer(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

// ---------------------------------------------------------------------------------------------
// Header

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::Uint8;    // lists only: the type of the item count
  PlyType value_type = PlyType::Float32;  // the scalar's type, or the type of a list's items
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::vector<std::string> part_table;  // write_ply's part names by id; empty without them
  size_t body_offset = 0;               // the first byte after the end_header line
};

// The next line from `offset` without its line break (LF or CRLF); false when no complete line
// is left.
bool take_line(std::string_view file, size_t& offset, std::string_view& line) {
  const size_t end = file.find('\n', offset);
  if (end == std::string_view::npos) return false;
  line = file.substr(offset, end - offset);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  offset = end + 1;
  return true;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  size_t start = 0;
  while (true) {
    start = line.find_first_not_of(" \t", start);
    if (start == std::string_view::npos) return words;
    const size_t end = std::min(line.find_first_of(" \t", start), line.size());
    words.push_back(line.substr(start, end - start));
    start = end;
  }
}

PlyFormat parse_format(const std::string& path, std::string_view line,
                       const std::vector<std::string_view>& words) {
  if (words.size() != 3) matbase::fail(path, "bad format line " + matbase::excerpt(line));
  if (words[2] != "1.0") matbase::fail(path, "unsupported format line " + matbase::excerpt(line) + " (not 1.0)");
  if (words[1] == "ascii") return PlyFormat::Ascii;
  if (words[1] == "binary_little_endian") return PlyFormat::BinaryLittleEndian;
  if (words[1] == "binary_big_endian") return PlyFormat::BinaryBigEndian;
  matbase::fail(path, "unsupported format line " + matbase::excerpt(line));
}

PlyElement parse_element(const std::string& path, std::string_view line,
                         const std::vector<std::string_view>& words,
                         const std::vector<PlyElement>& elements) {
  PlyElement element;
  if (words.size() != 3) matbase::fail(path, "bad element line " + matbase::excerpt(line));
  element.name = std::string(words[1]);
  const std::string_view count = words[2];
  const auto [end, error] =
      std::from_chars(count.data(), count.data() + count.size(), element.count);
  if (error != std::errc() || end != count.data() + count.size()) {
    matbase::fail(path, "bad element count in " + matbase::excerpt(line));
  }
  for (const PlyElement& other : elements) {
    if (other.name == element.name) {
      matbase::fail(path, "element " + matbase::excerpt(element.name) + " declared twice");
    }
  }
  return element;
}

PlyType parse_property_type(const std::string& path, std::string_view name) {
  const std::optional<PlyType> type = parse_type(name);
  if (!type) matbase::fail(path, "unsupported property type " + matbase::excerpt(name));
  return *type;
}

PlyProperty parse_property(const std::string& path, std::string_view line,
                           const std::vector<std::string_view>& words, const PlyElement& element) {
  PlyProperty property;
  if (words.size() == 3) {
    property.value_type = parse_property_type(path, words[1]);
    property.name = std::string(words[2]);
  } else if (words.size() == 5 && words[1] == "list") {
    property.is_list = true;
    property.count_type = parse_property_type(path, words[2]);
    property.value_type = parse_property_type(path, words[3]);
    property.name = std::string(words[4]);
    if (!is_integer(property.count_type)) {
      matbase::fail(path, "unsupported property type: list count type " + matbase::excerpt(words[2]) +
                     " is not an integer type");
    }
  } else {
    matbase::fail(path, "bad property line " + matbase::excerpt(line));
  }
  for (const PlyProperty& other : element.properties) {
    if (other.name == property.name) {
      matbase::fail(path, "property " + matbase::excerpt(property.name) + " of element " + element.name +
                     " declared twice");
    }
  }
  return property;
}

// write_ply's "comment part <k> <name>" (the name is the rest of the line, spaces included);
// any other comment, including one that merely starts with "part", is ignored.
void parse_comment(const std::string& path, std::string_view line,
                   std::map<uint64_t, std::string>& part_names) {
  constexpr std::string_view kPrefix = "comment part ";
  if (line.substr(0, kPrefix.size()) != kPrefix) return;
  const std::string_view rest = line.substr(kPrefix.size());
  const char* const stop = rest.data() + rest.size();
  uint64_t part = 0;
  const auto [end, error] = std::from_chars(rest.data(), stop, part);
  if (error != std::errc() || (end != stop && *end != ' ')) return;
  const std::string name = end == stop ? std::string() : std::string(end + 1, stop);
  if (!part_names.emplace(part, name).second) matbase::fail(path, matbase::concat("two comments name part ", part));
}

// The part table must name parts 0..K-1, so that part ids index it.
std::vector<std::string> make_part_table(const std::string& path,
                                         std::map<uint64_t, std::string> part_names) {
  std::vector<std::string> table;
  for (auto& [part, name] : part_names) {
    if (part != table.size()) matbase::fail(path, matbase::concat("the part comments skip part ", table.size()));
    table.push_back(std::move(name));
  }
  return table;
}

// The fewest bytes one item of the element can take: binary, the size of every scalar and list
// count (lists may be empty); ASCII, one character per value.
uint64_t minimum_item_bytes(const PlyElement& element, PlyFormat format) {
  uint64_t bytes = 0;
  for (const PlyProperty& property : element.properties) {
    if (format == PlyFormat::Ascii) {
      bytes += 1;
    } else {
      bytes += type_size(property.is_list ? property.count_type : property.value_type);
    }
  }
  return bytes;
}

// Rejects element counts the file cannot hold before anything is allocated for them, so that a
// corrupt count cannot ask for gigabytes.
void check_element_counts(const std::string& path, const PlyHeader& header, size_t body_size) {
  uint64_t remaining = body_size;
  for (const PlyElement& element : header.elements) {
    const uint64_t item_bytes = minimum_item_bytes(element, header.format);
    if (item_bytes == 0) continue;
    if (element.count > remaining / item_bytes) {
      matbase::fail(path, matbase::concat("element ", element.name, " declares ", element.count, " items but the ",
                        body_size, " bytes after the header cannot hold them"));
    }
    remaining -= element.count * item_bytes;
  }
}

PlyHeader parse_header(const std::string& path, std::string_view file) {
  // A header saved by a Windows editor may start with a byte-order mark: UTF-8's is passed over,
  // UTF-16's or UTF-32's named (a PLY header is ASCII, and the body may be binary).
  size_t offset = 0;
  if (const std::optional<std::string> mark = matbase::byte_order_mark(file)) {
    if (*mark != "UTF-8")
      matbase::fail(path, "the header is " + *mark + " text (it starts with a byte-order mark); a PLY header is ASCII");
    offset = 3;
  }
  std::string_view line;
  if (!take_line(file, offset, line) || line != "ply") {
    matbase::fail(path, "not a PLY file (it does not start with a \"ply\" line)");
  }
  PlyHeader header;
  bool has_format = false;
  std::map<uint64_t, std::string> part_names;
  while (true) {
    if (!take_line(file, offset, line)) matbase::fail(path, "truncated header (no end_header line)");
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "end_header") break;
    if (keyword == "comment") {
      parse_comment(path, line, part_names);
    } else if (keyword == "obj_info") {
      // Free text about the object, like a comment.
    } else if (keyword == "format") {
      if (has_format) matbase::fail(path, "two format lines");
      header.format = parse_format(path, line, words);
      has_format = true;
    } else if (keyword == "element") {
      header.elements.push_back(parse_element(path, line, words, header.elements));
    } else if (keyword == "property") {
      if (header.elements.empty()) matbase::fail(path, "property line before any element line");
      PlyElement& element = header.elements.back();
      element.properties.push_back(parse_property(path, line, words, element));
    } else {
      matbase::fail(path, "unexpected header line " + matbase::excerpt(line));
    }
  }
  if (!has_format) matbase::fail(path, "no format line in the header");
  header.part_table = make_part_table(path, std::move(part_names));
  header.body_offset = offset;
  check_element_counts(path, header, file.size() - offset);
  return header;
}

// ---------------------------------------------------------------------------------------------
// Body

// The unsigned integer stored in `size` bytes in the file's byte order. Assembling it byte by
// byte reads unaligned data safely and works whatever the host's own byte order.
uint64_t load_unsigned(const unsigned char* bytes, size_t size, bool big_endian) {
  uint64_t value = 0;
  for (size_t i = 0; i < size; ++i) {
    const size_t significance = big_endian ? size - 1 - i : i;
    value |= static_cast<uint64_t>(bytes[i]) << (8 * significance);
  }
  return value;
}

// Two's complement `bits` wide.
int64_t sign_extend(uint64_t value, int bits) {
  const uint64_t sign = uint64_t{1} << (bits - 1);
  const int64_t magnitude = static_cast<int64_t>(value & (sign - 1));
  return (value & sign) != 0 ? magnitude - static_cast<int64_t>(sign) : magnitude;
}

// One binary value as a double, which holds every PLY integer exactly.
double decode_binary(const unsigned char* bytes, PlyType type, bool big_endian) {
  const uint64_t value = load_unsigned(bytes, type_size(type), big_endian);
  switch (type) {
    case PlyType::Int8:
      return static_cast<double>(sign_extend(value, 8));
    case PlyType::Int16:
      return static_cast<double>(sign_extend(value, 16));
    case PlyType::Int32:
      return static_cast<double>(sign_extend(value, 32));
    case PlyType::Uint8:
    case PlyType::Uint16:
    case PlyType::Uint32:
      return static_cast<double>(value);
    case PlyType::Float32: {
      const uint32_t bits = static_cast<uint32_t>(value);
      float number = 0.0f;
      std::memcpy(&number, &bits, sizeof(number));
      return number;
    }
    case PlyType::Float64: {
      double number = 0.0;
      std::memcpy(&number, &value, sizeof(number));
      return number;
    }
  }
  return 0.0;
}

// Longer lists are not polygons of any scan; refusing them bounds what one corrupt count costs.
constexpr uint64_t kMaxListLength = 1000000;

// Reads the body's values one at a time, in either encoding, and knows which element item and
// property it is in so that every error says where the file went wrong.
class BodyReader {
 public:
  BodyReader(const std::string& path, std::string_view body, PlyFormat format)
      : path_(path), body_(body), format_(format) {}

  const std::string& path() const { return path_; }

  void locate(const PlyElement& element, uint64_t item, const PlyProperty& property) {
    element_ = &element;
    item_ = item;
    property_ = &property;
  }

  double read_value(PlyType type) {
    return format_ == PlyFormat::Ascii ? read_ascii(type) : read_binary(type);
  }

  // A list's item count, refused when it is implausible or more than the rest of the file holds.
  size_t read_list_length(const PlyProperty& list) {
    const double length = read_value(list.count_type);
    if (length < 0) fail_here(matbase::concat("negative list length ", length));
    if (length > static_cast<double>(kMaxListLength)) {
      fail_here(matbase::concat("list of ", static_cast<uint64_t>(length), " items (more than ",
                       kMaxListLength, ")"));
    }
    const uint64_t items = static_cast<uint64_t>(length);
    const uint64_t item_bytes = format_ == PlyFormat::Ascii ? 1 : type_size(list.value_type);
    if (items > (body_.size() - offset_) / item_bytes) {
      fail_here(matbase::concat("truncated file: a list of ", items, " items runs past the end of file"));
    }
    return static_cast<size_t>(items);
  }

 private:
  [[noreturn]] void fail_here(const std::string& problem) const {
    matbase::fail(path_,
         matbase::concat(problem, " (", element_->name, " ", item_, ", property ", property_->name, ")"));
  }

  double read_binary(PlyType type) {
    const size_t size = type_size(type);
    if (size > body_.size() - offset_) fail_here("truncated file: premature end of file");
    const auto* bytes = reinterpret_cast<const unsigned char*>(body_.data() + offset_);
    offset_ += size;
    return decode_binary(bytes, type, format_ == PlyFormat::BinaryBigEndian);
  }

  std::string_view next_token() {
    constexpr std::string_view kSpace = " \t\r\n\v\f";
    const size_t start = std::min(body_.find_first_not_of(kSpace, offset_), body_.size());
    const size_t end = std::min(body_.find_first_of(kSpace, start), body_.size());
    offset_ = end;
    return body_.substr(start, end - start);
  }

  // std::from_chars: exact, and independent of the C locale (a program that set a German locale
  // would make strtod stop at the '.').
  double read_ascii(PlyType type) {
    const std::string_view token = next_token();
    if (token.empty()) fail_here("truncated file: missing values");
    const char* const first = token.data();
    const char* const last = first + token.size();
    const TypeTraits& range = traits(type);
    // A number as written that the property's type cannot hold is refused with the type's range.
    const auto check = [&](std::from_chars_result result, bool in_range) {
      if (result.ptr != last || (result.ec != std::errc() && result.ec != std::errc::result_out_of_range))
        fail_here(matbase::concat("malformed number ", matbase::excerpt(token), " for a ", range.name));
      if (result.ec == std::errc::result_out_of_range || !in_range) {
        fail_here(is_integer(type) ? matbase::concat("number ", matbase::excerpt(token), " is outside a ", range.name, "'s range [",
                                            range.lowest, ", ", range.highest, "]")
                                   : matbase::concat("number ", matbase::excerpt(token), " is beyond the range of a ", range.name));
      }
    };
    if (type == PlyType::Float32) {
      float value = 0.0f;
      check(std::from_chars(first, last, value), true);
      return value;
    }
    if (type == PlyType::Float64) {
      double value = 0.0;
      check(std::from_chars(first, last, value), true);
      return value;
    }
    int64_t value = 0;
    const std::from_chars_result result = std::from_chars(first, last, value);
    check(result, value >= range.lowest && value <= range.highest);
    return static_cast<double>(value);
  }

  const std::string& path_;
  std::string_view body_;
  size_t offset_ = 0;
  PlyFormat format_;
  const PlyElement* element_ = nullptr;
  uint64_t item_ = 0;
  const PlyProperty* property_ = nullptr;
};

// One item of an element, by property index: scalar values, and the items of list properties.
struct ElementItem {
  std::vector<double> values;
  std::vector<std::vector<double>> lists;

  explicit ElementItem(const PlyElement& element)
      : values(element.properties.size()), lists(element.properties.size()) {}
};

// Reuses `item`'s storage, so reading millions of faces allocates nothing per face.
void read_item(BodyReader& body, const PlyElement& element, uint64_t index, ElementItem& item) {
  for (size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty& property = element.properties[p];
    body.locate(element, index, property);
    if (!property.is_list) {
      item.values[p] = body.read_value(property.value_type);
      continue;
    }
    std::vector<double>& list = item.lists[p];
    list.resize(body.read_list_length(property));
    for (double& value : list) value = body.read_value(property.value_type);
  }
}

void skip_element(BodyReader& body, const PlyElement& element) {
  if (element.properties.empty()) return;  // nothing to read, however large the count
  ElementItem item(element);
  for (uint64_t index = 0; index < element.count; ++index) read_item(body, element, index, item);
}

// ---------------------------------------------------------------------------------------------
// Vertices and faces

std::optional<size_t> find_property(const PlyElement& element, std::string_view name) {
  for (size_t p = 0; p < element.properties.size(); ++p) {
    if (element.properties[p].name == name) return p;
  }
  return std::nullopt;
}

// A property used as a number: absent, or a scalar.
std::optional<size_t> find_scalar(const std::string& path, const PlyElement& element,
                                  std::string_view name) {
  const std::optional<size_t> index = find_property(element, name);
  if (index && element.properties[*index].is_list) {
    matbase::fail(path, matbase::concat("property ", name, " of element ", element.name, " is a list"));
  }
  return index;
}

const PlyElement& require_element(const std::string& path, const PlyHeader& header,
                                  const std::string& name) {
  for (const PlyElement& element : header.elements) {
    if (element.name == name) return element;
  }
  matbase::fail(path, "no " + name + " element");
}

// Property indices of the vertex attributes the mesh keeps.
struct VertexLayout {
  std::array<size_t, 3> position{};
  std::optional<std::array<size_t, 3>> normal;
  std::optional<std::array<size_t, 2>> uv;
  std::optional<std::array<size_t, 3>> color;
  // What a colour value is divided by to make it 0..1: the integer type's largest value, or 1.
  std::array<double, 3> color_scale{1.0, 1.0, 1.0};
};

VertexLayout make_vertex_layout(const std::string& path, const PlyElement& vertex) {
  VertexLayout layout;
  const std::array<const char*, 3> position_names = {"x", "y", "z"};
  for (size_t axis = 0; axis < 3; ++axis) {
    const std::optional<size_t> index = find_scalar(path, vertex, position_names[axis]);
    if (!index) matbase::fail(path, matbase::concat("element vertex has no property ", position_names[axis]));
    layout.position[axis] = *index;
  }

  const std::optional<size_t> nx = find_scalar(path, vertex, "nx");
  const std::optional<size_t> ny = find_scalar(path, vertex, "ny");
  const std::optional<size_t> nz = find_scalar(path, vertex, "nz");
  if (nx && ny && nz) {
    layout.normal = std::array<size_t, 3>{*nx, *ny, *nz};
  } else if (nx || ny || nz) {
    matbase::fail(path, "element vertex has some but not all of nx, ny, nz");
  }

  // The names texture coordinates go by in the wild, most common first.
  const std::array<std::pair<const char*, const char*>, 4> uv_names = {
      {{"s", "t"}, {"u", "v"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}}};
  for (const auto& [u_name, v_name] : uv_names) {
    const std::optional<size_t> u = find_scalar(path, vertex, u_name);
    const std::optional<size_t> v = find_scalar(path, vertex, v_name);
    if (u && v) {
      layout.uv = std::array<size_t, 2>{*u, *v};
      break;
    }
  }

  // Colours as scanners write them: "red green blue" (Replica, MeshLab), or "diffuse_" before each.
  for (const char* prefix : {"", "diffuse_"}) {
    std::array<std::optional<size_t>, 3> channels;
    const std::array<const char*, 3> names = {"red", "green", "blue"};
    for (size_t c = 0; c < 3; ++c) channels[c] = find_scalar(path, vertex, std::string(prefix) + names[c]);
    if (!channels[0] || !channels[1] || !channels[2]) continue;
    layout.color = std::array<size_t, 3>{*channels[0], *channels[1], *channels[2]};
    for (size_t c = 0; c < 3; ++c) {
      const PlyType type = vertex.properties[*channels[c]].value_type;
      layout.color_scale[c] = is_integer(type) ? static_cast<double>(traits(type).highest) : 1.0;
    }
    break;
  }
  return layout;
}

// Face properties the mesh keeps: the corner list and the optional id that gives the part.
struct FaceLayout {
  size_t corners = 0;
  std::optional<size_t> id;
  std::string id_name;
};

FaceLayout make_face_layout(const std::string& path, const PlyElement& face,
                            const PlyReadOptions& options) {
  FaceLayout layout;
  std::optional<size_t> corners = find_property(face, "vertex_indices");
  if (!corners) corners = find_property(face, "vertex_index");
  if (!corners) matbase::fail(path, "element face has no property vertex_indices or vertex_index");
  const PlyProperty& list = face.properties[*corners];
  if (!list.is_list || !is_integer(list.value_type)) {
    matbase::fail(path, "face property " + list.name + " must be a list of integers");
  }
  layout.corners = *corners;

  if (!options.face_id_property.empty()) {
    layout.id = find_property(face, options.face_id_property);
    if (!layout.id) matbase::fail(path, "element face has no property " + options.face_id_property);
  } else {
    for (const char* candidate : {"part_id", "object_id", "instance_id", "segment_id"}) {
      layout.id = find_property(face, candidate);
      if (layout.id) break;
    }
  }
  if (layout.id) {
    const PlyProperty& id = face.properties[*layout.id];
    if (id.is_list || !is_integer(id.value_type)) {
      matbase::fail(path, "face property " + id.name + " must be an integer scalar to give parts");
    }
    layout.id_name = id.name;
  }
  return layout;
}

// A vertex attribute value as a float; values beyond the float range are refused here, where
// converting them would be undefined behaviour.
float vertex_float(const std::string& path, double value, uint64_t vertex, const char* attribute) {
  if (!std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max()) {
    matbase::fail(path, matbase::concat("non-finite vertex ", vertex, " (", attribute, " ", value, ")"));
  }
  return static_cast<float>(value);
}

void read_vertices(BodyReader& body, const PlyElement& element, const VertexLayout& layout,
                   TriangleMesh& mesh) {
  const std::string& path = body.path();
  mesh.positions.reserve(static_cast<size_t>(element.count));
  if (layout.normal) mesh.normals.reserve(static_cast<size_t>(element.count));
  if (layout.uv) mesh.uvs.reserve(static_cast<size_t>(element.count));
  if (layout.color) mesh.colors.reserve(static_cast<size_t>(element.count));
  ElementItem item(element);
  for (uint64_t v = 0; v < element.count; ++v) {
    read_item(body, element, v, item);
    glm::vec3 position;
    for (int axis = 0; axis < 3; ++axis) {
      position[axis] = vertex_float(path, item.values[layout.position[axis]], v, "position");
    }
    mesh.positions.push_back(position);
    if (layout.normal) {
      glm::vec3 normal;
      for (int axis = 0; axis < 3; ++axis) {
        normal[axis] = vertex_float(path, item.values[(*layout.normal)[axis]], v, "normal");
      }
      mesh.normals.push_back(normal);
    }
    if (layout.uv) {
      mesh.uvs.emplace_back(vertex_float(path, item.values[(*layout.uv)[0]], v, "uv"),
                            vertex_float(path, item.values[(*layout.uv)[1]], v, "uv"));
    }
    if (layout.color) {
      // sRGB-encoded 0..1 (an integer over its type's largest value), as Blender's importer reads
      // them into a byte colour attribute; kept linear.
      glm::vec3 color;
      for (size_t c = 0; c < 3; ++c) {
        const double encoded = item.values[(*layout.color)[c]] / layout.color_scale[c];
        if (!std::isfinite(encoded)) matbase::fail(path, matbase::concat("non-finite vertex ", v, " (colour)"));
        color[static_cast<int>(c)] = matbase::srgb_to_linear(static_cast<float>(std::clamp(encoded, 0.0, 1.0)));
      }
      mesh.colors.push_back(color);
    }
  }
}

// Triangles of every face (polygons fan-triangulated around their first corner) and, with an id
// property, the id of each triangle's face.
void read_faces(BodyReader& body, const PlyElement& element, const FaceLayout& layout,
                uint64_t vertex_count, TriangleMesh& mesh, std::vector<int64_t>& triangle_ids) {
  const std::string& path = body.path();
  mesh.triangles.reserve(static_cast<size_t>(element.count));
  ElementItem item(element);
  std::vector<uint32_t> corners;
  for (uint64_t f = 0; f < element.count; ++f) {
    read_item(body, element, f, item);
    const std::vector<double>& indices = item.lists[layout.corners];
    if (indices.size() < 3) {
      matbase::fail(path, matbase::concat("face ", f, " has ", indices.size(), " vertices (a face needs 3 or more)"));
    }
    corners.clear();
    for (const double index : indices) {
      if (index < 0 || index >= static_cast<double>(vertex_count)) {
        matbase::fail(path, matbase::concat("face ", f, ": vertex index ", static_cast<int64_t>(index),
                          " out of range (the file has ", vertex_count, " vertices)"));
      }
      corners.push_back(static_cast<uint32_t>(index));
    }
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      mesh.triangles.emplace_back(corners[0], corners[k], corners[k + 1]);
      if (layout.id) triangle_ids.push_back(static_cast<int64_t>(item.values[*layout.id]));
    }
  }
}

// Parts found by id are named stem_id: "object_id" 7 is "object_7", since "object_id_7" would
// say "id" twice; other properties keep their whole name.
std::string part_name_stem(const std::string& id_property) {
  constexpr std::string_view kIdSuffix = "_id";
  const std::string_view name = id_property;
  if (name.size() > kIdSuffix.size() && name.substr(name.size() - kIdSuffix.size()) == kIdSuffix) {
    return std::string(name.substr(0, name.size() - kIdSuffix.size()));
  }
  return id_property;
}

// Parts from the faces' ids: indices into write_ply's part table when the header has one,
// otherwise the distinct ids in increasing order, named after the property and the id.
void assign_parts(const std::string& path, const std::vector<std::string>& part_table,
                  const FaceLayout& layout, const std::vector<int64_t>& triangle_ids,
                  TriangleMesh& mesh) {
  if (!layout.id) {
    mesh.part_names = {"default"};
    return;
  }
  mesh.triangle_parts.reserve(triangle_ids.size());
  if (!part_table.empty()) {
    for (const int64_t id : triangle_ids) {
      if (id < 0 || static_cast<uint64_t>(id) >= part_table.size()) {
        matbase::fail(path, matbase::concat(layout.id_name, " ", id, " is outside the part table (",
                          part_table.size(), " parts named in the comments)"));
      }
      mesh.triangle_parts.push_back(static_cast<uint32_t>(id));
    }
    mesh.part_names = part_table;
    return;
  }
  const std::string stem = part_name_stem(layout.id_name);
  std::vector<int64_t> distinct_ids = triangle_ids;
  std::sort(distinct_ids.begin(), distinct_ids.end());
  distinct_ids.erase(std::unique(distinct_ids.begin(), distinct_ids.end()), distinct_ids.end());
  for (const int64_t id : triangle_ids) {
    const auto found = std::lower_bound(distinct_ids.begin(), distinct_ids.end(), id);
    mesh.triangle_parts.push_back(static_cast<uint32_t>(found - distinct_ids.begin()));
  }
  for (const int64_t id : distinct_ids) mesh.part_names.push_back(matbase::concat(stem, "_", id));
}

// ---------------------------------------------------------------------------------------------
// Writing

// One name per part the mesh has, each for one header comment line.
std::vector<std::string> part_names_to_write(const TriangleMesh& mesh, const std::string& path) {
  std::vector<std::string> names;
  for (uint32_t part = 0; part < mesh.part_count(); ++part) {
    // Parts used by triangles but missing from part_names still need an entry: the reader
    // refuses ids outside the table.
    std::string name =
        part < mesh.part_names.size() ? mesh.part_names[part] : matbase::concat("part_", part);
    if (name.find_first_of("\r\n") != std::string::npos) {
      throw std::invalid_argument(
          matbase::concat(path, ": the name of part ", part, " contains a line break"));
    }
    names.push_back(std::move(name));
  }
  return names;
}

std::string ply_header(const TriangleMesh& mesh, const std::vector<std::string>& part_names) {
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\ncomment written by matpredict\n";
  for (size_t part = 0; part < part_names.size(); ++part) {
    header << "comment part " << part << " " << part_names[part] << "\n";
  }
  header << "element vertex " << mesh.vertex_count() << "\n"
         << "property float x\nproperty float y\nproperty float z\n";
  if (!mesh.normals.empty()) header << "property float nx\nproperty float ny\nproperty float nz\n";
  if (!mesh.uvs.empty()) header << "property float s\nproperty float t\n";
  if (!mesh.colors.empty()) header << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  header << "element face " << mesh.triangle_count() << "\n"
         << "property list uchar uint vertex_indices\nproperty uint part_id\nend_header\n";
  return header.str();
}

// Collects the body in little-endian byte order, whatever the host's, and hands it to the
// stream in large blocks.
class LittleEndianWriter {
 public:
  explicit LittleEndianWriter(std::ostream& out) : out_(out) {}

  void put_u8(uint8_t value) { buffer_.push_back(static_cast<char>(value)); }
  void put_u32(uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) put_u8(static_cast<uint8_t>(value >> shift));
  }
  void put_float(float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    put_u32(bits);
  }
  template <glm::length_t N>
  void put_floats(const glm::vec<N, float>& values) {
    for (glm::length_t i = 0; i < N; ++i) put_float(values[i]);
  }
  void end_record() {
    if (buffer_.size() >= kBlockBytes) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr size_t kBlockBytes = 1 << 20;
  std::ostream& out_;
  std::string buffer_;
};

// A linear colour channel as the byte a colour attribute stores: sRGB-encoded, rounded, clamped.
uint8_t srgb_byte(float linear) {
  return static_cast<uint8_t>(std::lround(255.0f * matbase::linear_to_srgb(std::clamp(linear, 0.0f, 1.0f))));
}

void write_ply_file(const TriangleMesh& mesh, const std::vector<std::string>& part_names,
                    const std::string& file_path, const std::string& path) {
  std::ofstream out(file_path, std::ios::binary | std::ios::trunc);
  if (!out) matbase::fail(path, "cannot create the temporary file " + file_path);
  out << ply_header(mesh, part_names);
  LittleEndianWriter writer(out);
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    writer.put_floats(mesh.positions[v]);
    if (!mesh.normals.empty()) writer.put_floats(mesh.normals[v]);
    if (!mesh.uvs.empty()) writer.put_floats(mesh.uvs[v]);
    if (!mesh.colors.empty())
      for (int c = 0; c < 3; ++c) writer.put_u8(srgb_byte(mesh.colors[v][c]));
    writer.end_record();
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    writer.put_u8(3);
    for (int corner = 0; corner < 3; ++corner) writer.put_u32(mesh.triangles[t][corner]);
    writer.put_u32(mesh.triangle_parts.empty() ? 0u : mesh.triangle_parts[t]);
    writer.end_record();
  }
  writer.flush();
  out.close();
  if (!out) matbase::fail(path, "cannot write the temporary file " + file_path);
}

// Faces without normals are flat, as Blender's PLY importer shades them, unless Auto Smooth is
// asked for; a zero normal in the file counts as none.
void complete_normals(TriangleMesh& mesh, std::optional<double> auto_smooth_deg) {
  MissingNormals missing;
  missing.auto_smooth_deg = auto_smooth_deg;
  if (!mesh.normals.empty()) {
    missing.vertex_missing.resize(mesh.vertex_count());
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
      const double length = glm::length(glm::dvec3(mesh.normals[v]));
      missing.vertex_missing[v] = !(length > 0.0);
      if (!missing.vertex_missing[v]) mesh.normals[v] = glm::vec3(glm::dvec3(mesh.normals[v]) / length);
    }
  }
  complete_missing_normals(mesh, missing);
}

}  // namespace

TriangleMesh read_ply(const std::string& path, const PlyReadOptions& options) {
  const std::string file = load_file(path);
  const PlyHeader header = parse_header(path, file);
  const PlyElement& vertices = require_element(path, header, "vertex");
  const PlyElement& faces = require_element(path, header, "face");
  const VertexLayout vertex_layout = make_vertex_layout(path, vertices);
  const FaceLayout face_layout = make_face_layout(path, faces, options);
  if (faces.count == 0) matbase::fail(path, "no faces (element face has 0 items)");
  if (vertices.count > UINT32_MAX) matbase::fail(path, "more vertices than 32-bit indices can address");

  BodyReader body(path, std::string_view(file).substr(header.body_offset), header.format);
  TriangleMesh mesh;
  std::vector<int64_t> triangle_ids;
  for (const PlyElement& element : header.elements) {
    if (&element == &vertices) {
      read_vertices(body, element, vertex_layout, mesh);
    } else if (&element == &faces) {
      read_faces(body, element, face_layout, vertices.count, mesh, triangle_ids);
    } else {
      skip_element(body, element);
    }
  }
  assign_parts(path, header.part_table, face_layout, triangle_ids, mesh);
  complete_normals(mesh, options.auto_smooth_deg);

  try {
    validate_mesh(mesh, path);
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(error.what());  // validate_mesh's message starts with the path
  }
  return mesh;
}

void write_ply(const TriangleMesh& mesh, const std::string& path) {
  validate_mesh(mesh, path);
  const std::vector<std::string> part_names = part_names_to_write(mesh, path);
  matbase::write_atomically(path, [&](const std::filesystem::path& temporary) {
    write_ply_file(mesh, part_names, temporary.string(), path);
  });
}

}  // namespace matgeom
