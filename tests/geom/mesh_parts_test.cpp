#include "matgeom/mesh_parts.h"

#include "matgeom/object_asset.h"

#include <algorithm>
#include <stdexcept>

#include <catch2/catch.hpp>

// Splitting by part and merging back, on a mesh whose parts interleave in triangle order and
// share vertices, so that re-indexing and the carried attributes are exercised.

using namespace matgeom;

namespace {

// A 4 x 3 grid of quads; quad (i, j) belongs to part (i + 2 j) % 3 and every vertex has
// distinct attributes, so any mix-up shows.
TriangleMesh interleaved_grid() {
  TriangleMesh mesh;
  const int nx = 4, ny = 3;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const float x = static_cast<float>(i), y = static_cast<float>(j);
      mesh.positions.emplace_back(x, y, 0.1f * x * y);
      mesh.normals.emplace_back(0.0f, 0.0f, 1.0f + x);
      mesh.uvs.emplace_back(x / nx, y / ny);
      mesh.tangents.emplace_back(1.0f, 0.0f, y, (i + j) % 2 ? 1.0f : -1.0f);
      mesh.colors.emplace_back(0.1f * x, 0.2f * y, 0.5f);
    }
  const auto index = [&](int i, int j) { return static_cast<uint32_t>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint32_t part = static_cast<uint32_t>((i + 2 * j) % 3);
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      mesh.triangles.emplace_back(index(i, j), index(i + 1, j + 1), index(i, j + 1));
      mesh.triangle_parts.push_back(part);
      mesh.triangle_parts.push_back(part);
    }
  mesh.part_names = {"frame", "seat", "back rest"};
  return mesh;
}

}  // namespace

TEST_CASE("Parts are compact meshes carrying the source attributes", "[geom]") {
  const TriangleMesh mesh = interleaved_grid();
  const std::vector<MeshPart> parts = split_parts(mesh);
  REQUIRE(parts.size() == 3);
  size_t triangles = 0;
  for (size_t k = 0; k < parts.size(); ++k) {
    const MeshPart& part = parts[k];
    CHECK(part.id == k);
    CHECK(part.name == mesh.part_names[k]);
    CHECK(part.mesh.part_names == std::vector<std::string>{mesh.part_names[k]});
    CHECK(part.mesh.triangle_parts.empty());
    validate_mesh(part.mesh, "part");
    REQUIRE(part.source_triangles.size() == part.mesh.triangle_count());
    REQUIRE(part.source_vertices.size() == part.mesh.vertex_count());
    // Compact: every vertex is used by some triangle of the part.
    std::vector<bool> used(part.mesh.vertex_count(), false);
    for (size_t t = 0; t < part.mesh.triangle_count(); ++t) {
      const uint32_t source = part.source_triangles[t];
      CHECK(mesh.triangle_parts[source] == k);
      if (t > 0) CHECK(part.source_triangles[t - 1] < source);  // source order kept
      for (int c = 0; c < 3; ++c) {
        const uint32_t v = part.mesh.triangles[t][c];
        used[v] = true;
        const uint32_t sv = mesh.triangles[source][c];
        CHECK(part.source_vertices[v] == sv);
        CHECK(part.mesh.positions[v] == mesh.positions[sv]);
        CHECK(part.mesh.normals[v] == mesh.normals[sv]);
        CHECK(part.mesh.uvs[v] == mesh.uvs[sv]);
        CHECK(part.mesh.tangents[v] == mesh.tangents[sv]);
        CHECK(part.mesh.colors[v] == mesh.colors[sv]);
      }
    }
    CHECK(std::find(used.begin(), used.end(), false) == used.end());
    triangles += part.mesh.triangle_count();
  }
  CHECK(triangles == mesh.triangle_count());
}

TEST_CASE("Merging the parts gives the input back", "[geom]") {
  const TriangleMesh mesh = interleaved_grid();
  const std::vector<MeshPart> parts = split_parts(mesh);
  const TriangleMesh merged = merge_parts(parts);
  REQUIRE(merged.triangle_count() == mesh.triangle_count());
  CHECK(merged.part_names == mesh.part_names);
  // Merged triangle n is source triangle parts[k].source_triangles[i], corner by corner.
  size_t n = 0;
  for (const MeshPart& part : parts)
    for (const uint32_t source : part.source_triangles) {
      CHECK(merged.triangle_parts[n] == mesh.triangle_parts[source]);
      for (int c = 0; c < 3; ++c) {
        const uint32_t a = merged.triangles[n][c], b = mesh.triangles[source][c];
        CHECK(merged.positions[a] == mesh.positions[b]);
        CHECK(merged.normals[a] == mesh.normals[b]);
        CHECK(merged.uvs[a] == mesh.uvs[b]);
        CHECK(merged.tangents[a] == mesh.tangents[b]);
        CHECK(merged.colors[a] == mesh.colors[b]);
      }
      ++n;
    }
  // Splitting the merged mesh again reproduces the parts exactly.
  const std::vector<MeshPart> again = split_parts(merged);
  REQUIRE(again.size() == parts.size());
  for (size_t k = 0; k < parts.size(); ++k) {
    CHECK(again[k].mesh.positions == parts[k].mesh.positions);
    CHECK(again[k].mesh.triangles == parts[k].mesh.triangles);
  }
}

TEST_CASE("Splitting handles sparse ids, no ids and empty meshes", "[geom]") {
  TriangleMesh mesh = interleaved_grid();
  for (uint32_t& part : mesh.triangle_parts) part = part * 1000000u + 7u;  // no names for these
  const std::vector<MeshPart> sparse = split_parts(mesh);
  REQUIRE(sparse.size() == 3);
  CHECK(sparse[0].id == 7u);
  CHECK(sparse[2].id == 2000007u);
  CHECK(sparse[0].name.empty());

  mesh.triangle_parts.clear();
  const std::vector<MeshPart> whole = split_parts(mesh);
  REQUIRE(whole.size() == 1);
  CHECK(whole[0].mesh.triangle_count() == mesh.triangle_count());
  CHECK(whole[0].mesh.vertex_count() == mesh.vertex_count());

  CHECK(split_parts(TriangleMesh()).empty());
  CHECK(merge_parts({}).triangle_count() == 0);

  std::vector<MeshPart> mixed = split_parts(interleaved_grid());
  mixed[1].mesh.uvs.clear();
  CHECK_THROWS_AS(merge_parts(mixed), std::invalid_argument);
}

TEST_CASE("An asset's kept parts are those parts alone, with their names and materials", "[geom]") {
  ObjectAsset asset;
  asset.mesh = interleaved_grid();
  for (const std::string& name : asset.mesh.part_names) asset.materials.emplace_back("material of " + name);
  asset.notes = {"a note"};
  const ObjectAsset kept = kept_parts(asset, {true, false, true});
  validate_mesh(kept.mesh, "kept");
  CHECK(kept.mesh.part_names == std::vector<std::string>{"frame", "back rest"});
  REQUIRE(kept.materials.size() == 2);
  CHECK(kept.materials[0].name == "material of frame");
  CHECK(kept.materials[1].name == "material of back rest");
  CHECK(kept.notes == asset.notes);
  // Each kept triangle is a source triangle of its part, its corners' attributes carried over.
  size_t expected = 0;
  for (const uint32_t part : asset.mesh.triangle_parts) expected += part != 1;
  CHECK(kept.mesh.triangle_count() == expected);
  const std::vector<MeshPart> source = split_parts(asset.mesh);
  CHECK(split_parts(kept.mesh)[1].mesh.positions == source[2].mesh.positions);
  CHECK(split_parts(kept.mesh)[1].mesh.colors == source[2].mesh.colors);
  // Fewer flags than parts drop the parts beyond them; keeping nothing is refused.
  CHECK(kept_parts(asset, {false, true}).mesh.part_names == std::vector<std::string>{"seat"});
  CHECK_THROWS_AS(kept_parts(asset, {false, false, false}), std::invalid_argument);
  CHECK_THROWS_AS(kept_parts(asset, {}), std::invalid_argument);
}

TEST_CASE("Parts are found by name, and the first name missing is said", "[geom]") {
  const TriangleMesh mesh = interleaved_grid();
  const NamedParts found = named_parts(mesh, {"back rest", "frame"});
  CHECK(found.named == std::vector<bool>{true, false, true});
  CHECK_FALSE(found.missing);
  const NamedParts missing = named_parts(mesh, {"seat", "armrest", "legs"});
  CHECK(missing.named == std::vector<bool>{false, true, false});
  CHECK(missing.missing == std::optional<std::string>("armrest"));
}
