#include "matgeom/io/ply/ply_io.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "support/reader_checks.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

// These tests write PLY files byte by byte (ASCII text, binary values in either byte order
// assembled here) and check what the reader makes of them against meshes written down here.

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

// The names in a directory, to check that no temporary file is left behind.
std::vector<std::string> directory_entries(const TempDir& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir.path())) {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

// The message of the runtime_error read_ply throws, or "" when it reads the file.
std::string read_error(const std::string& path, const matgeom::PlyReadOptions& options = {}) {
  try {
    matgeom::read_ply(path, options);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// The message of the runtime_error write_ply throws, or "" when it writes the file.
std::string write_error(const matgeom::TriangleMesh& mesh, const std::string& path) {
  try {
    matgeom::write_ply(mesh, path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// Binary PLY values in an explicit byte order, assembled here rather than by the reader's code.
class BinaryPly {
 public:
  explicit BinaryPly(bool big_endian) : big_endian_(big_endian) {}

  void text(const std::string& header) { bytes_ += header; }
  void i8(int8_t value) { put(static_cast<uint8_t>(value), 1); }
  void u8(uint8_t value) { put(value, 1); }
  void i16(int16_t value) { put(static_cast<uint16_t>(value), 2); }
  void u16(uint16_t value) { put(value, 2); }
  void i32(int32_t value) { put(static_cast<uint32_t>(value), 4); }
  void u32(uint32_t value) { put(value, 4); }
  void f32(float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    put(bits, 4);
  }
  void f64(double value) {
    uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    put(bits, 8);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  // The low `size` bytes of `value`, most significant first in big-endian order.
  void put(uint64_t value, int size) {
    for (int i = 0; i < size; ++i) {
      const int byte = big_endian_ ? size - 1 - i : i;
      bytes_.push_back(static_cast<char>((value >> (8 * byte)) & 0xff));
    }
  }

  bool big_endian_;
  std::string bytes_;
};

// Six vertices, four triangles in three named parts, normals and UVs with awkward values.
matgeom::TriangleMesh three_part_mesh() {
  matgeom::TriangleMesh mesh;
  mesh.positions = {{0, 0, 0},           {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.1f, -2.5f, 3e-8f},
                    {1e6f, 7.25f, -0.3f}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0.6f, 0.8f, 0}, {-1, 0, 0}};
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.333f, 2.5f}, {-1.5f, 0.125f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}, {3, 5, 0}};
  mesh.triangle_parts = {0, 0, 1, 2};
  mesh.part_names = {"wall", "floor tile", "glass"};
  return mesh;
}

// A quad and a triangle with vertex colours, an unknown element with a list, and object ids.
const std::string kAsciiQuadAndTriangle =
    "ply\n"
    "format ascii 1.0\n"
    "comment made by hand\n"
    "obj_info a quad and a triangle\n"
    "element vertex 5\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "element material 2\n"
    "property list uchar float coefficients\n"
    "property int flags\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property int object_id\n"
    "end_header\n"
    "0 0 0 255 0 0\n"
    "1 0 0 0 255 0\n"
    "1 1 0 0 0 255\n"
    "0 1 0 10 20 30\n"
    "2 0.5 -0.25 1 2 3\n"
    "3 0.5 0.25 1 7\n"
    "0 -1\n"
    "4 0 1 2 3 7\n"
    "3 1 4 2 -1\n";

// Every scalar type under both of its names, double positions, u/v texture coordinates, ushort
// list counts and an unknown element after the faces.
std::string every_type_ply(bool big_endian) {
  BinaryPly ply(big_endian);
  ply.text(std::string("ply\nformat ") +
           (big_endian ? "binary_big_endian" : "binary_little_endian") +
           " 1.0\n"
           "element vertex 5\n"
           "property double x\nproperty float64 y\nproperty double z\n"
           "property float nx\nproperty float32 ny\nproperty float nz\n"
           "property char a\nproperty uint8 b\nproperty short c\nproperty uint16 d\n"
           "property int32 e\nproperty uint f\nproperty int8 g\nproperty uchar h\n"
           "property int16 i\nproperty ushort j\nproperty int k\nproperty uint32 l\n"
           "property float u\nproperty double v\n"
           "element face 2\n"
           "property list ushort int vertex_index\n"
           "element edge 1\n"
           "property list uint int16 ends\n"
           "property float64 weight\n"
           "end_header\n");
  const double positions[5][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 3, 0.5}};
  for (int v = 0; v < 5; ++v) {
    for (double coordinate : positions[v]) ply.f64(coordinate);
    ply.f32(0.0f);
    ply.f32(0.0f);
    ply.f32(1.0f);
    ply.i8(-5);
    ply.u8(200);
    ply.i16(-30000);
    ply.u16(60000);
    ply.i32(-2000000000);
    ply.u32(4000000000u);
    ply.i8(-128);
    ply.u8(255);
    ply.i16(-1);
    ply.u16(1);
    ply.i32(-1);
    ply.u32(1);
    ply.f32(0.25f * static_cast<float>(v));
    ply.f64(1.0 - 0.125 * v);
  }
  ply.u16(5);  // a pentagon
  for (int32_t corner : {0, 1, 2, 4, 3}) ply.i32(corner);
  ply.u16(3);
  for (int32_t corner : {1, 3, 0}) ply.i32(corner);
  ply.u32(2);
  ply.i16(-7);
  ply.i16(9);
  ply.f64(0.75);
  return ply.bytes();
}

// Like Replica's mesh_semantic.ply: two unit squares a metre apart, three quads, object ids.
std::string replica_like_ply() {
  BinaryPly ply(false);
  ply.text(
      "ply\n"
      "format binary_little_endian 1.0\n"
      "element vertex 8\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 3\n"
      "property list uchar int vertex_indices\n"
      "property int object_id\n"
      "end_header\n");
  for (int v = 0; v < 8; ++v) {
    ply.f32(static_cast<float>((v & 1) ^ ((v >> 1) & 1)));  // 0 1 1 0 per square
    ply.f32(static_cast<float>((v >> 1) & 1));
    ply.f32(static_cast<float>(v >> 2));
    ply.f32(0.0f);
    ply.f32(0.0f);
    ply.f32(1.0f);
    for (int channel = 0; channel < 3; ++channel) ply.u8(static_cast<uint8_t>(40 * v + channel));
  }
  const int32_t quads[3][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {3, 2, 6, 7}};
  const int32_t object_ids[3] = {12, 3, 12};
  for (int q = 0; q < 3; ++q) {
    ply.u8(4);
    for (int32_t corner : quads[q]) ply.i32(corner);
    ply.i32(object_ids[q]);
  }
  return ply.bytes();
}

// An ASCII file with vertices x y z and faces with vertex_indices only.
std::string ascii_ply(int vertices, int faces, const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

const std::string kTriangleBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

// IEC 61966-2-1's sRGB decoding of an 8-bit value, written out here.
float srgb_byte_to_linear(int byte) {
  const double c = byte / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

}  // namespace

TEST_CASE("PLY round trip keeps positions, normals, uvs, triangles and parts", "[geom]") {
  TempDir dir;
  const matgeom::TriangleMesh mesh = three_part_mesh();
  const std::string path = dir.file("mesh.ply");
  matgeom::write_ply(mesh, path);
  CHECK(directory_entries(dir) == std::vector<std::string>{"mesh.ply"});  // no temporary file left

  const matgeom::TriangleMesh read = matgeom::read_ply(path);
  CHECK(read.positions == mesh.positions);
  CHECK(read.normals == mesh.normals);
  CHECK(read.uvs == mesh.uvs);
  CHECK(read.tangents.empty());
  CHECK(read.triangles == mesh.triangles);
  CHECK(read.triangle_parts == mesh.triangle_parts);
  CHECK(read.part_names == mesh.part_names);

  SECTION("a mesh without normals, uvs or parts") {
    matgeom::TriangleMesh bare;
    bare.positions = mesh.positions;
    bare.triangles = mesh.triangles;
    matgeom::write_ply(bare, path);  // replaces the file
    const matgeom::TriangleMesh read_bare = matgeom::read_ply(path);
    CHECK(read_bare.positions == bare.positions);
    CHECK(read_bare.normals.empty());
    CHECK(read_bare.uvs.empty());
    CHECK(read_bare.triangles == bare.triangles);
    CHECK(read_bare.triangle_parts == std::vector<uint32_t>(4, 0));
    CHECK(read_bare.part_names == std::vector<std::string>{"part_0"});
  }
}

TEST_CASE("PLY writer refuses bad meshes and leaves nothing behind on failure", "[geom]") {
  TempDir dir;
  matgeom::TriangleMesh mesh = three_part_mesh();

  SECTION("part name with a line break") {
    mesh.part_names[1] = "two\nlines";
    CHECK_THROWS_AS(matgeom::write_ply(mesh, dir.file("mesh.ply")), std::invalid_argument);
    CHECK(directory_entries(dir).empty());
  }
  SECTION("invalid mesh") {
    mesh.triangles[0][2] = 6;
    CHECK_THROWS_AS(matgeom::write_ply(mesh, dir.file("mesh.ply")), std::invalid_argument);
    CHECK(directory_entries(dir).empty());
  }
  SECTION("missing directory") {
    const std::string path = dir.file("missing/mesh.ply");
    CHECK_THAT(write_error(mesh, path), Contains(path) && Contains("cannot create"));
    CHECK(directory_entries(dir).empty());
  }
  SECTION("the target is a directory, so the rename fails") {
    const std::string path = dir.file("occupied");
    fs::create_directory(path);
    CHECK_THAT(write_error(mesh, path), Contains(path) && Contains("rename"));
    CHECK(directory_entries(dir) ==
          std::vector<std::string>{"occupied"});  // the temporary file is gone
  }
}

TEST_CASE("PLY ASCII: fan triangulation, skipped properties and elements, object ids", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("hand.ply");
  SECTION("LF line ends") { write_bytes(path, kAsciiQuadAndTriangle); }
  SECTION("CRLF line ends") {
    std::string crlf;
    for (char c : kAsciiQuadAndTriangle)
      crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    write_bytes(path, crlf);
  }

  const matgeom::TriangleMesh mesh = matgeom::read_ply(path);
  CHECK(mesh.positions ==
        std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5f, -0.25f}});
  CHECK(mesh.normals.empty());
  CHECK(mesh.uvs.empty());
  // The quad 0 1 2 3 fans around vertex 0.
  CHECK(mesh.triangles == std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {1, 4, 2}});
  // Ids in increasing order: -1 is part 0, 7 is part 1.
  CHECK(mesh.part_names == std::vector<std::string>{"object_-1", "object_7"});
  CHECK(mesh.triangle_parts == std::vector<uint32_t>{1, 1, 0});
  // Colours are sRGB bytes, kept linear.
  REQUIRE(mesh.colors.size() == 5);
  CHECK(mesh.colors[0] == glm::vec3(1, 0, 0));
  CHECK(mesh.colors[2] == glm::vec3(0, 0, 1));
  for (int c = 0; c < 3; ++c) CHECK(mesh.colors[3][c] == Approx(srgb_byte_to_linear(10 * (c + 1))).epsilon(1e-6));
}

TEST_CASE("PLY binary big- and little-endian: every type, double positions, u v", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("every_type.ply");
  SECTION("big-endian") { write_bytes(path, every_type_ply(true)); }
  SECTION("little-endian") { write_bytes(path, every_type_ply(false)); }

  const matgeom::TriangleMesh mesh = matgeom::read_ply(path);
  CHECK(mesh.positions ==
        std::vector<glm::vec3>{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 3, 0.5f}});
  CHECK(mesh.normals == std::vector<glm::vec3>(5, glm::vec3(0, 0, 1)));
  CHECK(mesh.uvs ==
        std::vector<glm::vec2>{{0, 1}, {0.25f, 0.875f}, {0.5f, 0.75f}, {0.75f, 0.625f}, {1, 0.5f}});
  // The pentagon 0 1 2 4 3 fans around vertex 0.
  CHECK(mesh.triangles == std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 4}, {0, 4, 3}, {1, 3, 0}});
  CHECK(mesh.triangle_parts.empty());
  CHECK(mesh.part_names == std::vector<std::string>{"default"});
  CHECK(mesh.part_count() == 1);
}

TEST_CASE("PLY like Replica's semantic mesh: quads, colours, parts by object_id", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("mesh_semantic.ply");
  write_bytes(path, replica_like_ply());

  matgeom::PlyReadOptions options;
  SECTION("detected") {}
  SECTION("named") { options.face_id_property = "object_id"; }
  const matgeom::TriangleMesh mesh = matgeom::read_ply(path, options);
  REQUIRE(mesh.vertex_count() == 8);
  CHECK(mesh.positions[2] == glm::vec3(1, 1, 0));
  CHECK(mesh.positions[7] == glm::vec3(0, 1, 1));
  CHECK(mesh.normals == std::vector<glm::vec3>(8, glm::vec3(0, 0, 1)));
  CHECK(mesh.triangles ==
        std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}, {3, 2, 6}, {3, 6, 7}});
  // Ids sort as numbers: 3 before 12.
  CHECK(mesh.part_names == std::vector<std::string>{"object_3", "object_12"});
  CHECK(mesh.triangle_parts == std::vector<uint32_t>{1, 1, 0, 0, 1, 1});
  REQUIRE(mesh.colors.size() == 8);
  for (int v = 0; v < 8; ++v)
    for (int c = 0; c < 3; ++c) CHECK(mesh.colors[v][c] == Approx(srgb_byte_to_linear(static_cast<uint8_t>(40 * v + c))).epsilon(1e-6));

  SECTION("written and read again, the colours are the same bytes") {
    matgeom::write_ply(mesh, dir.file("again.ply"));
    CHECK(matgeom::read_ply(dir.file("again.ply")).colors == mesh.colors);
  }
}

TEST_CASE("PLY colours in floats, in ushorts, and as diffuse_red green blue", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("colours.ply");
  const std::string faces = "3 0 1 2\n";
  SECTION("floats are sRGB in 0..1, clamped") {
    write_bytes(path, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "property float red\nproperty float green\nproperty float blue\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n"
                      "0 0 0 0.5 1.5 -1\n1 0 0 0 0 0\n0 1 0 1 1 1\n" + faces);
    const matgeom::TriangleMesh mesh = matgeom::read_ply(path);
    REQUIRE(mesh.colors.size() == 3);
    CHECK(mesh.colors[0].x == Approx(std::pow((0.5 + 0.055) / 1.055, 2.4)).epsilon(1e-6));
    CHECK(mesh.colors[0].y == 1.0f);
    CHECK(mesh.colors[0].z == 0.0f);
  }
  SECTION("ushorts over 65535, with the diffuse_ prefix") {
    write_bytes(path, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "property ushort diffuse_red\nproperty ushort diffuse_green\nproperty ushort diffuse_blue\n"
                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0 65535 0 0\n1 0 0 0 65535 0\n0 1 0 0 0 65535\n" + faces);
    const matgeom::TriangleMesh mesh = matgeom::read_ply(path);
    CHECK(mesh.colors == std::vector<glm::vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  }
  SECTION("a file with only red and green has no colours") {
    write_bytes(path, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "property uchar red\nproperty uchar green\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n0 0 0 1 2\n1 0 0 1 2\n0 1 0 1 2\n" + faces);
    CHECK(matgeom::read_ply(path).colors.empty());
  }
}

TEST_CASE("PLY reader errors name the file and the problem", "[geom]") {
  TempDir dir;
  const std::string path = dir.file("broken.ply");

  SECTION("missing file") {
    CHECK_THAT(read_error(path), Contains(path) && Contains("no such file"));
  }
  SECTION("not PLY") {
    write_bytes(path, "solid cube\nfacet normal 0 0 1\n");
    CHECK_THAT(read_error(path), Contains(path) && Contains("not a PLY file"));
    write_bytes(path, "");
    CHECK_THAT(read_error(path), Contains(path) && Contains("not a PLY file"));
  }
  SECTION("unsupported format") {
    write_bytes(path, "ply\nformat binary_middle_endian 1.0\nend_header\n");
    CHECK_THAT(read_error(path), Contains(path) && Contains("unsupported format"));
    write_bytes(path, "ply\nformat ascii 2.0\nend_header\n");
    CHECK_THAT(read_error(path), Contains(path) && Contains("unsupported format"));
  }
  SECTION("unsupported property type") {
    std::string text = ascii_ply(3, 1, kTriangleBody);
    text.replace(text.find("float z"), 5, "float128");
    write_bytes(path, text);
    CHECK_THAT(read_error(path), Contains(path) && Contains("unsupported property type"));
  }
  SECTION("header without end_header") {
    write_bytes(path, "ply\nformat ascii 1.0\nelement vertex 3\n");
    CHECK_THAT(read_error(path), Contains(path) && Contains("truncated header"));
  }
  SECTION("missing z") {
    std::string text = ascii_ply(3, 1, "0 0\n1 0\n0 1\n3 0 1 2\n");
    text.erase(text.find("property float z\n"), 17);
    write_bytes(path, text);
    CHECK_THAT(read_error(path), Contains(path) && Contains("no property z"));
  }
  SECTION("missing face element") {
    write_bytes(path,
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                "property float y\nproperty float z\nend_header\n0 0 0\n");
    CHECK_THAT(read_error(path), Contains(path) && Contains("no face element"));
  }
  SECTION("zero faces") {
    write_bytes(path, ascii_ply(3, 0, "0 0 0\n1 0 0\n0 1 0\n"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("no faces"));
  }
  SECTION("face with two vertices") {
    write_bytes(path, ascii_ply(3, 2, "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("face 1 has 2 vertices"));
  }
  SECTION("vertex index out of range") {
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n"));
    CHECK_THAT(read_error(path),
               Contains(path) && Contains("face 0") && Contains("vertex index 9 out of range"));
  }
  SECTION("NaN vertex") {
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("non-finite vertex 1"));
  }
  SECTION("Inf vertex, ASCII and binary") {
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("non-finite vertex 2"));

    BinaryPly ply(true);
    ply.text(
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n");
    for (float value :
         {0.0f, 0.0f, 0.0f, 1.0f, std::numeric_limits<float>::infinity(), 0.0f, 0.0f, 1.0f, 0.0f}) {
      ply.f32(value);
    }
    ply.u8(3);
    for (int32_t corner : {0, 1, 2}) ply.i32(corner);
    write_bytes(path, ply.bytes());
    CHECK_THAT(read_error(path), Contains(path) && Contains("non-finite vertex 1"));
  }
  SECTION("malformed number") {
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 0.5.2 0\n0 1 0\n3 0 1 2\n"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("malformed number \"0.5.2\"") &&
                                     Contains("vertex 1, property y"));
    // Numbers the property's type cannot hold, reported as written with the type's range.
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"));
    CHECK_THAT(read_error(path), Contains(path + ": number \"300\" is outside a uchar's range [0, 255] (face 0, "
                                                 "property vertex_indices)"));
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 1e39 0\n0 1 0\n3 0 1 2\n"));
    CHECK_THAT(read_error(path), Contains(path + ": number \"1e39\" is beyond the range of a float (vertex 1, "
                                                 "property y)"));
  }
  SECTION("truncated ASCII") {
    write_bytes(path, ascii_ply(3, 1, "0 0 0\n1 0 0\n0 1 0\n3 0 1"));
    CHECK_THAT(read_error(path), Contains(path) && Contains("truncated") && Contains("face 0"));
  }
  SECTION("truncated binary") {
    const std::string whole = dir.file("whole.ply");
    matgeom::write_ply(three_part_mesh(), whole);
    std::string bytes = read_bytes(whole);
    bytes.resize(bytes.size() - 3);  // into the last face's part_id
    write_bytes(path, bytes);
    CHECK_THAT(read_error(path), Contains(path) && Contains("truncated") && Contains("face 3"));
  }
  SECTION("element count the file cannot hold") {
    std::string text = ascii_ply(3, 1, kTriangleBody);
    text.replace(text.find("vertex 3"), 8, "vertex 4000000000");
    write_bytes(path, text);
    REQUIRE(text.size() < 250);
    CHECK_THAT(read_error(path), Contains(path) && Contains("element vertex declares 4000000000") &&
                                     Contains("cannot hold"));
  }
  SECTION("list longer than sensible or than the file") {
    std::string text = ascii_ply(3, 1, kTriangleBody);
    text.replace(text.find("list uchar int"), 14, "list uint int");
    text.replace(text.rfind("3 0 1 2"), 1, "2000000");
    write_bytes(path, text);
    CHECK_THAT(read_error(path), Contains(path) && Contains("list of 2000000 items"));

    BinaryPly ply(false);
    ply.text(
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uint int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; ++i) ply.f32(static_cast<float>(i));
    ply.u32(1000);
    for (int32_t corner : {0, 1, 2}) ply.i32(corner);
    write_bytes(path, ply.bytes());
    CHECK_THAT(read_error(path),
               Contains(path) && Contains("truncated") && Contains("runs past the end"));
  }
  SECTION("part id outside the part table") {
    std::string text = ascii_ply(3, 1, "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 3\n");
    text.replace(text.find("element vertex"), 0, "comment part 0 only part\n");
    text.replace(text.find("end_header"), 0, "property uint part_id\n");
    write_bytes(path, text);
    CHECK_THAT(read_error(path), Contains(path) && Contains("part_id 3 is outside the part table"));
  }
  SECTION("named id property absent") {
    write_bytes(path, ascii_ply(3, 1, kTriangleBody));
    matgeom::PlyReadOptions options;
    options.face_id_property = "segment_id";
    CHECK_THAT(read_error(path, options), Contains(path) && Contains("no property segment_id"));
  }
}

TEST_CASE("PLY reader survives truncated and bit-flipped files", "[geom]") {
  TempDir dir;
  const std::string original_path = dir.file("original.ply");
  matgeom::write_ply(three_part_mesh(), original_path);
  const std::vector<std::string> originals = {read_bytes(original_path), kAsciiQuadAndTriangle,
                                              every_type_ply(true), replica_like_ply()};
  const std::string path = dir.file("damaged.ply");
  const auto read = [](const std::string& file) { return matgeom::read_ply(file); };
  for (const std::string& original : originals) {
    for (size_t length = 0; length < original.size(); ++length) {
      check_reads_or_rejects(path, original.substr(0, length), read);
    }

    std::mt19937 random(20240611u);
    for (int flip = 0; flip < 1000; ++flip) {
      std::string damaged = original;
      const size_t byte = random() % damaged.size();
      damaged[byte] = static_cast<char>(damaged[byte] ^ (1 << (random() % 8)));
      check_reads_or_rejects(path, damaged, read);
    }
  }
}
