#pragma once
// Writing frames: linear EXR and display PNG through OpenImageIO. Every file is written to a
// temporary name in the same folder and renamed, so a crash never leaves a half-written file;
// given an AtomicFileSet, a writer stages its file there instead, to appear with the set's others
// at its commit(). Every write is checked (a full disk is an error naming the file).
#include <string>
#include <vector>

#include "matgeom/atomic_file.h"
#include "matrender/frame.h"

namespace matrender {

// Linear float EXR with the given channel names, interleaved data, row 0 = top.
void write_exr(const std::string& path, int width, int height,
               const std::vector<std::string>& channels, const float* data, matgeom::AtomicFileSet* set = nullptr);

// The exposure a display image takes, in stops: 2^exposure scales floats, and beyond 2^+-126 the
// image would be all black or all white.
constexpr double kMaxExposureStops = 126.0;

// 8-bit PNG from linear RGB(A): exposure in stops, then the sRGB OETF ("Standard" view), clipped.
// `alpha` may be null. Colour is premultiplied by alpha in the input, as rendered, and written
// un-premultiplied (PNG's straight alpha).
void write_display_png(const std::string& path, int width, int height, const float* rgb,
                       const float* alpha, double exposure_stops = 0.0, matgeom::AtomicFileSet* set = nullptr);

// 8-bit or 16-bit PNG of raw values (no transfer curve), `channels` interleaved, each value
// mapped by v * scale + offset, rounded and clamped. A fourth channel is not treated as alpha.
void write_data_png(const std::string& path, int width, int height, int channels, const float* data,
                    double scale, double offset, bool sixteen_bit, matgeom::AtomicFileSet* set = nullptr);

// Writes every filled buffer of `frame` into `folder` as <stem>_<pass>.<ext> and returns the
// paths written: color.exr (RGBA; A = coverage for transparent renders, else 1), color.png
// (display; RGBA only for transparent renders), and per AOV an EXR (exact values) plus a PNG for
// viewing. Creates `folder` if needed. The files appear together or not at all: on any failure
// (a full disk, a directory in the way) none of them is left behind.
std::vector<std::string> write_frame(const FrameBuffers& frame, const std::string& folder,
                                     const std::string& stem, double exposure_stops = 0.0);

}  // namespace matrender
