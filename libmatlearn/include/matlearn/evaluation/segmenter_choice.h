#pragma once
// The segmenter evaluate's --segmenter and matpredict.isolate's `segmenter` name: "grabcut"
// (OpenCV's GrabCut, no weights) or "sam:CHECKPOINT" (Segment Anything, SAM ViT-B or MobileSAM,
// from a checkpoint scripts/convert_segment_anything.py wrote).
#include <memory>
#include <optional>
#include <string>

#include "matlearn/isolation/segmenter.h"

namespace matlearn {

// What is wrong with `choice` as a segmenter's name, before anything is loaded: "expected
// grabcut or sam:CHECKPOINT ..., got ...", or nothing.
std::optional<std::string> segmenter_choice_problem(const std::string& choice);

// Throws matbase::InputError with segmenter_choice_problem's words, or naming the checkpoint that
// cannot be loaded.
std::unique_ptr<Segmenter> make_segmenter(const std::string& choice);

}  // namespace matlearn
