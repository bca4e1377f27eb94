#include "matbase/text_encoding.h"

#include <string>

#include <catch2/catch.hpp>

#include "matbase/file/file_error.h"

// Byte-order marks and UTF-8 checked against encodings written out by hand ("é" is U+00E9,
// UTF-8 C3 A9; the G clef U+1D11E is the UTF-16 pair D834 DD1E, UTF-8 F0 9D 84 9E).

using matbase::decode_marked_text;
using matbase::valid_utf8;

TEST_CASE("decode_marked_text reads the encodings byte-order marks name", "[base]") {
  std::string decoded;
  SECTION("no mark: the bytes as they are") {
    CHECK(!decode_marked_text("v 1 2 3", decoded));
    CHECK(decoded == "v 1 2 3");
  }
  SECTION("a UTF-8 mark is dropped") {
    CHECK(!decode_marked_text("\xEF\xBB\xBFv 1", decoded));
    CHECK(decoded == "v 1");
  }
  SECTION("UTF-16 little-endian") {
    CHECK(!decode_marked_text(std::string("\xFF\xFEv\0\xE9\0", 6), decoded));
    CHECK(decoded == "v\xC3\xA9");
    CHECK(matbase::byte_order_mark("\xFF\xFEv") == "UTF-16 (little-endian)");
  }
  SECTION("UTF-16 big-endian with a surrogate pair") {
    CHECK(!decode_marked_text(std::string("\xFE\xFF\0a\xD8\x34\xDD\x1E", 8), decoded));
    CHECK(decoded == "a\xF0\x9D\x84\x9E");
  }
  SECTION("UTF-32 little-endian, not mistaken for UTF-16") {
    CHECK(!decode_marked_text(std::string("\xFF\xFE\0\0" "a\0\0\0\x1E\xD1\x01\0", 12), decoded));
    CHECK(decoded == "a\xF0\x9D\x84\x9E");
  }
  SECTION("what does not hold is a problem in words") {
    const auto odd = decode_marked_text(std::string("\xFF\xFEv\0\xE9", 5), decoded);
    REQUIRE(odd);
    CHECK(*odd == "the text starts with a byte-order mark of UTF-16 (little-endian), but its length (5 bytes) is not a "
                  "whole number of 2-byte units");
    const auto unpaired = decode_marked_text(std::string("\xFF\xFE\x34\xD8v\0", 6), decoded);
    REQUIRE(unpaired);
    CHECK(*unpaired ==
          "the text starts with a byte-order mark of UTF-16 (little-endian), but it has an unpaired UTF-16 surrogate at byte 2");
  }
}

TEST_CASE("valid_utf8 escapes what is not UTF-8 and keeps what is", "[base]") {
  CHECK(valid_utf8("caf\xC3\xA9 \xF0\x9D\x84\x9E") == "caf\xC3\xA9 \xF0\x9D\x84\x9E");
  CHECK(valid_utf8("Bois_ch\xEAne") == "Bois_ch\\xEAne");   // Latin-1
  CHECK(valid_utf8("\xC0\xAF") == "\\xC0\\xAF");              // an overlong '/'
  CHECK(valid_utf8("\xED\xA0\x80") == "\\xED\\xA0\\x80");     // a surrogate
  CHECK(valid_utf8("\xE2\x82") == "\\xE2\\x82");              // cut short
}

TEST_CASE("messages about files stay valid UTF-8", "[base]") {
  CHECK(matbase::cut_short("ch\xEAne \xC3\xA9\t") == "ch\\xEAne \xC3\xA9\\x09");
  try {
    matbase::fail("dir\xFF/model.obj", "usemtl " + matbase::excerpt("ch\xEAne"));
  } catch (const std::runtime_error& error) {
    CHECK(std::string(error.what()) == "dir\\xFF/model.obj: usemtl \"ch\\xEAne\"");
  }
}
