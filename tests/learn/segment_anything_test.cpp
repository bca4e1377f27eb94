// Segment Anything's prompt encoder and mask decoder: the official module layout (names, shapes
// and parameter counts measured from facebookresearch/segment-anything's own model, in
// tests/learn/data/segment_anything), what prompts become, and the way masks come back to the
// photograph against the closed form of bilinear interpolation.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <torch/torch.h>

#include "matlearn/evaluation/segmenter_choice.h"
#include "matlearn/models/segment_anything/sam_frame.h"
#include "matlearn/models/segment_anything/sam_mask_decoder.h"
#include "matlearn/models/segment_anything/sam_prompt_encoder.h"
#include "matlearn/models/segment_anything/sam_segmenter.h"
#include "matlearn/models/segment_anything/sam_tiny_vit_encoder.h"
#include "matlearn/models/segment_anything/sam_vit_encoder.h"
#include "matlearn/models/segment_anything/segment_anything.h"
#include "matlearn/models/state_dict.h"

namespace {

// The official state_dict's entries under `prefix` ("prompt_encoder."), name -> shape text "(a, b)".
std::map<std::string, std::string> official_entries(const std::string& file, const std::string& prefix) {
  std::ifstream in(std::string(MATPREDICT_SAM_DATA) + "/" + file);
  REQUIRE(in);
  std::map<std::string, std::string> entries;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const size_t tab = line.find('\t');
    if (line.compare(0, prefix.size(), prefix) == 0) entries[line.substr(prefix.size(), tab - prefix.size())] = line.substr(tab + 1);
  }
  return entries;
}

std::string shape_text(const torch::Tensor& t) {
  std::string text = "(";
  for (int64_t d = 0; d < t.dim(); ++d) text += (d ? ", " : "") + std::to_string(t.size(d));
  return text + (t.dim() == 1 ? ",)" : ")");
}

std::map<std::string, std::string> our_entries(const torch::nn::Module& module) {
  std::map<std::string, std::string> entries;
  for (const auto& p : module.named_parameters()) entries[p.key()] = shape_text(p.value());
  for (const auto& b : module.named_buffers()) entries[b.key()] = shape_text(b.value());
  return entries;
}

int64_t parameter_count(const torch::nn::Module& module) {
  int64_t count = 0;
  for (const auto& p : module.parameters()) count += p.numel();
  return count;
}

}  // namespace

TEST_CASE("the prompt encoder and mask decoder are laid out as the official ones", "[segment_anything]") {
  matlearn::SamPromptEncoder prompt_encoder;
  matlearn::SamMaskDecoder mask_decoder;
  // Measured by building the official vit_b and vit_t models (the two share both modules).
  CHECK(parameter_count(*prompt_encoder) == 6220);
  CHECK(parameter_count(*mask_decoder) == 4058340);
  for (const char* file : {"vit_b_state_dict.tsv", "vit_t_state_dict.tsv"}) {
    CHECK(our_entries(*prompt_encoder) == official_entries(file, "prompt_encoder."));
    CHECK(our_entries(*mask_decoder) == official_entries(file, "mask_decoder."));
  }
}

TEST_CASE("prompts become tokens: a box's two corners, points with a padding point", "[segment_anything]") {
  torch::manual_seed(1);
  matlearn::SamPromptEncoder encoder;
  torch::NoGradGuard no_grad;
  const torch::Tensor box = torch::tensor({{100.0f, 200.0f, 600.0f, 900.0f}});
  const matlearn::SamPromptTokens boxed = encoder->forward(std::nullopt, std::nullopt, box);
  CHECK(boxed.sparse.sizes() == torch::IntArrayRef({1, 2, 256}));
  CHECK(boxed.dense.sizes() == torch::IntArrayRef({1, 256, 64, 64}));
  const torch::Tensor points = torch::tensor({{{10.0f, 20.0f}, {500.0f, 300.0f}}});
  const matlearn::SamPromptTokens on = encoder->forward(points, torch::tensor({{1, 1}}), std::nullopt);
  const matlearn::SamPromptTokens off = encoder->forward(points, torch::tensor({{0, 1}}), std::nullopt);
  REQUIRE(on.sparse.sizes() == torch::IntArrayRef({1, 3, 256}));
  // The padding point's token is "not a point", whatever its position.
  const auto weight = [&](const char* name) { return encoder->named_parameters()[name]; };
  CHECK(torch::allclose(on.sparse[0][2], weight("not_a_point_embed.weight")[0]));
  // A point's label adds its kind's embedding to the same position encoding.
  CHECK(torch::allclose(on.sparse[0][0] - off.sparse[0][0],
                        weight("point_embeddings.1.weight")[0] - weight("point_embeddings.0.weight")[0], 1e-5, 1e-6));
  CHECK(torch::equal(on.sparse[0][1], off.sparse[0][1]));
  // With a box no padding point is added: two points, two corners.
  CHECK(encoder->forward(points, torch::tensor({{1, 1}}), box).sparse.size(1) == 4);
  // Random Fourier features are sines and cosines: each pair's squares sum to 1.
  const torch::Tensor grid = encoder->dense_positional_encoding();
  CHECK(grid.sizes() == torch::IntArrayRef({1, 256, 64, 64}));
  CHECK(torch::allclose(grid.slice(1, 0, 128).pow(2) + grid.slice(1, 128, 256).pow(2), torch::ones({1, 128, 64, 64}), 1e-5, 1e-5));
}

TEST_CASE("the mask decoder gives four masks of 256 x 256 and their IoU scores", "[segment_anything]") {
  torch::manual_seed(2);
  matlearn::SamPromptEncoder encoder;
  matlearn::SamMaskDecoder decoder;
  torch::NoGradGuard no_grad;
  const matlearn::SamPromptTokens tokens = encoder->forward(std::nullopt, std::nullopt, torch::tensor({{100.0f, 200.0f, 600.0f, 900.0f}}));
  const torch::Tensor image = torch::randn({1, 256, 64, 64});
  const matlearn::SamMasks masks = decoder->forward(image, encoder->dense_positional_encoding(), tokens.sparse, tokens.dense);
  CHECK(masks.logits.sizes() == torch::IntArrayRef({1, 4, 256, 256}));
  CHECK(masks.iou.sizes() == torch::IntArrayRef({1, 4}));
  CHECK(torch::isfinite(masks.logits).all().item<bool>());
  // Two prompts on one image decode as each alone.
  const torch::Tensor two = torch::cat({tokens.sparse, tokens.sparse.flip(1)});
  const matlearn::SamMasks both = decoder->forward(image, encoder->dense_positional_encoding(), two, tokens.dense.expand({2, -1, -1, -1}));
  CHECK(torch::allclose(both.logits[0], masks.logits[0], 1e-4, 1e-4));
}

TEST_CASE("SamFrame resizes the longer side to 1024 as the official transform rounds", "[segment_anything]") {
  const auto size = [](int64_t h, int64_t w) {
    const matlearn::SamFrame frame = matlearn::SamFrame::of(h, w);
    return std::make_pair(frame.resized_height, frame.resized_width);
  };
  CHECK(size(480, 640) == std::make_pair<int64_t, int64_t>(768, 1024));
  CHECK(size(333, 500) == std::make_pair<int64_t, int64_t>(682, 1024));
  CHECK(size(1500, 1000) == std::make_pair<int64_t, int64_t>(1024, 683));
  CHECK(size(700, 701) == std::make_pair<int64_t, int64_t>(1023, 1024));
  const torch::Tensor point = matlearn::SamFrame::of(480, 640).to_input(torch::tensor({{320.0f, 100.0f}}));
  CHECK(torch::allclose(point, torch::tensor({{512.0f, 160.0f}})));
}

TEST_CASE("mask logits come back to the photograph by bilinear interpolation between pixel centres", "[segment_anything]") {
  // 2 x 2 logits over the 1024 input: rows are y. Upsampled 512x, output pixel o samples the
  // source at (o + 1/2) / 512 - 1/2, clamped to [0, 1]: weight w(o) of the second row or column.
  const torch::Tensor logits = torch::tensor({{-1.0f, 3.0f}, {1.0f, -3.0f}}).view({1, 1, 2, 2});
  const auto w = [](int64_t o) { return std::clamp((static_cast<double>(o) + 0.5) / 512.0 - 0.5, 0.0, 1.0); };
  const auto expected = [&](int64_t x, int64_t y) {
    return (1 - w(y)) * ((1 - w(x)) * -1.0 + w(x) * 3.0) + w(y) * ((1 - w(x)) * 1.0 + w(x) * -3.0);
  };
  // A square photograph of 1024: nothing cut, nothing resized.
  const torch::Tensor square = matlearn::SamFrame::of(1024, 1024).logits_at_photo_size(logits)[0][0];
  REQUIRE(square.sizes() == torch::IntArrayRef({1024, 1024}));
  for (const int64_t x : {0, 255, 256, 300, 511, 512, 520, 767, 768, 1023})
    for (const int64_t y : {0, 200, 256, 511, 513, 700, 1023})
      CHECK(square[y][x].item<double>() == Approx(expected(x, y)).margin(1e-5));
  // The object (> 0): top right and bottom left; at the centre the sign turns with the weights.
  CHECK(square[0][1023].item<float>() > 0);
  CHECK(square[1023][0].item<float>() > 0);
  CHECK(square[0][0].item<float>() < 0);
  CHECK((square[511][511].item<float>() > 0) == (expected(511, 511) > 0));
  CHECK((square[520][520].item<float>() > 0) == (expected(520, 520) > 0));
  CHECK(expected(520, 520) < 0);
  // A 512 x 1024 photograph fills the input's top half: the bottom half is cut and nothing resized.
  const torch::Tensor wide = matlearn::SamFrame::of(512, 1024).logits_at_photo_size(logits)[0][0];
  REQUIRE(wide.sizes() == torch::IntArrayRef({512, 1024}));
  CHECK(torch::allclose(wide, square.slice(0, 0, 512)));
}

TEST_CASE("the ViT-B image encoder is laid out as the official one", "[segment_anything]") {
  matlearn::SamVitEncoder encoder;
  // Measured by building the official vit_b model.
  CHECK(parameter_count(*encoder) == 89670912);
  CHECK(our_entries(*encoder) == official_entries("vit_b_state_dict.tsv", "image_encoder."));
}

TEST_CASE("the ViT encoder's windows, padding and global blocks", "[segment_anything]") {
  torch::manual_seed(3);
  torch::NoGradGuard no_grad;
  // A small encoder of the same design: 80 px in 16 px patches, a 5 x 5 grid.
  matlearn::SamVitConfig small;
  small.image_side = 80;
  small.dim = 32;
  small.depth = 2;
  small.heads = 2;
  small.window = 2;  // 5 is no multiple of 2: every windowed block pads to 6 x 6
  small.global_blocks = {1};
  small.out_channels = 16;
  matlearn::SamVitEncoder encoder(small);
  for (auto& p : encoder->parameters()) p.normal_(0.0, 0.2);  // the relative positions too
  const torch::Tensor image = torch::randn({2, 3, 80, 80});
  const torch::Tensor out = encoder->forward(image);
  CHECK(out.sizes() == torch::IntArrayRef({2, 16, 5, 5}));
  CHECK(torch::isfinite(out).all().item<bool>());
  // Each image of a batch is encoded alone.
  CHECK(torch::allclose(encoder->forward(image.slice(0, 1, 2)), out.slice(0, 1, 2), 1e-4, 1e-5));

  // One window over the whole grid is global attention.
  matlearn::SamVitBlock windowed(32, 2, 5, 5), global(32, 2, 0, 5);
  for (auto& p : windowed->parameters()) p.normal_(0.0, 0.2);
  auto source = windowed->named_parameters();
  for (auto& p : global->named_parameters()) p.value().copy_(source[p.key()]);
  const torch::Tensor tokens = torch::randn({1, 5, 5, 32});
  CHECK(torch::allclose(windowed->forward(tokens), global->forward(tokens), 1e-5, 1e-6));
  // Windows see only their own tokens: changing a token of the last window leaves the first's.
  matlearn::SamVitBlock small_windows(32, 2, 2, 5);
  for (auto& p : small_windows->parameters()) p.normal_(0.0, 0.2);
  torch::Tensor changed = tokens.clone();
  changed[0][4][4] += 1.0;
  const torch::Tensor before = small_windows->forward(tokens), after = small_windows->forward(changed);
  CHECK(torch::equal(before.slice(1, 0, 2).slice(2, 0, 2), after.slice(1, 0, 2).slice(2, 0, 2)));
  CHECK_FALSE(torch::equal(before[0][4][4], after[0][4][4]));
}

TEST_CASE("MobileSAM's TinyViT encoder is laid out as the official one and gives the 64 x 64 embedding", "[segment_anything]") {
  torch::manual_seed(4);
  matlearn::SamTinyVitEncoder encoder;
  // Measured by building the official vit_t model (its unused 1000-class head included).
  CHECK(parameter_count(*encoder) == 6065532);
  std::map<std::string, std::string> official = official_entries("vit_t_state_dict.tsv", "image_encoder.");
  CHECK(our_entries(*encoder) == official);
  encoder->eval();
  torch::NoGradGuard no_grad;
  const torch::Tensor embedding = encoder->forward(torch::randn({1, 3, 1024, 1024}));
  CHECK(embedding.sizes() == torch::IntArrayRef({1, 256, 64, 64}));
  CHECK(torch::isfinite(embedding).all().item<bool>());
}

namespace {

// Runs a command, its output kept: (exit status, output).
std::pair<int, std::string> run(const std::string& command) {
  std::string output;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(pipe);
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return {WEXITSTATUS(status), output};
}

// A MobileSAM checkpoint in the released layout with random weights, written by Debian's torch,
// then converted by the script a user runs.
std::filesystem::path converted_mobile_sam(const std::filesystem::path& folder, const std::string& options) {
  std::filesystem::create_directories(folder);
  const std::string python = MATPREDICT_DEBIAN_PYTHON;
  const std::filesystem::path released = folder / "mobile_sam.pt", converted = folder / "converted.pt";
  REQUIRE(run(python + " " + MATPREDICT_SAM_CHECKPOINT_SCRIPT + " " + MATPREDICT_SAM_DATA + "/vit_t_state_dict.tsv " +
              released.string() + " " + options).first == 0);
  const auto [status, output] = run(python + " " + MATPREDICT_SAM_CONVERT_SCRIPT + " " + released.string() + " " + converted.string());
  INFO(output);
  REQUIRE(status == 0);
  return converted;
}

}  // namespace

TEST_CASE("a released MobileSAM checkpoint, converted, loads and segments", "[segment_anything]") {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "matpredict_sam_checkpoint_test";
  std::filesystem::remove_all(folder);
  // Released files may lack the BatchNorm counters: the script adds them.
  const std::filesystem::path checkpoint = converted_mobile_sam(folder / "counters", "--without-counters");
  const matlearn::SamSegmenter segmenter(checkpoint);
  CHECK(segmenter.size() == matlearn::SamSize::MobileSam);
  CHECK(segmenter.name() == "sam:" + checkpoint.string());
  // The weights are the file's.
  const std::map<std::string, torch::Tensor> file = matlearn::read_state_dict(checkpoint);
  matlearn::SegmentAnything model = matlearn::load_segment_anything(checkpoint);
  const auto parameters = model->named_parameters();
  CHECK(torch::equal(parameters["mask_decoder.iou_token.weight"], file.at("mask_decoder.iou_token.weight")));
  CHECK(torch::equal(model->named_buffers()["prompt_encoder.pe_layer.positional_encoding_gaussian_matrix"],
                     file.at("prompt_encoder.pe_layer.positional_encoding_gaussian_matrix")));
  // A 160 x 120 photograph and a box: a mask of its size (random weights: any content).
  matbase::FloatImage photo(160, 120, 3, 0.5f);
  const matbase::Mask mask = segmenter.segment(photo, {matbase::PixelBox{40, 30, 119, 89}, {}});
  CHECK(mask.size() == 160u * 120u);
  CHECK(std::all_of(mask.begin(), mask.end(), [](uint8_t v) { return v <= 1; }));
  // The same photograph, the same mask.
  CHECK(segmenter.segment(photo, {matbase::PixelBox{40, 30, 119, 89}, {}}) == mask);
}

TEST_CASE("checkpoints that do not fit are refused naming the file and the tensor", "[segment_anything]") {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "matpredict_sam_refusal_test";
  std::filesystem::remove_all(folder);
  const std::filesystem::path wrong = converted_mobile_sam(folder / "wrong", "--wrong mask_decoder.iou_token.weight");
  CHECK_THROWS_WITH(matlearn::load_segment_anything(wrong),
                    Catch::Contains(wrong.string() + " does not fit the model:") &&
                        Catch::Contains("mask_decoder.iou_token.weight is [2, 256] in the file, [1, 256] in the model"));
  CHECK_THROWS_WITH(matlearn::load_segment_anything(folder / "none.pt"), Catch::Contains((folder / "none.pt").string()));
  // A file torch.save wrote that is no Segment Anything: the script refuses it, and so does the loader.
  const std::string python = MATPREDICT_DEBIAN_PYTHON;
  const std::filesystem::path other = folder / "other.pt";
  REQUIRE(run(python + " -c \"import torch; torch.save({'weight': torch.zeros(3)}, '" + other.string() + "')\"").first == 0);
  const auto [status, output] = run(python + " " + MATPREDICT_SAM_CONVERT_SCRIPT + " " + other.string() + " " + (folder / "x.pt").string());
  CHECK(status == 1);
  CHECK_THAT(output, Catch::Contains("not a Segment Anything checkpoint"));
  CHECK_FALSE(std::filesystem::exists(folder / "x.pt"));
  CHECK_THROWS_WITH(matlearn::load_segment_anything(other),
                    Catch::StartsWith(other.string()) && Catch::Contains("scripts/convert_segment_anything.py"));
  // evaluate's names: grabcut, or sam: and a checkpoint.
  CHECK_FALSE(matlearn::segmenter_choice_problem("grabcut"));
  CHECK_FALSE(matlearn::segmenter_choice_problem("sam:x.pt"));
  CHECK(matlearn::segmenter_choice_problem("sam:").value_or("").find("expected grabcut or sam:CHECKPOINT") == 0);
  CHECK_THROWS_WITH(matlearn::make_segmenter("sam:" + (folder / "none.pt").string()), Catch::Contains("none.pt"));
}
