#include "render_releasing_gil.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace matpredict_python {
namespace {

namespace py = pybind11;

// How long the calling thread sleeps between looks: Ctrl-C is answered within this (and the
// renderer's own cancellation, milliseconds), and taking the GIL this often costs nothing.
constexpr std::chrono::milliseconds kPollInterval(20);

}  // namespace

matrender::RenderStats render_releasing_gil(matrender::Scene& scene, const matrender::Camera& camera,
                                            matrender::RenderSettings settings, matrender::FrameBuffers& frame,
                                            const py::object& progress) {
  std::atomic<bool> cancel{false}, done{false};
  std::atomic<double> fraction{0.0};
  settings.cancel = &cancel;
  settings.progress = [&fraction](double f) { fraction.store(f); };
  matrender::RenderStats stats;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      stats = matrender::render(scene, camera, settings, frame);
    } catch (...) {
      failure = std::current_exception();
    }
    done.store(true);
  });
  const auto stop_worker = [&] {
    cancel.store(true);
    py::gil_scoped_release release;
    worker.join();
  };
  double reported = -1.0;
  for (bool finished = false; !finished;) {
    {
      py::gil_scoped_release release;
      std::this_thread::sleep_for(kPollInterval);
      finished = done.load();
    }
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (const double f = fraction.load(); !progress.is_none() && f != reported) {
        reported = f;
        progress(f);
      }
    } catch (...) {
      stop_worker();
      throw;
    }
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (failure) std::rethrow_exception(failure);
  return stats;
}

}  // namespace matpredict_python
