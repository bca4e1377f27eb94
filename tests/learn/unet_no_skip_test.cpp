// UNet-no-skip (matlearn/models/unet_no_skip.h): its reconstructed parameter count and output.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include "matlearn/models/unet_no_skip.h"
#include "regressor_checks.h"

using namespace matlearn;

CATCH_TEST_CASE("UNet-no-skip has the reconstructed parameter count and full-resolution output", "[learn]") {
  check_regressor<UNetNoSkip>(23730758, 32, 32, 48);  // ../shared/reference/networks.md; the paper's 23.6M
}
