// An output folder is checked before any work: a folder, or one that can be made, is fine; a file
// where the folder or one of its parents should be is named.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "matbase/file/output_folder.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

TEST_CASE("an output folder that exists or can be made passes, a file in its way is named", "[base]") {
  const TempDir dir;
  CHECK_FALSE(matbase::output_folder_problem(dir.path().string()).has_value());
  CHECK_FALSE(matbase::output_folder_problem(dir.file("new/deeper")).has_value());
  write_text(dir.file("out.png"), "not a folder");
  CHECK(matbase::output_folder_problem(dir.file("out.png")) == dir.file("out.png") + " is a file, not a folder");
  CHECK(matbase::output_folder_problem(dir.file("out.png/dataset/more")) ==
        dir.file("out.png/dataset/more") + ": " + dir.file("out.png") + " is a file, so no folder can be made in it");
  CHECK_FALSE(std::filesystem::exists(dir.file("new")));  // checking makes nothing
}
