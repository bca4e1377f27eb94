// The ResNet-50 encoder (matlearn/models/resnet_encoder.h) against torchvision's resnet50, the
// strict state-dict loading.
// libtorch includes glog, whose CHECK macro would replace Catch's (passing checks would vanish
// and failing ones abort): Catch's macros go by their CATCH_ names here.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <fstream>

#include "matlearn/models/resnet_encoder.h"
#include "matlearn/models/state_dict.h"
#include "torchvision_reference.h"

using namespace matlearn;
namespace fs = std::filesystem;

CATCH_TEST_CASE("The ResNet-50 encoder has torchvision's parameter names, shapes and count", "[learn]") {
  // docs/networks.md: 23,508,032 for conv1 .. layer4.
  torchvision_reference::check_names_and_count(*ResNet50Encoder(), "resnet50", 318, 23508032);
}

CATCH_TEST_CASE("With torchvision's weights the ResNet-50 encoder computes torchvision's feature maps", "[learn]") {
  ResNet50Encoder encoder;
  torchvision_reference::check_stage_outputs(encoder, "resnet50", [&](const torch::Tensor& input) {
    const ResNetFeatures f = encoder->forward(input);
    return std::vector<std::pair<std::string, torch::Tensor>>{
        {"stem", f.stem}, {"layer1", f.layer1}, {"layer2", f.layer2}, {"layer3", f.layer3}, {"layer4", f.layer4}};
  });
}

CATCH_TEST_CASE("Weights that do not fit are an error naming the tensors", "[learn]") {
  const fs::path dir = torchvision_reference::folder("resnet50");
  ResNet50Encoder encoder;
  // A state dict with one tensor of the wrong shape and one unknown name.
  c10::Dict<std::string, torch::Tensor> dict;
  for (const auto& p : encoder->named_parameters()) dict.insert(p.key(), p.value().detach());
  for (const auto& b : encoder->named_buffers()) dict.insert(b.key(), b.value().detach());
  dict.insert_or_assign("conv1.weight", torch::zeros({64, 3, 3, 3}));
  dict.insert("fc.weight", torch::zeros({1000, 2048}));
  const std::vector<char> bytes = torch::pickle_save(dict);
  std::ofstream(dir / "bad.pt", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  CATCH_CHECK_THROWS_WITH(load_state_dict(*encoder, dir / "bad.pt"),
                          Catch::Contains("conv1.weight") && Catch::Contains("unexpected fc.weight"));
  std::ofstream(dir / "garbage.pt") << "not a tensor file";
  CATCH_CHECK_THROWS_WITH(load_state_dict(*encoder, dir / "garbage.pt"), Catch::Contains("garbage.pt"));
  // A round trip through save_state_dict.
  ResNet50Encoder other;
  save_state_dict(*encoder, dir / "round_trip.pt");
  load_state_dict(*other, dir / "round_trip.pt");
  CATCH_CHECK(torch::equal(other->named_parameters()["layer3.2.conv2.weight"],
                           encoder->named_parameters()["layer3.2.conv2.weight"]));
}
