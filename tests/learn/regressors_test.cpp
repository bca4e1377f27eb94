// The six regressors of matlearn/models/regressor.h: parameter counts (the paper's four within 2 %
// of its table, the repository's two as it counts them), a head that alone depends on the output
// count, full-resolution output, and the table of names.
// libtorch includes glog, whose CHECK would replace Catch's: Catch's macros go by CATCH_ names.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <cmath>

#include "matlearn/models/regressor.h"
#include "regressor_checks.h"

using namespace matlearn;

namespace {

// The paper's table of parameter counts (millions) against ours for 6 outputs.
void check_paper_count(Architecture architecture, double paper_millions) {
  const double ours = static_cast<double>(parameter_count(*make_regressor(architecture, 6)));
  CATCH_INFO(info(architecture).name << ": " << ours << " parameters, paper " << paper_millions << "M");
  CATCH_CHECK(std::abs(ours / (paper_millions * 1e6) - 1.0) <= 0.02);
}

}  // namespace

// Counts from docs/networks.md, which reconstructs the designs from the paper.
CATCH_TEST_CASE("UNet-no-skip: count, head and output", "[learn]") {
  check_regressor(Architecture::unet_no_skip, 23730758, 32, 32, 48);
  check_paper_count(Architecture::unet_no_skip, 23.6);
  // The quarter-width network of the quick default: every width divided by 4.
  const auto quarter = make_regressor(Architecture::unet_no_skip, 6, 4);
  CATCH_CHECK(parameter_count(*quarter) < 1600000);
  CATCH_CHECK(parameter_count(*quarter) > 1400000);
}

CATCH_TEST_CASE("ResNet50-U: count, head and output", "[learn]") {
  check_regressor(Architecture::resnet50_u, 39642470, 16, 64, 96);
  check_paper_count(Architecture::resnet50_u, 39.5);
}

CATCH_TEST_CASE("Swin-T-U: count, head and output", "[learn]") {
  check_regressor(Architecture::swin_t_u, 31742688, 24, 64, 96);
  check_paper_count(Architecture::swin_t_u, 31.6);
}

CATCH_TEST_CASE("ConvNeXt-T-U: count, head and output", "[learn]") {
  check_regressor(Architecture::convnext_t_u, 32041926, 24, 64, 96);
  check_paper_count(Architecture::convnext_t_u, 32.0);
}

CATCH_TEST_CASE("The repository's two networks have its parameter counts", "[learn]") {
  // docs/networks.md: the repository's ResNet50UNet 67,137,605 with 5 outputs; SwinTUNet
  // 45,040,448 with 6 on timm's trunk, plus the final LayerNorm (2 x 768) ours keeps.
  CATCH_CHECK(parameter_count(*make_regressor(Architecture::repo_resnet50_unet, 5)) == 67137605);
  check_regressor(Architecture::repo_swin_t_unet, 45040448 + 1536, 32, 64, 96);
  // A side that is not a multiple of 32 still comes out at full resolution: the UpBlocks resize.
  const auto resnet = make_regressor(Architecture::repo_resnet50_unet, 5);
  resnet->eval();
  torch::NoGradGuard no_grad;
  CATCH_CHECK(resnet->forward(torch::randn({1, 3, 64, 64})).sizes() == torch::IntArrayRef({1, 5, 64, 64}));
}

CATCH_TEST_CASE("Networks are found by name, and unknown names and bad widths are errors", "[learn]") {
  for (const ArchitectureInfo& a : architectures()) CATCH_CHECK(architecture_named(a.name).architecture == a.architecture);
  CATCH_CHECK_THROWS_WITH(architecture_named("resnet51"), Catch::Contains("resnet51") && Catch::Contains("swin_t_u"));
  CATCH_CHECK_THROWS(make_regressor(Architecture::swin_t_u, 6, 4));
  CATCH_CHECK_THROWS(make_regressor(Architecture::unet_no_skip, 6, 3));
  // Pretrainable trunks expose themselves for converted torchvision weights; UNet-no-skip has none.
  CATCH_CHECK(make_regressor(Architecture::unet_no_skip, 6)->encoder() == nullptr);
  CATCH_CHECK(make_regressor(Architecture::convnext_t_u, 6)->encoder() != nullptr);
}
