#include "matlearn/models/segment_anything/sam_segmenter.h"

#include <vector>

#include "matdataset/format/resample.h"
#include "matlearn/models/segment_anything/sam_frame.h"

namespace matlearn {
namespace {

// The mean and standard deviation of ImageNet's 8-bit RGB, which Segment Anything normalises by.
constexpr float kPixelMean[3] = {123.675f, 116.28f, 103.53f};
constexpr float kPixelStd[3] = {58.395f, 57.12f, 57.375f};

// rgb (display-encoded, [0, 1]) as the model's 1 x 3 x 1024 x 1024 input.
torch::Tensor model_input(const matbase::FloatImage& rgb, const SamFrame& frame) {
  const matbase::FloatImage resized =
      matdataset::resize_bilinear(rgb, static_cast<int>(frame.resized_width), static_cast<int>(frame.resized_height));
  torch::Tensor input = torch::zeros({1, 3, SamFrame::kInputSide, SamFrame::kInputSide});
  auto pixels = input.accessor<float, 4>();
  for (int y = 0; y < resized.height; ++y)
    for (int x = 0; x < resized.width; ++x)
      for (int c = 0; c < 3; ++c) pixels[0][c][y][x] = (255.0f * resized.at(x, y, c) - kPixelMean[c]) / kPixelStd[c];
  return input;
}

}  // namespace

SamSegmenter::SamSegmenter(const std::filesystem::path& checkpoint)
    : checkpoint_(checkpoint), model_(load_segment_anything(checkpoint)) {}

SamPrediction SamSegmenter::predict(const matbase::FloatImage& rgb, const Prompt& given) const {
  torch::NoGradGuard no_grad;
  const Prompt prompt = given.empty() ? default_prompt(rgb.width, rgb.height) : given;
  const SamFrame frame = SamFrame::of(rgb.height, rgb.width);
  SegmentAnythingImpl& model = *model_.ptr();  // inference changes no weight
  SamPrediction prediction;
  prediction.input = model_input(rgb, frame);
  prediction.embedding = model.embed(prediction.input);

  std::optional<torch::Tensor> points, labels, box;
  if (!prompt.points.empty()) {
    std::vector<float> coordinates;
    std::vector<int64_t> kinds;
    for (const PromptPoint& point : prompt.points) {
      coordinates.insert(coordinates.end(), {static_cast<float>(point.x), static_cast<float>(point.y)});
      kinds.push_back(point.foreground ? 1 : 0);
    }
    const int64_t n = static_cast<int64_t>(kinds.size());
    points = frame.to_input(torch::tensor(coordinates).view({1, n, 2}));
    labels = torch::tensor(kinds).view({1, n});
  }
  if (prompt.box) {
    const matbase::PixelBox& b = *prompt.box;
    box = frame.to_input(torch::tensor({static_cast<float>(b.x0), static_cast<float>(b.y0), static_cast<float>(b.x1),
                                        static_cast<float>(b.y1)}).view({1, 4}));
  }
  prediction.masks = model.decode(prediction.embedding, points, labels, box);
  const bool ambiguous = !prompt.box && prompt.points.size() <= 1;
  prediction.chosen = ambiguous ? 1 + prediction.masks.iou[0].slice(0, 1, 4).argmax().item<int64_t>() : 0;
  const int64_t k = prediction.chosen;
  prediction.logits = frame.logits_at_photo_size(prediction.masks.logits.slice(1, k, k + 1))[0][0];
  return prediction;
}

matbase::Mask SamSegmenter::segment(const matbase::FloatImage& rgb, const Prompt& prompt) const {
  const torch::Tensor bytes = (predict(rgb, prompt).logits > 0).to(torch::kUInt8).contiguous();
  return matbase::Mask(bytes.data_ptr<uint8_t>(), bytes.data_ptr<uint8_t>() + bytes.numel());
}

}  // namespace matlearn
