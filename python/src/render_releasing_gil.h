#pragma once
// A render that lets Python run meanwhile: the renderer works on its own threads without the GIL
// while the calling thread wakes every few milliseconds to take it briefly, hand the progress to
// a Python callback and look for signals, so other Python threads go on, a progress bar moves,
// and Ctrl-C stops the render promptly with KeyboardInterrupt.
#include <pybind11/pybind11.h>

#include "matrender/camera.h"
#include "matrender/frame.h"
#include "matrender/render.h"
#include "matrender/scene.h"

namespace matpredict_python {

// Renders as matrender::render does, called with the GIL held. `progress` (None or a callable
// taking the finished fraction) is called on the calling thread. A signal's exception
// (KeyboardInterrupt) or one the callback raises cancels the render and propagates.
matrender::RenderStats render_releasing_gil(matrender::Scene& scene, const matrender::Camera& camera,
                                            matrender::RenderSettings settings, matrender::FrameBuffers& frame,
                                            const pybind11::object& progress);

}  // namespace matpredict_python
