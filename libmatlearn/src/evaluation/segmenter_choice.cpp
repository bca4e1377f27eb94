#include "matlearn/evaluation/segmenter_choice.h"

#include "matbase/input_error.h"
#include "matlearn/isolation/grabcut.h"
#include "matlearn/models/segment_anything/sam_segmenter.h"

namespace matlearn {

std::unique_ptr<Segmenter> make_segmenter(const std::string& choice) {
  if (const std::optional<std::string> problem = segmenter_choice_problem(choice)) throw matbase::InputError("segmenter: " + *problem);
  if (choice == "grabcut") return std::make_unique<GrabCutSegmenter>();
  return std::make_unique<SamSegmenter>(*sam_checkpoint_of(choice));
}

}  // namespace matlearn
