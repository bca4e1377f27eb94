// Files appear whole or not at all: a failed write leaves the destination as it was and no
// temporary behind.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "matbase/file/atomic_file.h"

namespace fs = std::filesystem;

namespace {

struct TemporaryFolder {
  fs::path path = fs::temp_directory_path() / ("matgeom_atomic_" + std::to_string(::getpid()));
  TemporaryFolder() { fs::create_directories(path); }
  ~TemporaryFolder() { fs::remove_all(path); }
  size_t entries() const { return static_cast<size_t>(std::distance(fs::directory_iterator(path), {})); }
};

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("The temporary of a file sits beside it, hidden, with its extension", "[geom]") {
  const fs::path temporary = matbase::temporary_path("/data/out/mesh.glb");
  CHECK(temporary.parent_path() == "/data/out");
  CHECK(temporary.extension() == ".glb");
  CHECK(temporary.filename().string().rfind(".mesh.tmp-", 0) == 0);
}

TEST_CASE("Stale temporaries are removed: a dead process's always, any process's when asked", "[geom]") {
  TemporaryFolder folder;
  const fs::path file = folder.path / "007.png";
  const std::string mine = matbase::temporary_path(file).filename().string();
  // This machine's tag, then the id of a process that cannot exist (beyond Linux's pid_max).
  const std::string tag = mine.substr(std::string(".007.tmp-").size(), mine.rfind('-') - std::string(".007.tmp-").size());
  const fs::path dead = folder.path / (".007.tmp-" + tag + "-99999999.png");
  const fs::path elsewhere = folder.path / ".007.tmp-othernode-12.png";
  const fs::path own = folder.path / mine;
  const fs::path other_file = folder.path / ".008.tmp-othernode-12.png";
  for (const fs::path& p : {dead, elsewhere, own, other_file}) matbase::write_file_atomically(p, "x");
  matbase::remove_stale_temporaries(file, false);
  CHECK_FALSE(fs::exists(dead));
  CHECK(fs::exists(elsewhere));  // another machine's process may still be writing it
  CHECK(fs::exists(own));        // this process's own
  matbase::remove_stale_temporaries(file, true);
  CHECK_FALSE(fs::exists(elsewhere));
  CHECK_FALSE(fs::exists(own));
  CHECK(fs::exists(other_file));  // another file's temporary is never touched
}

TEST_CASE("write_atomically replaces a file whole, or leaves it as it was", "[geom]") {
  TemporaryFolder folder;
  const fs::path file = folder.path / "report.csv";
  matbase::write_file_atomically(file, "first");
  matbase::write_file_atomically(file, "second");
  CHECK(contents(file) == "second");
  CHECK(folder.entries() == 1);

  // A writer that fails half-way: the old file stays, nothing else is left.
  CHECK_THROWS_WITH(matbase::write_atomically(file,
                                              [](const fs::path& temporary) {
                                                std::ofstream(temporary) << "half";
                                                throw std::runtime_error("disk full");
                                              }),
                    "disk full");
  CHECK(contents(file) == "second");
  CHECK(folder.entries() == 1);

  // A missing folder is an error naming the file, and nothing is created.
  CHECK_THROWS_AS(matbase::write_file_atomically(folder.path / "missing" / "x.txt", "x"), std::runtime_error);
  CHECK(folder.entries() == 1);
  // A destination that is a folder cannot be replaced: named in the error, temporary removed.
  fs::create_directories(folder.path / "occupied");
  try {
    matbase::write_file_atomically(folder.path / "occupied", "x");
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).rfind((folder.path / "occupied").string(), 0) == 0);
  }
  CHECK(folder.entries() == 2);
}

TEST_CASE("An AtomicFileSet makes its files appear together or not at all", "[geom]") {
  TemporaryFolder folder;
  {
    matbase::AtomicFileSet files(folder.path / "object.obj");
    files.stage(folder.path / "object.mtl", "mtl");
    files.stage(folder.path / "object.obj", "obj");
    CHECK(!fs::exists(folder.path / "object.obj"));
    files.commit();
  }
  CHECK(contents(folder.path / "object.mtl") == "mtl");
  CHECK(contents(folder.path / "object.obj") == "obj");
  {
    // Staged but never committed: removed, the committed files untouched.
    matbase::AtomicFileSet files(folder.path / "object.obj");
    files.stage(folder.path / "object.obj", "new");
  }
  CHECK(contents(folder.path / "object.obj") == "obj");
  CHECK(folder.entries() == 2);
  {
    // The second rename fails: the first file, which this commit created, is removed again.
    fs::create_directories(folder.path / "blocked.obj");
    matbase::AtomicFileSet files(folder.path / "blocked.obj");
    files.stage(folder.path / "blocked.mtl", "mtl");
    files.stage(folder.path / "blocked.obj", "obj");
    CHECK_THROWS_AS(files.commit(), std::runtime_error);
  }
  CHECK(!fs::exists(folder.path / "blocked.mtl"));
  CHECK(folder.entries() == 3);
}

TEST_CASE("A signal handler can remove the temporaries being written, and only those", "[geom]") {
  TemporaryFolder folder;
  matbase::write_file_atomically(folder.path / "done.txt", "done");
  // Called where a handler would run: in the middle of writing one file, with a set staged.
  matbase::AtomicFileSet set(folder.path / "view.png");
  set.stage(folder.path / "view.exr", "exr");
  CHECK_THROWS_WITH(matbase::write_atomically(folder.path / "big.bin",
                                              [&](const fs::path& temporary) {
                                                std::ofstream(temporary) << "half";
                                                CHECK(folder.entries() == 3);
                                                matbase::remove_temporaries_in_flight();
                                                CHECK(!fs::exists(temporary));
                                                throw std::runtime_error("ended");
                                              }),
                    "ended");
  // Only the finished file is left: the set's staged temporary went too.
  CHECK(folder.entries() == 1);
  CHECK(contents(folder.path / "done.txt") == "done");
  // Renamed files are forgotten: removing again touches nothing that is done.
  matbase::write_file_atomically(folder.path / "later.txt", "later");
  matbase::remove_temporaries_in_flight();
  CHECK(contents(folder.path / "later.txt") == "later");
}
