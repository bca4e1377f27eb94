// Numbers read whole from text, and the sentences that refuse them.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <string>

#include "matbase/number_text.h"

using matbase::finite_number;
using matbase::whole_number;

TEST_CASE("whole numbers are read whole or not at all", "[base]") {
  CHECK(whole_number("42") == 42);
  CHECK(whole_number("-9223372036854775808") == std::numeric_limits<int64_t>::min());
  for (const char* text : {"", "12a", "1.0", " 1", "9223372036854775808", "+-1"}) {
    INFO(text);
    CHECK_FALSE(whole_number(text).has_value());
  }
  CHECK(matbase::unsigned_whole_number("18446744073709551615") == std::numeric_limits<uint64_t>::max());
  CHECK_FALSE(matbase::unsigned_whole_number("-1").has_value());
}

TEST_CASE("finite numbers refuse infinities, NaN and trailing text", "[base]") {
  CHECK(finite_number("0.25") == 0.25);
  CHECK(finite_number("-1e3") == -1000.0);
  for (const char* text : {"inf", "nan", "1e309", "0.5x", ""}) {
    INFO(text);
    CHECK_FALSE(finite_number(text).has_value());
  }
}

TEST_CASE("refusals state the range as a sentence and quote the value", "[base]") {
  CHECK_FALSE(matbase::whole_number_problem("7", 1, 65536).has_value());
  CHECK(matbase::whole_number_problem("99999999999", 1, 65536) ==
        "expected a whole number from 1 to 65,536, got 99999999999");
  CHECK(matbase::whole_number_problem("", 0, 10) == "expected a whole number from 0 to 10, got nothing");
  CHECK(matbase::seed_problem("-1") == "expected a whole number from 0 to 18,446,744,073,709,551,615, got -1");
  CHECK(matbase::number_problem("2", 0.0, 1.0, false) == "expected a number from 0 to 1, got 2");
  CHECK(matbase::number_problem("0", 0.0, 1.5, true) == "expected a number greater than 0 and at most 1.5, got 0");
  const std::string long_text(50, '9');
  CHECK(matbase::number_problem(long_text + "x", 0.0, 1.0, false) ==
        "expected a number from 0 to 1, got " + std::string(37, '9') + "...");
}

TEST_CASE("thousands are grouped by commas, down to the most negative number", "[base]") {
  CHECK(matbase::with_thousands(0) == "0");
  CHECK(matbase::with_thousands(999) == "999");
  CHECK(matbase::with_thousands(1234567) == "1,234,567");
  CHECK(matbase::with_thousands(std::numeric_limits<int64_t>::min()) == "-9,223,372,036,854,775,808");
}
