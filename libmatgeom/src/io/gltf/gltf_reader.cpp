#include "matgeom/io/gltf/gltf_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "matbase/file/file_error.h"
#include "io/gltf/extensions.h"
#include "io/gltf/gltf_file.h"
#include "io/gltf/gltf_materials.h"
#include "io/gltf/json_checks.h"
#include "matbase/file/input_file.h"
#include "matbase/image/image_file.h"
#include "matbase/image/unorm.h"
#include "matbase/text.h"
#include "matgeom/shading_normals.h"
#include "matgeom/tangents.h"

// Reading a glTF file is three steps: tinygltf parses the JSON, buffers and images; the node
// hierarchy gives every mesh a world transform; each primitive instance becomes a piece of
// geometry in Blender's frame, and the pieces are merged into one mesh with a part per material.
// Every index and byte range in the file is checked before it is used.

namespace matgeom {
namespace {

using gltf::GltfFile;


// ---------------------------------------------------------------------------------------------
// Loading

bool has_glb_magic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, sizeof(magic));
  return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

// tinygltf::LoadImageData reads its user data as a LoadImageDataOption, a struct of this one
// bool, which Debian's libtinygltf keeps out of its public header: true keeps each image's own
// channel count (grey, grey-alpha, RGB, RGBA) instead of expanding it to RGBA.
struct LoadImageDataOption {
  bool preserve_channels = true;
};

// How tinygltf decodes the file's images: as the OBJ and material-folder readers decode theirs
// (image_file.h), with the first problem in our words.
struct ImageDecoding {
  LoadImageDataOption option;
  std::string problem;
};

// The problem with an image tinygltf's decoder refused: stb_image's or the size the JSON states.
std::string undecoded_image_problem(std::string_view bytes, int width, int height) {
  tinygltf::Image decoded;
  std::string ignored;
  const int size = static_cast<int>(bytes.size());
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if ((width > 0 || height > 0) && tinygltf::LoadImageData(&decoded, 0, &ignored, &ignored, 0, 0, data, size, nullptr)) {
    return matbase::concat("the image is ", decoded.width, "x", decoded.height, ", but the file says ", width, "x", height);
  }
  return matbase::undecodable_image(bytes);
}

// A tinygltf::LoadImageDataFunction.
bool decode_gltf_image(tinygltf::Image* image, const int index, std::string* errors, std::string* warnings, int width,
                       int height, const unsigned char* bytes, int size, void* user_data) {
  auto& decoding = *static_cast<ImageDecoding*>(user_data);
  const std::string_view data(reinterpret_cast<const char*>(bytes), static_cast<size_t>(size));
  std::optional<std::string> problem = matbase::unread_image_format(data);
  if (!problem &&
      tinygltf::LoadImageData(image, index, errors, warnings, width, height, bytes, size, &decoding.option))
    return true;
  if (decoding.problem.empty())
    decoding.problem = matbase::concat("image ", index, ": ", problem ? *problem : undecoded_image_problem(data, width, height));
  return false;
}

GltfFile load_gltf(const std::string& path) {
  if (const std::optional<std::string> problem = matbase::input_file_problem(path)) matbase::fail(path, *problem);

  // The GLB magic decides the container; a .glb without it is not worth handing to the JSON
  // parser, whose error would be misleading.
  const bool binary = has_glb_magic(path);
  if (!binary && matbase::lowercase_extension(path) == ".glb") {
    matbase::fail(path, "not a binary glTF file (the header does not start with 'glTF')");
  }

  gltf::check_gltf_json(path, binary);
  GltfFile file;
  file.path = path;
  tinygltf::TinyGLTF loader;
  ImageDecoding decoding;
  loader.SetImageLoader(decode_gltf_image, &decoding);
  std::string errors;
  std::string warnings;
  const bool loaded = binary ? loader.LoadBinaryFromFile(&file.model, &errors, &warnings, path)
                             : loader.LoadASCIIFromFile(&file.model, &errors, &warnings, path);
  if (!decoding.problem.empty()) matbase::fail(path, decoding.problem);
  // tinygltf's messages quote what they could not read, data URIs included: passed on cut.
  if (!loaded) {
    std::string problem = "tinygltf could not load the file: " + matbase::without_data_uris(matbase::trim(errors));
    if (!warnings.empty()) problem += " (warnings: " + matbase::without_data_uris(matbase::trim(warnings)) + ")";
    matbase::fail(path, problem);
  }
  // tinygltf 2.7 warns only when an external image cannot be read; continuing would silently
  // render the material without its texture, so a warning is an error here.
  if (!warnings.empty()) matbase::fail(path, "tinygltf: " + matbase::without_data_uris(matbase::trim(warnings)));

  const auto& used = file.model.extensionsUsed;
  file.quantized = std::find(used.begin(), used.end(), gltf::kMeshQuantization) != used.end();
  return file;
}

// ---------------------------------------------------------------------------------------------
// Accessors

bool is_integer_component(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return true;
    default:
      return false;
  }
}

// The component formats glTF 2.0 allows per vertex attribute (spec section 3.7.2.1), widened by
// KHR_mesh_quantization when the file uses it.
bool attribute_format_allowed(const std::string& semantic, int component_type, bool normalized,
                              bool quantized) {
  if (component_type == TINYGLTF_COMPONENT_TYPE_FLOAT) return !normalized;
  const bool uvs = semantic.rfind("TEXCOORD_", 0) == 0;
  if (uvs && normalized &&
      (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
       component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)) {
    return true;
  }
  if (!quantized) return false;
  if (semantic == "POSITION" || uvs)
    return is_integer_component(component_type);
  // NORMAL and TANGENT: unit vectors, so only signed normalized integers make sense.
  return normalized && (component_type == TINYGLTF_COMPONENT_TYPE_BYTE ||
                        component_type == TINYGLTF_COMPONENT_TYPE_SHORT);
}

template <typename T>
double load_component(const unsigned char* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));  // glTF is little-endian, as is every target we build for
  return static_cast<double>(value);
}

// One component as a double; normalized integers map to [0, 1] or [-1, 1] as glTF specifies
// (signed values by max(c / (2^(b-1) - 1), -1)).
double decode_component(const unsigned char* bytes, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const double c = load_component<int8_t>(bytes);
      return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      const double c = load_component<uint8_t>(bytes);
      return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const double c = load_component<int16_t>(bytes);
      return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const double c = load_component<uint16_t>(bytes);
      return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return load_component<uint32_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load_component<float>(bytes);
    default:
      return std::nan("");  // unreachable: read_accessor rejects other component types
  }
}

// An accessor's elements, `components` doubles each, element after element.
struct AccessorValues {
  size_t count = 0;
  int components = 0;
  std::vector<double> values;

  double at(size_t element, int component) const {
    return values[element * static_cast<size_t>(components) + static_cast<size_t>(component)];
  }
};

// Reads accessor `index` after checking that it has `expected_type` and that every byte it
// addresses lies inside its buffer view and buffer. `what` names the user in error messages.
AccessorValues read_accessor(const GltfFile& file, int index, int expected_type,
                             const std::string& what) {
  const tinygltf::Model& model = file.model;
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
    matbase::fail(file.path, matbase::concat(what, ": accessor ", index, " does not exist (the file has ",
                           model.accessors.size(), ")"));
  }
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
  const std::string name = matbase::concat(what, " (accessor ", index, ")");
  if (accessor.type != expected_type) matbase::fail(file.path, name + ": wrong element type");
  if (accessor.sparse.isSparse) matbase::fail(file.path, name + ": sparse accessors are not supported");
  const int component_size =
      tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
  if (component_size <= 0 || accessor.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE ||
      accessor.componentType == TINYGLTF_COMPONENT_TYPE_INT) {
    matbase::fail(file.path, matbase::concat(name, ": invalid component type ", accessor.componentType));
  }
  if (accessor.normalized && !is_integer_component(accessor.componentType)) {
    matbase::fail(file.path, name + ": only 8- and 16-bit integers can be normalized");
  }

  AccessorValues result;
  result.count = accessor.count;
  result.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
  if (accessor.count == 0) return result;
  if (accessor.bufferView < 0 ||
      static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
    matbase::fail(file.path, matbase::concat(name, ": buffer view ", accessor.bufferView, " does not exist"));
  }
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
  if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
    matbase::fail(file.path, matbase::concat(name, ": buffer ", view.buffer, " does not exist"));
  }
  const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
  if (view.byteOffset > buffer.data.size() ||
      view.byteLength > buffer.data.size() - view.byteOffset) {
    matbase::fail(file.path,
         matbase::concat(name, ": buffer view ", accessor.bufferView, " (bytes ", view.byteOffset, " + ",
                view.byteLength, ") runs past its buffer of ", buffer.data.size(), " bytes"));
  }

  const size_t element_size =
      static_cast<size_t>(component_size) * static_cast<size_t>(result.components);
  const int stride_or_error = accessor.ByteStride(view);
  if (stride_or_error <= 0 || static_cast<size_t>(stride_or_error) < element_size) {
    matbase::fail(file.path, matbase::concat(name, ": invalid byteStride ", view.byteStride));
  }
  const size_t stride = static_cast<size_t>(stride_or_error);
  // The last element starts at byteOffset + stride (count - 1) and needs element_size bytes;
  // the comparison is arranged so that no term can overflow.
  const size_t available = view.byteLength;
  bool fits = accessor.byteOffset <= available && element_size <= available - accessor.byteOffset;
  fits = fits && (available - accessor.byteOffset - element_size) / stride >= accessor.count - 1;
  if (!fits) {
    matbase::fail(file.path, matbase::concat(name, ": ", accessor.count, " elements from byte ", accessor.byteOffset,
                           " run past the end of buffer view ", accessor.bufferView, " (",
                           view.byteLength, " bytes)"));
  }

  const unsigned char* base = buffer.data.data() + view.byteOffset + accessor.byteOffset;
  result.values.resize(accessor.count * static_cast<size_t>(result.components));
  for (size_t element = 0; element < accessor.count; ++element) {
    for (int c = 0; c < result.components; ++c) {
      const unsigned char* bytes =
          base + element * stride + static_cast<size_t>(c) * static_cast<size_t>(component_size);
      result.values[element * static_cast<size_t>(result.components) + static_cast<size_t>(c)] =
          decode_component(bytes, accessor.componentType, accessor.normalized);
    }
  }
  return result;
}

// Passed as the vertex count when reading POSITION, which defines it.
constexpr size_t kAnyCount = SIZE_MAX;

// A vertex attribute: read_accessor plus the glTF format rules, one element per vertex and
// finite values.
AccessorValues read_attribute(const GltfFile& file, int index, const std::string& semantic,
                              int expected_type, size_t vertex_count, const std::string& what) {
  const std::string name = what + " " + semantic;
  AccessorValues values = read_accessor(file, index, expected_type, name);
  const tinygltf::Accessor& accessor = file.model.accessors[static_cast<size_t>(index)];
  if (!attribute_format_allowed(semantic, accessor.componentType, accessor.normalized,
                                file.quantized)) {
    matbase::fail(file.path, matbase::concat(name, ": component type ", accessor.componentType,
                           accessor.normalized ? " (normalized)" : "", " is not allowed"));
  }
  if (vertex_count != kAnyCount && values.count != vertex_count) {
    matbase::fail(file.path, matbase::concat(name, ": ", values.count, " elements for ", vertex_count, " vertices"));
  }
  for (size_t i = 0; i < values.values.size(); ++i) {
    if (std::isfinite(values.values[i])) continue;
    matbase::fail(file.path,
         matbase::concat(name, ": non-finite vertex ", i / static_cast<size_t>(values.components)));
  }
  return values;
}

// ---------------------------------------------------------------------------------------------
// Node hierarchy

glm::dmat4 node_local_transform(const GltfFile& file, size_t node_index) {
  const tinygltf::Node& node = file.model.nodes[node_index];
  const std::string name = matbase::concat("node ", node_index);
  auto check_finite = [&](const std::vector<double>& values, size_t size, const char* property) {
    if (!values.empty() && values.size() != size) {
      matbase::fail(file.path, matbase::concat(name, ": ", property, " needs ", size, " numbers"));
    }
    for (double v : values) {
      if (!std::isfinite(v)) matbase::fail(file.path, matbase::concat(name, ": non-finite ", property));
    }
  };
  check_finite(node.matrix, 16, "matrix");
  check_finite(node.translation, 3, "translation");
  check_finite(node.rotation, 4, "rotation");
  check_finite(node.scale, 3, "scale");

  // glTF stores matrices column-major, as glm does.
  if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());

  glm::dmat4 transform(1.0);
  if (!node.translation.empty()) {
    transform[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (!node.rotation.empty()) {
    // glTF quaternions are (x, y, z, w); glm's constructor takes w first.
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    if (!(length > 0.0)) matbase::fail(file.path, name + ": zero rotation quaternion");
    transform = transform * glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) {
    transform = transform * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0),
                                       glm::dvec4(0, node.scale[1], 0, 0),
                                       glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
  }
  return transform;
}

struct MeshInstance {
  size_t mesh = 0;
  size_t node = 0;
  glm::dmat4 world{1.0};
};

// The scene's roots: the default scene's, or (without one) every node that is nobody's child.
std::vector<int> scene_roots(const GltfFile& file) {
  const tinygltf::Model& model = file.model;
  if (model.defaultScene >= 0) {
    if (static_cast<size_t>(model.defaultScene) >= model.scenes.size()) {
      matbase::fail(file.path, matbase::concat("default scene ", model.defaultScene, " does not exist"));
    }
    return model.scenes[static_cast<size_t>(model.defaultScene)].nodes;
  }
  std::vector<bool> is_child(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes) {
    for (int child : node.children) {
      if (child >= 0 && static_cast<size_t>(child) < model.nodes.size())
        is_child[static_cast<size_t>(child)] = true;
    }
  }
  std::vector<int> roots;
  for (size_t n = 0; n < model.nodes.size(); ++n) {
    if (!is_child[n]) roots.push_back(static_cast<int>(n));
  }
  return roots;
}

// Depth first, children in order, with an explicit stack: a hierarchy thousands of levels deep
// (a hostile file, or a long chain of bones) must not overflow the call stack.
std::vector<MeshInstance> collect_mesh_instances(const GltfFile& file) {
  const tinygltf::Model& model = file.model;
  struct Pending {
    int node;
    glm::dmat4 parent;
  };
  std::vector<bool> visited(model.nodes.size(), false);
  std::vector<MeshInstance> instances;
  std::vector<Pending> stack;
  const std::vector<int> roots = scene_roots(file);
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.push_back({*root, glm::dmat4(1.0)});
  while (!stack.empty()) {
    const Pending pending = stack.back();
    stack.pop_back();
    if (pending.node < 0 || static_cast<size_t>(pending.node) >= model.nodes.size()) {
      matbase::fail(file.path, matbase::concat("node ", pending.node, " does not exist"));
    }
    const size_t n = static_cast<size_t>(pending.node);
    // glTF node graphs are forests; a second visit means a cycle or a shared child.
    if (visited[n])
      matbase::fail(file.path, matbase::concat("node ", n, " is reached twice (the hierarchy must be a tree)"));
    visited[n] = true;

    const glm::dmat4 world = pending.parent * node_local_transform(file, n);
    const tinygltf::Node& node = model.nodes[n];
    if (node.mesh >= 0) {
      if (static_cast<size_t>(node.mesh) >= model.meshes.size()) {
        matbase::fail(file.path, matbase::concat("node ", n, ": mesh ", node.mesh, " does not exist"));
      }
      instances.push_back({static_cast<size_t>(node.mesh), n, world});
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.push_back({*child, world});
  }
  return instances;
}

// ---------------------------------------------------------------------------------------------
// Primitives

// glTF is +Y up, Blender +Z up: (x, y, z) -> (x, -z, y), a rotation of +90 degrees about X.
glm::dmat4 gltf_to_blender() {
  return glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, -1, 0, 0),
                    glm::dvec4(0, 0, 0, 1));
}

// Vertex indices of one primitive: its index accessor, or 0..n-1 when it has none.
std::vector<uint32_t> read_indices(const GltfFile& file, const tinygltf::Primitive& primitive,
                                   size_t vertex_count, const std::string& what) {
  std::vector<uint32_t> indices;
  if (primitive.indices < 0) {
    indices.resize(vertex_count);
    for (size_t i = 0; i < vertex_count; ++i) indices[i] = static_cast<uint32_t>(i);
    return indices;
  }
  const std::string name = what + " indices";
  const AccessorValues values = read_accessor(file, primitive.indices, TINYGLTF_TYPE_SCALAR, name);
  const tinygltf::Accessor& accessor = file.model.accessors[static_cast<size_t>(primitive.indices)];
  if (accessor.normalized || (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                              accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                              accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
    matbase::fail(file.path, name + ": indices must be unsigned 8-, 16- or 32-bit integers");
  }
  indices.reserve(values.count);
  for (double value : values.values) {
    if (value >= static_cast<double>(vertex_count)) {
      matbase::fail(file.path, matbase::concat(name, ": index ", static_cast<uint64_t>(value), " out of range (",
                             vertex_count, " vertices)"));
    }
    indices.push_back(static_cast<uint32_t>(value));
  }
  return indices;
}

// Triangles from an index list in the primitive's mode (glTF spec 3.7.2.1 for strips and fans).
// Triangles that repeat a vertex have no surface (strips use them to restart) and are dropped.
std::vector<glm::uvec3> assemble_triangles(const GltfFile& file, int mode,
                                           const std::vector<uint32_t>& indices,
                                           const std::string& what) {
  std::vector<glm::uvec3> triangles;
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (a != b && b != c && c != a) triangles.emplace_back(a, b, c);
  };
  const size_t n = indices.size();
  switch (mode) {
    case TINYGLTF_MODE_TRIANGLES:
      if (n % 3 != 0) matbase::fail(file.path, matbase::concat(what, ": ", n, " indices is not a multiple of 3"));
      for (size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
      break;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      for (size_t i = 0; i + 2 < n; ++i) {
        const size_t odd = i % 2;
        add(indices[i], indices[i + 1 + odd], indices[i + 2 - odd]);
      }
      break;
    case TINYGLTF_MODE_TRIANGLE_FAN:
      for (size_t i = 0; i + 2 < n; ++i) add(indices[i + 1], indices[i + 2], indices[0]);
      break;
    default:
      matbase::fail(file.path,
           matbase::concat(what, ": unsupported primitive mode ", mode,
                  " (only triangles, triangle strips and triangle fans have a surface)"));
  }
  return triangles;
}

int find_attribute(const tinygltf::Primitive& primitive, const char* semantic) {
  const auto it = primitive.attributes.find(semantic);
  return it == primitive.attributes.end() ? -1 : it->second;
}

// One primitive's geometry in the glTF frame, still untransformed. Normals that the file leaves
// out or gives with zero length are marked so that they can be computed after the transform.
struct PrimitivePiece {
  TriangleMesh mesh;
  int material = -1;
  std::vector<bool> normal_missing;
  bool file_tangents = false;
};

// `uv_set`: the n of the TEXCOORD_n its material's textures sample; kNoUvSet for a material
// without textures, whose primitive keeps TEXCOORD_0 when it has one (for the UV pass and scene
// materials).
constexpr int kNoUvSet = -1;

PrimitivePiece read_primitive(const GltfFile& file, const tinygltf::Primitive& primitive, int uv_set,
                              const std::string& what, std::vector<std::string>& notes) {
  PrimitivePiece piece;
  piece.material = primitive.material;
  TriangleMesh& mesh = piece.mesh;

  const int position_accessor = find_attribute(primitive, "POSITION");
  if (position_accessor < 0) matbase::fail(file.path, what + ": no POSITION attribute");
  const AccessorValues positions =
      read_attribute(file, position_accessor, "POSITION", TINYGLTF_TYPE_VEC3, kAnyCount, what);
  const size_t vertex_count = positions.count;
  mesh.positions.resize(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    mesh.positions[v] = glm::vec3(positions.at(v, 0), positions.at(v, 1), positions.at(v, 2));
  }

  piece.normal_missing.assign(vertex_count, true);
  const int normal_accessor = find_attribute(primitive, "NORMAL");
  if (normal_accessor >= 0) {
    const AccessorValues normals =
        read_attribute(file, normal_accessor, "NORMAL", TINYGLTF_TYPE_VEC3, vertex_count, what);
    mesh.normals.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      const glm::dvec3 n(normals.at(v, 0), normals.at(v, 1), normals.at(v, 2));
      const double length = glm::length(n);
      piece.normal_missing[v] = !(length > 0.0);
      mesh.normals[v] = piece.normal_missing[v] ? glm::vec3(0.0f) : glm::vec3(n / length);
    }
  }

  if (find_attribute(primitive, "COLOR_0") >= 0)
    add_note(notes, "the vertex colours (COLOR_0) are not applied: the materials' base colours stand alone");

  const std::string uv_semantic = "TEXCOORD_" + std::to_string(uv_set == kNoUvSet ? 0 : uv_set);
  const int uv_accessor = find_attribute(primitive, uv_semantic.c_str());
  if (uv_accessor < 0 && uv_set != kNoUvSet)
    add_note(notes, matbase::concat(what, " has no ", uv_semantic, ", which material ", primitive.material,
                                    "'s textures sample: they show one texel there"));
  if (uv_accessor >= 0) {
    const AccessorValues uvs =
        read_attribute(file, uv_accessor, uv_semantic, TINYGLTF_TYPE_VEC2, vertex_count, what);
    mesh.uvs.resize(vertex_count);
    // glTF puts the UV origin at the image's top-left corner with v pointing down; Blender and
    // our textures use v pointing up from the bottom-left corner, so v becomes 1 - v (the image
    // rows themselves stay top to bottom, as decoded).
    for (size_t v = 0; v < vertex_count; ++v) {
      mesh.uvs[v] = glm::vec2(uvs.at(v, 0), 1.0 - uvs.at(v, 1));
    }

    // A tangent frame only serves a normal map, which needs UVs, so TANGENT is read only here.
    // glTF's tangent frame (bitangent = w N x T) spans the normal map's +X and +Y, +Y pointing
    // up the image, which is +v after the flip above; so w carries over unchanged.
    const int tangent_accessor = find_attribute(primitive, "TANGENT");
    if (tangent_accessor >= 0) {
      const AccessorValues tangents =
          read_attribute(file, tangent_accessor, "TANGENT", TINYGLTF_TYPE_VEC4, vertex_count, what);
      mesh.tangents.resize(vertex_count);
      for (size_t v = 0; v < vertex_count; ++v) {
        mesh.tangents[v] = glm::vec4(tangents.at(v, 0), tangents.at(v, 1), tangents.at(v, 2),
                                     tangents.at(v, 3) < 0.0 ? -1.0 : 1.0);
      }
      piece.file_tangents = true;
    }
  }

  const std::vector<uint32_t> indices = read_indices(file, primitive, vertex_count, what);
  mesh.triangles = assemble_triangles(file, primitive.mode, indices, what);
  return piece;
}

// Normals the file did not give (or gave as zero vectors) are flat, as the glTF 2.0 spec
// requires of a primitive without NORMAL ("client implementations MUST calculate flat normals")
// and Blender's importer shades it, unless Auto Smooth is asked for; they are completed after
// the transform, so that a non-uniform scale tilts the faces as they appear in the scene.
void complete_normals(PrimitivePiece& piece, std::optional<double> auto_smooth_deg) {
  MissingNormals missing;
  missing.vertex_missing = piece.normal_missing;
  missing.auto_smooth_deg = auto_smooth_deg;
  // glTF splits a vertex at a UV seam into two with one position; smoothing joins them again.
  if (auto_smooth_deg) missing.file_vertex = vertices_by_position(piece.mesh);
  complete_missing_normals(piece.mesh, missing);
  if (piece.mesh.normals.empty()) piece.file_tangents = false;
}

// File tangents are re-orthogonalised against the (possibly recomputed) normals; if any is
// unusable, or the file gave none, the whole piece gets MikkTSpace-style tangents.
void complete_tangents(PrimitivePiece& piece) {
  TriangleMesh& mesh = piece.mesh;
  // A flat piece has no vertex normals to build a frame on (merge_pieces and matrender's scene
  // make them explicit where needed).
  if (mesh.uvs.empty() || mesh.normals.empty()) return;
  bool usable = piece.file_tangents;
  for (size_t v = 0; usable && v < mesh.vertex_count(); ++v) {
    const glm::dvec3 n(mesh.normals[v]);
    const glm::dvec3 t(mesh.tangents[v]);
    const glm::dvec3 in_plane = t - n * glm::dot(n, t);
    const double length = glm::length(in_plane);
    // A tangent within about half a degree of the normal has no usable direction left.
    usable = length > 1e-2;
    if (usable) mesh.tangents[v] = glm::vec4(glm::vec3(in_plane / length), mesh.tangents[v].w);
  }
  if (!usable) compute_tangents(mesh);
}

void check_finite_positions(const GltfFile& file, const TriangleMesh& mesh,
                            const std::string& what) {
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::vec3& p = mesh.positions[v];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
    matbase::fail(file.path, matbase::concat(what, ": non-finite vertex ", v, " after the node transform"));
  }
}

// Morph targets are not applied: the base shape is read, which is the shape the file shows only
// while every weight is 0 (the default without weights). An instance weighted otherwise is
// refused (the node's weights replace the mesh's).
void check_morph_weights(const GltfFile& file, const MeshInstance& instance) {
  const tinygltf::Mesh& mesh = file.model.meshes[instance.mesh];
  const bool has_targets = std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                       [](const tinygltf::Primitive& p) { return !p.targets.empty(); });
  const std::vector<double>& node_weights = file.model.nodes[instance.node].weights;
  const std::vector<double>& weights = node_weights.empty() ? mesh.weights : node_weights;
  if (!has_targets || std::all_of(weights.begin(), weights.end(), [](double w) { return w == 0.0; })) return;
  std::string listed;
  constexpr size_t kShown = 8;
  for (size_t w = 0; w < std::min(weights.size(), kShown); ++w) listed += matbase::concat(w == 0 ? "" : ", ", weights[w]);
  if (weights.size() > kShown) listed += matbase::concat(", ... (", weights.size(), " weights)");
  matbase::fail(file.path, matbase::concat("mesh ", instance.mesh, " (node ", instance.node, "): morph target weights ", listed,
                         " are not applied; only the base shape is read, so every weight must be 0"));
}

// Every primitive of every mesh instance, transformed into Blender's frame, with normals and
// (where there are UVs) tangents.
std::vector<PrimitivePiece> read_pieces(const GltfFile& file, const GltfReadOptions& options, gltf::GltfMaterials& materials,
                                        std::vector<std::string>& notes) {
  std::vector<PrimitivePiece> pieces;
  for (const MeshInstance& instance : collect_mesh_instances(file)) {
    const glm::dmat4 transform = gltf_to_blender() * instance.world;
    // A node scaled to zero (a common way to hide things) has no surface to render.
    const double determinant = glm::determinant(glm::dmat3(transform));
    if (!(std::abs(determinant) > 0.0) || !std::isfinite(determinant)) continue;

    check_morph_weights(file, instance);
    const tinygltf::Mesh& gltf_mesh = file.model.meshes[instance.mesh];
    for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
      const std::string what = matbase::concat("mesh ", instance.mesh, " primitive ", p);
      const tinygltf::Primitive& primitive = gltf_mesh.primitives[p];
      if (primitive.material >= 0 && static_cast<size_t>(primitive.material) >= file.model.materials.size())
        matbase::fail(file.path, matbase::concat(what, ": material ", primitive.material, " does not exist"));
      const int uv_set = primitive.material >= 0
                             ? materials.material(static_cast<size_t>(primitive.material)).uv_set.value_or(kNoUvSet)
                             : kNoUvSet;
      PrimitivePiece piece = read_primitive(file, primitive, uv_set, what, notes);
      if (piece.mesh.triangles.empty()) continue;
      // transform_mesh maps normals by the inverse transpose and, for a mirroring transform,
      // reverses the winding and the tangents' handedness.
      transform_mesh(piece.mesh, transform);
      check_finite_positions(file, piece.mesh, what);
      complete_normals(piece, options.auto_smooth_deg);
      complete_tangents(piece);
      pieces.push_back(std::move(piece));
    }
  }
  return pieces;
}

// ---------------------------------------------------------------------------------------------
// Assembly

// Parts follow the glTF material order (used materials only), then the default slot if needed.
std::map<int, uint32_t> assign_parts(const std::vector<PrimitivePiece>& pieces) {
  std::set<int> used;
  for (const PrimitivePiece& piece : pieces) used.insert(piece.material);
  std::map<int, uint32_t> part_of_material;
  uint32_t next = 0;
  for (int material : used) {
    if (material >= 0) part_of_material[material] = next++;
  }
  if (used.count(-1) != 0) part_of_material[-1] = next;
  return part_of_material;
}

// Concatenates the pieces. If any piece has UVs the mesh has UVs everywhere: pieces without
// get (0, 0) and the arbitrary tangent frame compute_tangents gives degenerate UVs. If any piece
// has normals, a flat piece gets its face normals at one vertex per corner (flat_shaded).
TriangleMesh merge_pieces(const GltfFile& file, std::vector<PrimitivePiece>& pieces,
                          const std::map<int, uint32_t>& part_of_material) {
  const bool any_uvs = std::any_of(pieces.begin(), pieces.end(), [](const PrimitivePiece& piece) {
    return !piece.mesh.uvs.empty();
  });
  const bool any_normals = std::any_of(pieces.begin(), pieces.end(), [](const PrimitivePiece& piece) {
    return !piece.mesh.normals.empty();
  });
  TriangleMesh merged;
  for (PrimitivePiece& piece : pieces) {
    TriangleMesh& mesh = piece.mesh;
    if (any_normals && mesh.normals.empty()) {
      mesh = flat_shaded(mesh);
      if (!mesh.uvs.empty()) compute_tangents(mesh);
    }
    if (any_uvs && mesh.uvs.empty()) {
      mesh.uvs.assign(mesh.vertex_count(), glm::vec2(0.0f));
      if (any_normals) compute_tangents(mesh);
    }
    if (mesh.vertex_count() > UINT32_MAX - merged.vertex_count()) {
      matbase::fail(file.path, "more vertices than 32-bit indices can address");
    }
    const uint32_t offset = static_cast<uint32_t>(merged.vertex_count());
    const uint32_t part = part_of_material.at(piece.material);
    merged.positions.insert(merged.positions.end(), mesh.positions.begin(), mesh.positions.end());
    merged.normals.insert(merged.normals.end(), mesh.normals.begin(), mesh.normals.end());
    merged.uvs.insert(merged.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    merged.tangents.insert(merged.tangents.end(), mesh.tangents.begin(), mesh.tangents.end());
    for (const glm::uvec3& triangle : mesh.triangles) {
      merged.triangles.push_back(triangle + glm::uvec3(offset));
      merged.triangle_parts.push_back(part);
    }
  }
  return merged;
}

// The extensions the file uses that nothing here reads, named once each.
void note_unread_extensions(const GltfFile& file, std::vector<std::string>& notes) {
  for (const std::string& extension : file.model.extensionsUsed) {
    if (std::find(gltf::kReadExtensions.begin(), gltf::kReadExtensions.end(), extension) != gltf::kReadExtensions.end()) continue;
    add_note(notes, "the glTF extension " + matbase::excerpt(extension) + " is not applied");
  }
}

}  // namespace

ObjectAsset read_gltf(const std::string& path, const GltfReadOptions& options) {
  const GltfFile file = load_gltf(path);
  gltf::GltfMaterials materials(file);
  std::vector<std::string> notes;
  note_unread_extensions(file, notes);
  std::vector<PrimitivePiece> pieces = read_pieces(file, options, materials, notes);
  if (pieces.empty()) matbase::fail(path, "no triangles in the scene");

  const std::map<int, uint32_t> part_of_material = assign_parts(pieces);
  ObjectAsset asset;
  asset.mesh = merge_pieces(file, pieces, part_of_material);
  asset.materials.resize(part_of_material.size());
  asset.mesh.part_names.resize(part_of_material.size());
  for (const auto& [material, part] : part_of_material) {
    asset.materials[part] = material >= 0
                                ? materials.material(static_cast<size_t>(material)).inputs
                                : matmaterial::MaterialInputs("default");  // Blender renders them with its default surface
    asset.mesh.part_names[part] = asset.materials[part].name;
  }
  asset.images = materials.take_images();
  for (std::string& note : materials.take_notes()) add_note(notes, std::move(note));
  asset.notes = std::move(notes);
  return asset;
}

}  // namespace matgeom
