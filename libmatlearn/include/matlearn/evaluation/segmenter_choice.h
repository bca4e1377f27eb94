#pragma once
// The segmenter evaluate's --segmenter and matpredict.isolate's `segmenter` name: "grabcut"
// (OpenCV's GrabCut, no weights) or "sam:CHECKPOINT" (Segment Anything, SAM ViT-B or MobileSAM,
// from a checkpoint scripts/convert_segment_anything.py wrote).
#include <memory>
#include <string>

#include "matlearn/isolation/segmenter.h"

namespace matlearn {

// Throws matbase::InputError with segmenter_choice_problem's words, or naming the checkpoint that
// cannot be loaded.
std::unique_ptr<Segmenter> make_segmenter(const std::string& choice);

}  // namespace matlearn
