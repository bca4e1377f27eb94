#pragma once
// Writes a mesh as Replica writes its scans (mesh_semantic.ply): binary little-endian, vertices
// x y z nx ny nz red green blue (uchar, sRGB), faces as a vertex_indices list and an int object_id
// taken from each part's name "object_<id>". Written here, byte by byte, not by matgeom's writer,
// so that tests read a scan laid out as the scanner lays it out.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "matgeom/mesh.h"

inline void write_replica_ply(const matgeom::TriangleMesh& mesh, const std::string& path) {
  if (mesh.normals.size() != mesh.positions.size() || mesh.colors.size() != mesh.positions.size())
    throw std::invalid_argument("write_replica_ply: the mesh needs normals and colours");
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(mesh.vertex_count()) +
      "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
      "property float nz\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face " +
      std::to_string(mesh.triangle_count()) + "\nproperty list uchar int vertex_indices\nproperty int object_id\nend_header\n";
  const auto put32 = [&bytes](uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<char>((value >> shift) & 0xff));
  };
  const auto put_float = [&put32](float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    put32(bits);
  };
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k) put_float(mesh.positions[v][k]);
    for (int k = 0; k < 3; ++k) put_float(mesh.normals[v][k]);
    for (int k = 0; k < 3; ++k) {
      // IEC 61966-2-1's sRGB encoding.
      const double c = std::fmin(std::fmax(static_cast<double>(mesh.colors[v][k]), 0.0), 1.0);
      const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
      bytes.push_back(static_cast<char>(static_cast<uint8_t>(std::lround(255.0 * encoded))));
    }
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    bytes.push_back(3);
    for (int k = 0; k < 3; ++k) put32(mesh.triangles[t][k]);
    const std::string& name = mesh.part_names.at(mesh.triangle_parts.empty() ? 0 : mesh.triangle_parts[t]);
    if (name.rfind("object_", 0) != 0) throw std::invalid_argument("write_replica_ply: part " + name + " is no object_<id>");
    put32(static_cast<uint32_t>(std::stoi(name.substr(7))));
  }
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("write_replica_ply: cannot write " + path);
}
