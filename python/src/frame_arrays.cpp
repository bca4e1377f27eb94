#include "frame_arrays.h"

#include <memory>
#include <string>

#include <pybind11/numpy.h>

namespace matpredict_python {
namespace {

namespace py = pybind11;

// An (height, width, channels) array over `values`, kept alive by `owner`.
template <class T>
py::array_t<T> view_of(std::vector<T>& values, const matrender::FrameBuffers& frame, int channels, const py::capsule& owner) {
  const py::ssize_t c = channels, w = frame.width, h = frame.height, item = sizeof(T);
  return py::array_t<T>({h, w, c}, {w * c * item, c * item, item}, values.data(), owner);
}

void add_buffer(py::dict& arrays, const std::string& name, const matrender::FrameBufferView& view,
                const matrender::FrameBuffers& frame, const py::capsule& owner) {
  if (view.floats && !view.floats->empty()) arrays[name.c_str()] = view_of(*view.floats, frame, view.channels, owner);
  if (view.ints && !view.ints->empty()) arrays[name.c_str()] = view_of(*view.ints, frame, view.channels, owner);
}

}  // namespace

py::dict frame_arrays(matrender::FrameBuffers&& frame) {
  auto owned = std::make_unique<matrender::FrameBuffers>(std::move(frame));
  const py::capsule owner(owned.get(), [](void* p) { delete static_cast<matrender::FrameBuffers*>(p); });
  matrender::FrameBuffers* held = owned.release();  // the capsule's now
  py::dict arrays;
  add_buffer(arrays, "color", matrender::frame_buffer(*held, 0), *held, owner);
  for (const matrender::AovName& aov : matrender::aov_names())
    if (held->aovs & aov.bit) add_buffer(arrays, aov.name, matrender::frame_buffer(*held, aov.bit), *held, owner);
  return arrays;
}

}  // namespace matpredict_python
