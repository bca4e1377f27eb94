// Inputs the shared helpers guard against: paths that are not regular files (a device or a FIFO
// can block a reader or feed it forever), thread counts beyond the machine and allocations beyond
// its memory.
#include <catch2/catch.hpp>

#include <fstream>
#include <optional>
#include <string>
#include <stdexcept>

#include <sys/resource.h>
#include <sys/stat.h>

#include "matbase/file/input_file.h"
#include "matbase/memory_limit.h"
#include "matbase/threads.h"
#include "matgeom/io/gltf/gltf_reader.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/io/obj/obj_io.h"
#include "matgeom/io/ply/ply_io.h"
#include "support/temp_dir.h"

using Catch::Matchers::Contains;

TEST_CASE("Only regular files are input files", "[geom]") {
  const TempDir dir;
  const std::string file = dir.file("mesh.obj");
  std::ofstream(file) << "v 0 0 0\n";
  CHECK_FALSE(matbase::input_file_problem(file));
  CHECK(matbase::input_file_problem(dir.file("missing.obj")) == std::string("no such file"));
  CHECK(matbase::input_file_problem(dir.path().string()) == std::string("is a directory, not a file"));
  CHECK_THAT(*matbase::input_file_problem("/dev/zero"), Contains("not a regular file"));
  const std::string fifo = dir.file("fifo.obj");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THAT(*matbase::input_file_problem(fifo), Contains("not a regular file"));
}

TEST_CASE("Every mesh reader refuses a FIFO or a device without opening it", "[geom]") {
  // Opening a FIFO for reading blocks until a writer comes: reaching the check at all shows the
  // reader did not open it.
  const TempDir dir;
  const std::string fifo = dir.file("fifo");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {
    CAPTURE(path);
    // (Catch2's combined matchers hold references to their parts: each is written out.)
    CHECK_THROWS_WITH(matgeom::read_object(path), Contains(path + ": ") && Contains("not a regular file"));
    CHECK_THROWS_WITH(matgeom::read_obj(path), Contains(path + ": ") && Contains("not a regular file"));
    CHECK_THROWS_WITH(matgeom::read_gltf(path), Contains(path + ": ") && Contains("not a regular file"));
    CHECK_THROWS_WITH(matgeom::read_ply(path), Contains(path + ": ") && Contains("not a regular file"));
  }
}

TEST_CASE("Thread requests beyond the machine are capped to it", "[geom]") {
  const int hardware = matbase::hardware_threads();
  CHECK(hardware >= 1);
  CHECK(matbase::worker_threads(0) == hardware);
  CHECK(matbase::worker_threads(1) == 1);
  CHECK(matbase::worker_threads(1000000) == hardware);
  CHECK_THROWS_AS(matbase::worker_threads(-1), std::invalid_argument);
}

TEST_CASE("Allocations are checked against the memory this process can have", "[geom]") {
  CHECK(matbase::byte_size_text(512) == "512 bytes");
  CHECK(matbase::byte_size_text(6.0 * 1024 * 1024 * 1024) == "6.0 GiB");
  CHECK(matbase::byte_size_text(1536) == "1.5 KiB");
  CHECK_FALSE(matbase::memory_problem(1024.0, "a small image"));
  const std::optional<std::string> huge = matbase::memory_problem(1e18, "its 100000 x 100000 texels");
  REQUIRE(huge);
  CHECK_THAT(*huge, Catch::StartsWith("needs 888.2 PiB for its 100000 x 100000 texels, more than the ") &&
                        Catch::EndsWith(" of memory this process can have"));
  // ulimit -v counts: a lower address-space limit lowers what fits.
  rlimit saved{};
  REQUIRE(getrlimit(RLIMIT_AS, &saved) == 0);
  const rlimit lowered{rlim_t{1} << 40, saved.rlim_max};  // 1 TiB: more than the tests use
  if (saved.rlim_cur == RLIM_INFINITY || saved.rlim_cur > lowered.rlim_cur) {
    REQUIRE(setrlimit(RLIMIT_AS, &lowered) == 0);
    CHECK(matbase::memory_limit_bytes() <= lowered.rlim_cur);
    REQUIRE(setrlimit(RLIMIT_AS, &saved) == 0);
  }
}
