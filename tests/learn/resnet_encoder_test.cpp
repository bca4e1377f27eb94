// The ResNet-50 encoder (matlearn/models/resnet_encoder.h) against torchvision's resnet50 run by
// Debian's python3-torchvision: the same parameter and buffer names and shapes, and with the same
// weights, the same feature maps.
// libtorch includes glog, whose CHECK macro would replace Catch's (passing checks would vanish
// and failing ones abort): Catch's macros go by their CATCH_ names here.
#define CATCH_CONFIG_PREFIX_ALL
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "matlearn/models/resnet50_u.h"
#include "matlearn/models/resnet_encoder.h"
#include "matlearn/models/state_dict.h"
#include "regressor_checks.h"

using namespace matlearn;
namespace fs = std::filesystem;

namespace {

void run(const std::string& command) {
  if (std::system(command.c_str()) != 0) throw std::runtime_error(command + " failed (needs Debian's python3-torchvision)");
}

// Runs tests/learn/torchvision_resnet50.py once, and converts its torchvision weights with
// scripts/convert_torchvision_weights.py into weights.pt; returns the folder.
fs::path torchvision_reference() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / "matpredict_resnet50_reference";
    fs::create_directories(d);
    const std::string python = MATPREDICT_DEBIAN_PYTHON;
    run(python + " " + MATPREDICT_RESNET50_SCRIPT + " " + d.string());
    run(python + " " + MATPREDICT_CONVERT_SCRIPT + " resnet50 " + (d / "torchvision.pth").string() + " " +
        (d / "weights.pt").string() + " > /dev/null");
    return d;
  }();
  return dir;
}

// "(64,3,7,7)", "()" for a scalar: the format of names.txt.
std::string shape_text(const torch::Tensor& t) {
  std::string s = "(";
  for (int64_t i = 0; i < t.dim(); ++i) s += (i ? "," : "") + std::to_string(t.size(i));
  return s + ")";
}

std::map<std::string, torch::Tensor> tensors_in(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::map<std::string, torch::Tensor> tensors;
  for (const auto& e : torch::pickle_load(bytes).toGenericDict()) tensors[e.key().toStringRef()] = e.value().toTensor();
  return tensors;
}

}  // namespace

CATCH_TEST_CASE("The ResNet-50 encoder has torchvision's parameter names, shapes and count", "[learn]") {
  std::map<std::string, std::string> reference;
  std::ifstream names(torchvision_reference() / "names.txt");
  std::string name, shape;
  while (names >> name >> shape) reference[name] = shape;
  CATCH_REQUIRE(reference.size() == 318);

  ResNet50Encoder encoder;
  std::map<std::string, std::string> ours;
  int64_t parameter_count = 0;
  for (const auto& p : encoder->named_parameters()) {
    ours[p.key()] = shape_text(p.value());
    parameter_count += p.value().numel();
  }
  for (const auto& b : encoder->named_buffers()) ours[b.key()] = shape_text(b.value());
  CATCH_CHECK(ours == reference);
  CATCH_CHECK(parameter_count == 23508032);  // ../shared/reference/networks.md: encoder only
}

CATCH_TEST_CASE("With torchvision's weights the encoder computes torchvision's feature maps", "[learn]") {
  const fs::path dir = torchvision_reference();
  ResNet50Encoder encoder;
  load_state_dict(*encoder, dir / "weights.pt");
  encoder->eval();
  std::map<std::string, torch::Tensor> io = tensors_in(dir / "io.pt");
  torch::NoGradGuard no_grad;
  const ResNetFeatures f = encoder->forward(io.at("input"));
  const std::pair<const char*, torch::Tensor> stages[] = {
      {"stem", f.stem}, {"layer1", f.layer1}, {"layer2", f.layer2}, {"layer3", f.layer3}, {"layer4", f.layer4}};
  for (const auto& [stage, ours] : stages) {
    const torch::Tensor& theirs = io.at(stage);
    CATCH_REQUIRE(ours.sizes() == theirs.sizes());
    const double scale = std::max(1.0, theirs.abs().max().item<double>());
    const double difference = (ours - theirs).abs().max().item<double>();
    CATCH_INFO(stage << ": largest difference " << difference << " for values up to " << scale);
    CATCH_CHECK(difference <= 1e-4 * scale);
  }
}

CATCH_TEST_CASE("Weights that do not fit are an error naming the tensors", "[learn]") {
  const fs::path dir = torchvision_reference();
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
  CATCH_CHECK(torch::equal(other->named_parameters()["layer3.2.conv2.weight"], encoder->named_parameters()["layer3.2.conv2.weight"]));
}

CATCH_TEST_CASE("ResNet50-U has the reconstructed parameter count and full-resolution output", "[learn]") {
  check_regressor<ResNet50U>(39642470, 16, 64, 96);  // ../shared/reference/networks.md; the paper's 39.5M
}
