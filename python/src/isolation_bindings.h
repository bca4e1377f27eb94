#pragma once
// matpredict.isolate: an object isolated in an image (a photograph) as evaluate --image does it.
// Both extensions declare it: matpredict._core with GrabCut, matpredict._learn (libtorch) with
// every segmenter; the package calls _learn's for "sam:CHECKPOINT".
#include <functional>
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "matlearn/isolation/segmenter.h"

namespace matpredict_python {

// The segmenter a checked name gives (matlearn::segmenter_choice_problem accepted it).
using SegmenterMaker = std::function<std::shared_ptr<const matlearn::Segmenter>(const std::string&)>;

void bind_isolation(pybind11::module_& module, SegmenterMaker make_segmenter);

// matpredict.mask_box: the box prompt around a mask (matpredict._core alone declares it).
void bind_mask_box(pybind11::module_& module);

}  // namespace matpredict_python
