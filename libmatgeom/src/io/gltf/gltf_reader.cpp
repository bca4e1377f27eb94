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

// What the whole reader needs: the model and the path every error message starts with.
struct GltfFile {
  std::string path;
  tinygltf::Model model;
  bool quantized = false;  // KHR_mesh_quantization allows integer positions, normals, tangents
};

// ---------------------------------------------------------------------------------------------
// Loading

bool has_glb_magic(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, sizeof(magic));
  return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

void check_required_extensions(const GltfFile& file) {
  // Extensions that change how geometry or images are stored would be misread if ignored;
  // KHR_mesh_quantization only widens the accessor formats, which the reader handles;
  // KHR_materials_clearcoat, _ior, _sheen, _transmission and KHR_texture_transform are read.
  for (const std::string& extension : file.model.extensionsRequired) {
    if (extension == "KHR_mesh_quantization" || extension == gltf::kClearcoat || extension == gltf::kIor ||
        extension == gltf::kSheen || extension == gltf::kTransmission || extension == gltf::kTextureTransform)
      continue;
    matbase::fail(file.path, "requires the unsupported glTF extension " + extension);
  }
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

  check_required_extensions(file);
  const auto& used = file.model.extensionsUsed;
  file.quantized = std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end();
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
  if (semantic == "TEXCOORD_0" && normalized &&
      (component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
       component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)) {
    return true;
  }
  if (!quantized) return false;
  if (semantic == "POSITION" || semantic == "TEXCOORD_0")
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

PrimitivePiece read_primitive(const GltfFile& file, const tinygltf::Primitive& primitive,
                              const std::string& what) {
  PrimitivePiece piece;
  piece.material = primitive.material;
  if (primitive.material >= 0 &&
      static_cast<size_t>(primitive.material) >= file.model.materials.size()) {
    matbase::fail(file.path, matbase::concat(what, ": material ", primitive.material, " does not exist"));
  }
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

  const int uv_accessor = find_attribute(primitive, "TEXCOORD_0");
  if (uv_accessor >= 0) {
    const AccessorValues uvs =
        read_attribute(file, uv_accessor, "TEXCOORD_0", TINYGLTF_TYPE_VEC2, vertex_count, what);
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
std::vector<PrimitivePiece> read_pieces(const GltfFile& file, const GltfReadOptions& options) {
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
      PrimitivePiece piece = read_primitive(file, gltf_mesh.primitives[p], what);
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
// Materials and images

matbase::ImagePixels convert_image(const GltfFile& file, size_t index) {
  const tinygltf::Image& image = file.model.images[index];
  const std::string name = matbase::concat("image ", index);
  if (image.image.empty() || image.width <= 0 || image.height <= 0) {
    matbase::fail(file.path, name + ": no decoded pixels");
  }
  if (image.component < 1 || image.component > 4 || (image.bits != 8 && image.bits != 16)) {
    matbase::fail(file.path, matbase::concat(name, ": unsupported format (", image.component, " channels of ",
                           image.bits, " bits)"));
  }
  const size_t expected = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                          static_cast<size_t>(image.component) *
                          static_cast<size_t>(image.bits / 8);
  if (image.image.size() != expected) matbase::fail(file.path, name + ": pixel data has the wrong size");

  matbase::ImagePixels pixels;
  const bool embedded = image.uri.empty() || image.uri.rfind("data:", 0) == 0;
  pixels.name = embedded
                    ? matbase::concat(std::filesystem::path(file.path).filename().string(), "#image", index)
                    : image.uri;
  pixels.width = image.width;
  pixels.height = image.height;
  pixels.channels = image.component;
  pixels.data = matbase::unorm_channels_to_8_bit(image.image, image.bits);
  return pixels;
}

// glTF images referenced by materials, converted once each, in order of first reference.
class ImageTable {
 public:
  explicit ImageTable(const GltfFile& file) : file_(file) {}

  int asset_index(size_t gltf_image) {
    const auto it = asset_indices_.find(gltf_image);
    if (it != asset_indices_.end()) return it->second;
    const int index = static_cast<int>(images_.size());
    images_.push_back(convert_image(file_, gltf_image));
    asset_indices_.emplace(gltf_image, index);
    return index;
  }

  std::vector<matbase::ImagePixels> take_images() { return std::move(images_); }

 private:
  const GltfFile& file_;
  std::map<size_t, int> asset_indices_;
  std::vector<matbase::ImagePixels> images_;
};

struct TextureRef {
  int image = -1;  // index into the asset's images
  matmaterial::TextureWrap wrap = matmaterial::TextureWrap::Repeat;
  matmaterial::TextureTransform transform;  // KHR_texture_transform's
};

// MaterialInputs has one wrap mode. Blender 3.4's Image Texture offers REPEAT and EXTEND per image
// (its importer emulates mirrored and mixed modes with extra nodes); here a texture clamps only
// when both axes say CLAMP_TO_EDGE, and MIRRORED_REPEAT is approximated by REPEAT.
matmaterial::TextureWrap sampler_wrap(const GltfFile& file, int sampler_index, const std::string& what) {
  if (sampler_index < 0) return matmaterial::TextureWrap::Repeat;
  if (static_cast<size_t>(sampler_index) >= file.model.samplers.size()) {
    matbase::fail(file.path, matbase::concat(what, ": sampler ", sampler_index, " does not exist"));
  }
  const tinygltf::Sampler& sampler = file.model.samplers[static_cast<size_t>(sampler_index)];
  const bool clamp = sampler.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
                     sampler.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  return clamp ? matmaterial::TextureWrap::Clamp : matmaterial::TextureWrap::Repeat;
}

// Two numbers of a KHR_texture_transform member, `fallback` when absent.
glm::dvec2 transform_pair(const GltfFile& file, const tinygltf::Value& transform, const char* member,
                          glm::dvec2 fallback, const std::string& what) {
  if (!transform.Has(member)) return fallback;
  const tinygltf::Value& value = transform.Get(member);
  if (!value.IsArray() || value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
    matbase::fail(file.path, matbase::concat(what, ": ", gltf::kTextureTransform, " ", member, " needs 2 numbers"));
  const glm::dvec2 pair(value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble());
  if (!std::isfinite(pair.x) || !std::isfinite(pair.y))
    matbase::fail(file.path, matbase::concat(what, ": ", gltf::kTextureTransform, " ", member, " is not finite"));
  return pair;
}

// A textureInfo's KHR_texture_transform, whose texCoord (when given) replaces the textureInfo's.
matmaterial::TextureTransform read_texture_transform(const GltfFile& file, const tinygltf::Value& transform, int& tex_coord,
                                        const std::string& what) {
  if (!transform.IsObject()) matbase::fail(file.path, matbase::concat(what, ": ", gltf::kTextureTransform, " is not an object"));
  matmaterial::TextureTransform t;
  t.offset = transform_pair(file, transform, "offset", t.offset, what);
  t.scale = transform_pair(file, transform, "scale", t.scale, what);
  if (transform.Has("rotation")) {
    const tinygltf::Value& rotation = transform.Get("rotation");
    if (!rotation.IsNumber() || !std::isfinite(rotation.GetNumberAsDouble()))
      matbase::fail(file.path, matbase::concat(what, ": ", gltf::kTextureTransform, " rotation is not a finite number"));
    t.rotation = rotation.GetNumberAsDouble();
  }
  if (transform.Has("texCoord")) {
    if (!transform.Get("texCoord").IsInt())
      matbase::fail(file.path, matbase::concat(what, ": ", gltf::kTextureTransform, " texCoord is not an integer"));
    tex_coord = transform.Get("texCoord").GetNumberAsInt();
  }
  return t;
}

// `extensions`: the textureInfo's, where a KHR_texture_transform may be.
TextureRef resolve_texture(const GltfFile& file, ImageTable& images, int texture_index, int tex_coord,
                           const tinygltf::ExtensionMap& extensions, const std::string& what) {
  TextureRef ref;
  if (texture_index < 0) return ref;
  const auto transform = extensions.find(gltf::kTextureTransform);
  if (transform != extensions.end()) ref.transform = read_texture_transform(file, transform->second, tex_coord, what);
  if (static_cast<size_t>(texture_index) >= file.model.textures.size()) {
    matbase::fail(file.path, matbase::concat(what, ": texture ", texture_index, " does not exist"));
  }
  if (tex_coord != 0) {
    matbase::fail(file.path, matbase::concat(what, ": uses TEXCOORD_", tex_coord, "; only TEXCOORD_0 is read"));
  }
  const tinygltf::Texture& texture = file.model.textures[static_cast<size_t>(texture_index)];
  if (texture.source < 0 || static_cast<size_t>(texture.source) >= file.model.images.size()) {
    matbase::fail(file.path,
         matbase::concat(what, ": texture ", texture_index, " has no image in a core format (PNG or JPEG)"));
  }
  ref.image = images.asset_index(static_cast<size_t>(texture.source));
  ref.wrap = sampler_wrap(file, texture.sampler, what);
  return ref;
}

// A factor must lie in its parameter's range (the parameter table's).
double checked_factor(const GltfFile& file, matmaterial::MaterialParameter p, double value, const std::string& what) {
  const matmaterial::MaterialParameterInfo& info = matmaterial::material_parameter(p);
  if (!(value >= info.min && value <= info.max))
    matbase::fail(file.path, matbase::concat(what, " ", value, " is outside [", info.min, ", ", info.max, "]"));
  return value;
}

// A number member of an extension object, if present.
std::optional<double> extension_number(const GltfFile& file, const tinygltf::Value& extension, const char* member,
                                       const std::string& what) {
  if (!extension.Has(member)) return std::nullopt;
  const tinygltf::Value& value = extension.Get(member);
  if (!value.IsNumber()) matbase::fail(file.path, matbase::concat(what, ": ", member, " is not a number"));
  return value.GetNumberAsDouble();
}

// A textureInfo member of an extension object: the texture, without an image when absent.
TextureRef extension_texture(const GltfFile& file, ImageTable& images, const tinygltf::Value& extension,
                             const char* member, const std::string& what) {
  if (!extension.Has(member)) return {};
  const tinygltf::Value& info = extension.Get(member);
  const std::string where = matbase::concat(what, " ", member);
  if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
    matbase::fail(file.path, where + ": expected a texture info with an integer index");
  int tex_coord = 0;
  if (info.Has("texCoord")) {
    if (!info.Get("texCoord").IsInt()) matbase::fail(file.path, where + ": texCoord is not an integer");
    tex_coord = info.Get("texCoord").GetNumberAsInt();
  }
  tinygltf::ExtensionMap extensions;
  if (info.Has("extensions")) {
    const tinygltf::Value& all = info.Get("extensions");
    if (!all.IsObject()) matbase::fail(file.path, where + ": extensions is not an object");
    for (const std::string& name : all.Keys()) extensions.emplace(name, all.Get(name));
  }
  return resolve_texture(file, images, info.Get("index").GetNumberAsInt(), tex_coord, extensions, where);
}

// One input an extension gives as factor x one channel of a texture (glTF's pattern), set on
// `p`; the factor is glTF's default 0 when absent.
void read_extension_input(const GltfFile& file, ImageTable& images, const tinygltf::Value& extension,
                          const char* factor_member, const char* texture_member, int channel, matmaterial::MaterialParameter p,
                          matmaterial::MaterialInputs& desc, const std::string& where) {
  const double factor = extension_number(file, extension, factor_member, where).value_or(0.0);
  desc.set(p, checked_factor(file, p, factor, matbase::concat(where, " ", factor_member)));
  const TextureRef texture = extension_texture(file, images, extension, texture_member, where);
  if (texture.image >= 0) desc.set_image(p, texture.image, channel, texture.transform);
}

// KHR_materials_clearcoat as Blender 3.4's importer wires it: Clearcoat = clearcoatFactor x
// clearcoatTexture.R, Clearcoat Roughness = clearcoatRoughnessFactor x clearcoatRoughnessTexture.G,
// both factors 0 when absent (so a coat without a roughness is a mirror, not Blender's default
// 0.03). clearcoatNormalTexture has no MaterialInputs input yet: the coat keeps the smooth normal.
void read_clearcoat(const GltfFile& file, ImageTable& images, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                    const std::string& what) {
  const std::string where = matbase::concat(what, " ", gltf::kClearcoat);
  read_extension_input(file, images, extension, "clearcoatFactor", "clearcoatTexture", gltf::kClearcoatChannel,
                       matmaterial::MaterialParameter::Clearcoat, desc, where);
  read_extension_input(file, images, extension, "clearcoatRoughnessFactor", "clearcoatRoughnessTexture",
                       gltf::kClearcoatRoughnessChannel, matmaterial::MaterialParameter::ClearcoatRoughness, desc, where);
}

// KHR_materials_sheen as Blender 3.4's importer wires it (gltf2_blender_KHR_materials_sheen.py):
// a Velvet BSDF added to the Principled BSDF, Color = sheenColorFactor x sheenColorTexture.RGB,
// Sigma = sheenRoughnessFactor x sheenRoughnessTexture.A, both factors 0 when absent. Present
// with a black colour, the extension adds a velvet that reflects nothing.
void read_sheen(const GltfFile& file, ImageTable& images, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                const std::string& what) {
  const std::string where = matbase::concat(what, " ", gltf::kSheen);
  glm::dvec3 colour(0.0);
  if (extension.Has("sheenColorFactor")) {
    const tinygltf::Value& factor = extension.Get("sheenColorFactor");
    if (!factor.IsArray() || factor.ArrayLen() != 3) matbase::fail(file.path, where + ": sheenColorFactor needs 3 numbers");
    for (int c = 0; c < 3; ++c) {
      const tinygltf::Value& component = factor.Get(c);
      if (!component.IsNumber()) matbase::fail(file.path, where + ": sheenColorFactor needs 3 numbers");
      colour[c] = checked_factor(file, matmaterial::MaterialParameter::VelvetColor, component.GetNumberAsDouble(),
                                 where + " sheenColorFactor");
    }
  }
  desc.set(matmaterial::MaterialParameter::VelvetColor, colour);
  const TextureRef colour_texture = extension_texture(file, images, extension, "sheenColorTexture", where);
  if (colour_texture.image >= 0)
    desc.set_image(matmaterial::MaterialParameter::VelvetColor, colour_texture.image, 0, colour_texture.transform);
  read_extension_input(file, images, extension, "sheenRoughnessFactor", "sheenRoughnessTexture",
                       gltf::kSheenRoughnessChannel, matmaterial::MaterialParameter::VelvetSigma, desc, where);
}

// KHR_materials_transmission as Blender 3.4's importer wires it: Transmission =
// transmissionFactor x transmissionTexture.R; a factor of 0 (the default) leaves the texture out.
void read_transmission(const GltfFile& file, ImageTable& images, const tinygltf::Value& extension, matmaterial::MaterialInputs& desc,
                       const std::string& what) {
  const std::string where = matbase::concat(what, " ", gltf::kTransmission);
  read_extension_input(file, images, extension, "transmissionFactor", "transmissionTexture",
                       gltf::kTransmissionChannel, matmaterial::MaterialParameter::Transmission, desc, where);
  if (desc.scalar(matmaterial::MaterialParameter::Transmission) == 0.0) desc[matmaterial::MaterialParameter::Transmission].image = -1;
}

// The Principled BSDF inputs Blender's importer sets (docs/conventions.md): base colour =
// factor x texture, roughness = factor x texture.G, metallic = factor x texture.B, normal map
// strength = normalTexture.scale, emission = emissiveFactor x emissiveTexture with
// KHR_materials_emissive_strength's strength, IOR = KHR_materials_ior's (1.5 without it),
// KHR_materials_clearcoat (read_clearcoat), KHR_materials_transmission (read_transmission),
// KHR_materials_sheen (read_sheen);
// alphaMode BLEND or MASK: Alpha = baseColorFactor[3] x baseColorTexture.A; specular and
// specular tint keep Blender's defaults. Occlusion has no MaterialInputs input.
matmaterial::MaterialInputs convert_material(const GltfFile& file, ImageTable& images, size_t index) {
  const tinygltf::Material& material = file.model.materials[index];
  const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  const std::string what = matbase::concat("material ", index);

  using P = matmaterial::MaterialParameter;
  matmaterial::MaterialInputs desc(material.name.empty() ? matbase::concat("material", index) : material.name);
  if (pbr.baseColorFactor.size() != 4) matbase::fail(file.path, what + ": baseColorFactor needs 4 numbers");
  glm::dvec3 base_color;
  for (int c = 0; c < 3; ++c) {
    base_color[c] = checked_factor(file, P::BaseColor, pbr.baseColorFactor[static_cast<size_t>(c)],
                                   what + " baseColorFactor");
  }
  desc.set(P::BaseColor, base_color);
  // alphaMode BLEND and MASK link Alpha to baseColorFactor[3] x the base texture's A; Blender
  // 3.4's importer turns MASK's alphaCutoff into an EEVEE clip threshold that Cycles ignores,
  // so MASK renders with the same fractional alpha as BLEND. OPAQUE leaves Alpha at 1.
  const bool uses_alpha = material.alphaMode == "BLEND" || material.alphaMode == "MASK";
  if (!uses_alpha && material.alphaMode != "OPAQUE")
    matbase::fail(file.path, matbase::concat(what, ": alphaMode ", matbase::excerpt(material.alphaMode), " is not OPAQUE, MASK or BLEND"));
  if (uses_alpha)
    desc.set(P::Alpha, checked_factor(file, P::Alpha, pbr.baseColorFactor[3], what + " baseColorFactor alpha"));
  desc.set(P::Metallic, checked_factor(file, P::Metallic, pbr.metallicFactor, what + " metallicFactor"));
  desc.set(P::Roughness, checked_factor(file, P::Roughness, pbr.roughnessFactor, what + " roughnessFactor"));
  if (material.emissiveFactor.size() != 3) matbase::fail(file.path, what + ": emissiveFactor needs 3 numbers");
  glm::dvec3 emission;
  for (int c = 0; c < 3; ++c)
    emission[c] = checked_factor(file, P::Emission, material.emissiveFactor[static_cast<size_t>(c)],
                                 what + " emissiveFactor");
  desc.set(P::Emission, emission);
  const auto strength = material.extensions.find(gltf::kEmissiveStrength);
  if (strength != material.extensions.end() && strength->second.Has("emissiveStrength")) {
    const tinygltf::Value& value = strength->second.Get("emissiveStrength");
    if (!value.IsNumber()) matbase::fail(file.path, what + ": emissiveStrength is not a number");
    desc.set(P::EmissionStrength, checked_factor(file, P::EmissionStrength, value.GetNumberAsDouble(),
                                                 what + " emissiveStrength"));
  }
  desc.set(P::Ior, gltf::kDefaultIor);
  const auto ior = material.extensions.find(gltf::kIor);
  if (ior != material.extensions.end())
    desc.set(P::Ior, checked_factor(file, P::Ior, extension_number(file, ior->second, "ior", what).value_or(gltf::kDefaultIor),
                                    matbase::concat(what, " ", gltf::kIor, " ior")));
  const auto clearcoat = material.extensions.find(gltf::kClearcoat);
  if (clearcoat != material.extensions.end()) read_clearcoat(file, images, clearcoat->second, desc, what);
  const auto transmission = material.extensions.find(gltf::kTransmission);
  if (transmission != material.extensions.end()) read_transmission(file, images, transmission->second, desc, what);
  const auto sheen = material.extensions.find(gltf::kSheen);
  if (sheen != material.extensions.end()) read_sheen(file, images, sheen->second, desc, what);
  if (!std::isfinite(material.normalTexture.scale))
    matbase::fail(file.path, what + ": non-finite normal scale");
  desc.normal_strength = material.normalTexture.scale;

  const TextureRef base = resolve_texture(file, images, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                         pbr.baseColorTexture.extensions, what + " baseColorTexture");
  const TextureRef metallic_roughness =
      resolve_texture(file, images, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                      pbr.metallicRoughnessTexture.extensions, what + " metallicRoughnessTexture");
  const TextureRef normal = resolve_texture(file, images, material.normalTexture.index, material.normalTexture.texCoord,
                                           material.normalTexture.extensions, what + " normalTexture");
  const TextureRef emissive =
      resolve_texture(file, images, material.emissiveTexture.index, material.emissiveTexture.texCoord,
                      material.emissiveTexture.extensions, what + " emissiveTexture");
  if (base.image >= 0) desc.set_image(P::BaseColor, base.image, 0, base.transform);
  if (base.image >= 0 && uses_alpha) desc.set_image(P::Alpha, base.image, gltf::kBaseColorAlphaChannel, base.transform);
  if (emissive.image >= 0) desc.set_image(P::Emission, emissive.image, 0, emissive.transform);
  if (metallic_roughness.image >= 0)
    desc.set_metallic_roughness_image(metallic_roughness.image, metallic_roughness.transform);
  desc.normal_image = normal.image;
  desc.normal_transform = normal.transform;
  // The wrap mode follows the most visible texture: base colour, else roughness, else normal.
  for (const TextureRef& ref : {base, metallic_roughness, normal}) {
    if (ref.image < 0) continue;
    desc.wrap = ref.wrap;
    break;
  }
  return desc;
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

}  // namespace

ObjectAsset read_gltf(const std::string& path, const GltfReadOptions& options) {
  const GltfFile file = load_gltf(path);
  std::vector<PrimitivePiece> pieces = read_pieces(file, options);
  if (pieces.empty()) matbase::fail(path, "no triangles in the scene");

  const std::map<int, uint32_t> part_of_material = assign_parts(pieces);
  ObjectAsset asset;
  asset.mesh = merge_pieces(file, pieces, part_of_material);

  ImageTable images(file);
  asset.materials.resize(part_of_material.size());
  asset.mesh.part_names.resize(part_of_material.size());
  for (const auto& [material, part] : part_of_material) {
    asset.materials[part] = material >= 0
                                ? convert_material(file, images, static_cast<size_t>(material))
                                : matmaterial::MaterialInputs("default");  // Blender renders them with its default surface
    asset.mesh.part_names[part] = asset.materials[part].name;
  }
  asset.images = images.take_images();
  return asset;
}

}  // namespace matgeom
