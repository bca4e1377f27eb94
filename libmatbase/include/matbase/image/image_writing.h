#pragma once
// Writing images through OpenImageIO: linear float EXR, display PNG and raw-value PNG, for every
// library (the renderer's frames, the dataset's maps, contact sheets). Every file is written to a
// temporary name in the same folder and renamed, so a crash never leaves a half-written file;
// given an AtomicFileSet, a writer stages its file there instead, to appear with the set's others
// at its commit(). Every write is checked (a full disk is an error naming the file).
#include <cstdint>
#include <string>
#include <vector>

#include "matbase/file/atomic_file.h"

namespace matbase {

// Linear float EXR (zip compressed) with the given channel names, interleaved data, row 0 = top.
// A channel named "A" is the alpha channel. No time stamp: the same data gives the same bytes.
void write_exr(const std::string& path, int width, int height, const std::vector<std::string>& channels,
               const float* data, AtomicFileSet* set = nullptr);

// The exposure a display image takes, in stops: 2^exposure scales floats, and beyond 2^+-126 the
// image would be all black or all white.
constexpr double kMaxExposureStops = 126.0;

// The 8-bit code a display image gives a linear value, exposure already applied: the sRGB OETF
// ("Standard" view) of the value clipped to [0, 1], rounded (write_display_png's every pixel).
uint8_t display_code(float linear);

// 8-bit PNG from linear RGB(A): exposure in stops, then the sRGB OETF ("Standard" view), clipped.
// `alpha` may be null. Colour is premultiplied by alpha in the input, as rendered, and written
// un-premultiplied in linear space (PNG's straight alpha), so a partly covered pixel keeps the
// surface's colour: no dark fringe, no white halo. No dither.
void write_display_png(const std::string& path, int width, int height, const float* rgb, const float* alpha,
                       double exposure_stops = 0.0, AtomicFileSet* set = nullptr);

// 8-bit or 16-bit PNG of raw values (no transfer curve, no dither), `channels` interleaved, each
// value mapped by v * scale + offset, rounded and clamped. A fourth channel is not treated as
// alpha: it is written verbatim.
void write_data_png(const std::string& path, int width, int height, int channels, const float* data, double scale,
                    double offset, bool sixteen_bit, AtomicFileSet* set = nullptr);

}  // namespace matbase
