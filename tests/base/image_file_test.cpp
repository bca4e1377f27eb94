// Image files too short for the signatures the decoder looks for, and the formats it names
// instead of decoding: every one a problem in words, never an exception.
#include <catch2/catch.hpp>

#include <string>

#include "matbase/image/image_file.h"
#include "support/temp_dir.h"
#include "support/test_files.h"

namespace {

// The starts of a WebP file (its signature at byte 8) and of an AVIF file (its at byte 4).
const std::string kWebp = std::string("RIFF") + std::string(4, '\0') + "WEBPVP8 ";
const std::string kAvif = std::string(4, '\0') + "ftypavif";

}  // namespace

TEST_CASE("image files shorter than any signature are refused in words, whatever their bytes", "[base]") {
  const TempDir dir;
  // Every prefix of the signatures looked for beyond the first byte (WebP's at 8, AVIF's at 4),
  // and one-byte files: the fuzzer's '"' ended in std::out_of_range.
  for (const std::string& whole : {kWebp, kAvif, std::string("\"")})
    for (size_t length = 0; length <= whole.size(); ++length) {
      const std::string path = dir.file("short" + std::to_string(length) + ".png");
      write_bytes(path, whole.substr(0, length));
      matbase::ImagePixels pixels;
      std::optional<std::string> problem;
      REQUIRE_NOTHROW(problem = matbase::decode_image_file(path, "short", pixels));
      CHECK(problem.has_value());
    }
}

TEST_CASE("WebP and AVIF files are named, not decoded", "[base]") {
  CHECK_THAT(matbase::unread_image_format(kWebp).value_or(""), Catch::Matchers::StartsWith("a WebP image"));
  CHECK_THAT(matbase::unread_image_format(kAvif).value_or(""), Catch::Matchers::StartsWith("an AVIF or HEIF image"));
  CHECK_FALSE(matbase::unread_image_format("RIFF").has_value());
  CHECK_FALSE(matbase::unread_image_format("\"").has_value());
}
