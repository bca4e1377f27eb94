#pragma once
// A rendered frame as a dict of numpy arrays, without a copy.
#include <pybind11/pybind11.h>

#include "matrender/frame.h"

namespace matpredict_python {

// "color" and every AOV the frame holds (matrender::aov_names()), each an array of shape
// (height, width, channels), row 0 the image top: float32, or int32 for label, part_id,
// object_id and sample_count. The arrays view the frame's own buffers, which live as long as any of them.
pybind11::dict frame_arrays(matrender::FrameBuffers&& frame);

}  // namespace matpredict_python
