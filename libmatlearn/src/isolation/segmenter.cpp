#include "matlearn/isolation/segmenter.h"

namespace matlearn {
namespace {

constexpr const char* kSam = "sam:";

}  // namespace

std::optional<std::string> sam_checkpoint_of(const std::string& choice) {
  const std::string sam = kSam;
  if (choice.compare(0, sam.size(), sam) != 0 || choice.size() == sam.size()) return std::nullopt;
  return choice.substr(sam.size());
}

std::optional<std::string> segmenter_choice_problem(const std::string& choice) {
  if (choice == "grabcut" || sam_checkpoint_of(choice)) return std::nullopt;
  return "expected grabcut or sam:CHECKPOINT (a converted Segment Anything checkpoint), got \"" + choice + "\"";
}

}  // namespace matlearn
