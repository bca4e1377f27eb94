#pragma once
// The one robustness rule every mesh reader's test holds it to, on truncated, bit-flipped and
// fuzzed files: a reader gives a valid mesh with triangles (and, for an asset, a material for
// every part) or throws std::runtime_error whose message starts with the file's path. Another
// exception escapes and fails the test; a crash or a sanitizer report fails it too.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <catch2/catch.hpp>

#include "matgeom/mesh.h"
#include "matgeom/object_asset.h"
#include "support/test_files.h"

// `read(path)` returns a matgeom::ObjectAsset or a matgeom::TriangleMesh.
template <typename Read>
void check_reads_or_rejects(const std::string& path, Read read) {
  try {
    const auto result = read(path);
    if constexpr (std::is_same_v<std::decay_t<decltype(result)>, matgeom::ObjectAsset>) {
      CHECK_NOTHROW(matgeom::validate_mesh(result.mesh, path));
      CHECK(result.mesh.triangle_count() > 0);
      CHECK(result.materials.size() >= result.mesh.part_count());
    } else {
      CHECK_NOTHROW(matgeom::validate_mesh(result, path));
      CHECK(result.triangle_count() > 0);
    }
  } catch (const std::runtime_error& error) {
    CHECK_THAT(error.what(), Catch::Matchers::StartsWith(path + ": "));
  }
}

// The same for `bytes` written to `path` first, as a new file: rewriting a file that has data
// makes ext4 flush it at every close (auto_da_alloc), which makes thousands of variants slow.
template <typename Read>
void check_reads_or_rejects(const std::string& path, const std::string& bytes, Read read) {
  std::filesystem::remove(path);
  write_bytes(path, bytes);
  check_reads_or_rejects(path, read);
}
