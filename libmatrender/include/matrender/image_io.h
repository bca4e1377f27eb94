#pragma once
// Writing a rendered frame: every buffer as linear EXR plus a PNG to look at, through matgeom's
// image writers (matbase/image/image_writing.h), which write a temporary and rename it.
#include <string>
#include <vector>

#include "matbase/image/image_writing.h"
#include "matrender/frame.h"

namespace matrender {

// Writes every filled buffer of `frame` into `folder` as <stem>_<pass>.<ext> and returns the
// paths written: color.exr (RGBA; A = coverage for transparent renders, else 1), color.png
// (display; RGBA only for transparent renders), and per AOV an EXR (exact values) plus a PNG for
// viewing. Creates `folder` if needed. The files appear together or not at all: on any failure
// (a full disk, a directory in the way) none of them is left behind.
std::vector<std::string> write_frame(const FrameBuffers& frame, const std::string& folder,
                                     const std::string& stem, double exposure_stops = 0.0);

}  // namespace matrender
