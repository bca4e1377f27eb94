#include "matlearn/evaluation/segmenter_choice.h"

#include "matbase/input_error.h"
#include "matlearn/isolation/grabcut.h"
#include "matlearn/models/segment_anything/sam_segmenter.h"

namespace matlearn {

namespace {

constexpr const char* kSam = "sam:";

bool names_sam(const std::string& choice) {
  const std::string sam = kSam;
  return choice.compare(0, sam.size(), sam) == 0 && choice.size() > sam.size();
}

}  // namespace

std::optional<std::string> segmenter_choice_problem(const std::string& choice) {
  if (choice == "grabcut" || names_sam(choice)) return std::nullopt;
  return "expected grabcut or sam:CHECKPOINT (a converted Segment Anything checkpoint), got \"" + choice + "\"";
}

std::unique_ptr<Segmenter> make_segmenter(const std::string& choice) {
  if (const std::optional<std::string> problem = segmenter_choice_problem(choice)) throw matbase::InputError("segmenter: " + *problem);
  if (choice == "grabcut") return std::make_unique<GrabCutSegmenter>();
  return std::make_unique<SamSegmenter>(choice.substr(std::string(kSam).size()));
}

}  // namespace matlearn
