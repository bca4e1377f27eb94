// Writes every stage of our Segment Anything's prediction on a photograph to a file torch.load
// reads, for sam_official_parity.py to compare with the official model's.
//   sam_prediction_dump CHECKPOINT IMAGE OUT.pt [--box X0,Y0,X1,Y1] [--point X,Y,LABEL ...]
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <torch/torch.h>

#include "matdataset/format/sample_reader.h"
#include "matlearn/isolation/prompt.h"
#include "matlearn/models/segment_anything/sam_segmenter.h"

namespace {

std::vector<int> numbers_of(const std::string& text) {
  std::vector<int> numbers;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) numbers.push_back(std::stoi(item));
  return numbers;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s CHECKPOINT IMAGE OUT.pt [--box X0,Y0,X1,Y1] [--point X,Y,LABEL ...]\n", argv[0]);
    return 2;
  }
  try {
    matlearn::Prompt prompt;
    for (int k = 4; k + 1 < argc; k += 2) {
      const std::vector<int> values = numbers_of(argv[k + 1]);
      if (std::string(argv[k]) == "--box" && values.size() == 4)
        prompt.box = matbase::PixelBox{values[0], values[1], values[2], values[3]};
      else if (std::string(argv[k]) == "--point" && values.size() == 3)
        prompt.points.push_back({values[0], values[1], values[2] == 1});
      else
        throw std::invalid_argument(std::string("bad option ") + argv[k] + " " + argv[k + 1]);
    }
    const matdataset::PhotoInput photo = matdataset::read_photo(argv[2], {});
    matlearn::check_prompt(prompt, photo.rgb.width, photo.rgb.height, argv[2]);
    const matlearn::SamPrediction prediction = matlearn::SamSegmenter(argv[1]).predict(photo.rgb, prompt);
    c10::Dict<std::string, torch::Tensor> stages;
    stages.insert("input", prediction.input);
    stages.insert("embedding", prediction.embedding);
    stages.insert("mask_logits", prediction.masks.logits);
    stages.insert("iou", prediction.masks.iou);
    stages.insert("chosen", torch::tensor(prediction.chosen));
    stages.insert("logits", prediction.logits);
    const std::vector<char> bytes = torch::pickle_save(stages);
    std::ofstream(argv[3], std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sam_prediction_dump: %s\n", e.what());
    return 1;
  }
}
