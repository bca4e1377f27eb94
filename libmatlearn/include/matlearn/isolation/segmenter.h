#pragma once
// What isolates an object: a segmenter finds its pixels in an image from a prompt. GrabCut
// (grabcut.h) needs no weights; Segment Anything is a network with its checkpoint.
#include <optional>
#include <string>

#include "matbase/image/float_image.h"
#include "matlearn/isolation/prompt.h"

namespace matlearn {

class Segmenter {
 public:
  virtual ~Segmenter() = default;
  // The object's pixels in `rgb` (display-encoded RGB in [0, 1]) before cleanup, for a prompt
  // check_prompt accepted; an empty prompt asks for the most central object.
  virtual matbase::Mask segment(const matbase::FloatImage& rgb, const Prompt& prompt) const = 0;
  // "grabcut", "sam:<checkpoint>": what --segmenter names it.
  virtual std::string name() const = 0;
};

// What is wrong with `choice` as a segmenter's name (evaluate's --segmenter, matpredict.isolate's
// `segmenter`), before anything is loaded: "grabcut" (OpenCV's GrabCut, no weights) and
// "sam:CHECKPOINT" (Segment Anything, matlearn/evaluation/segmenter_choice.h) are; for anything
// else "expected grabcut or sam:CHECKPOINT ..., got ...".
std::optional<std::string> segmenter_choice_problem(const std::string& choice);

// The checkpoint a "sam:CHECKPOINT" choice names, or nothing for another choice.
std::optional<std::string> sam_checkpoint_of(const std::string& choice);

}  // namespace matlearn
