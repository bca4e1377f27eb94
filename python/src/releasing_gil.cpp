#include "releasing_gil.h"

#include <chrono>
#include <exception>
#include <thread>

#include <pybind11/pybind11.h>

namespace matpredict_python {
namespace {

namespace py = pybind11;

// How long the calling thread sleeps between looks: Ctrl-C is answered within this (and the
// work's own cancellation), and taking the GIL this often costs nothing.
constexpr std::chrono::milliseconds kPollInterval(20);

}  // namespace

void run_releasing_gil(const std::function<void()>& work, std::atomic<bool>& cancel, const std::function<void()>& report) {
  std::atomic<bool> done{false};
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
    }
    done.store(true);
  });
  const auto join = [&] {
    py::gil_scoped_release release;
    worker.join();
  };
  for (bool finished = false; !finished;) {
    {
      py::gil_scoped_release release;
      std::this_thread::sleep_for(kPollInterval);
      finished = done.load();
    }
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      report();
    } catch (...) {
      cancel.store(true);
      join();
      throw;
    }
  }
  join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace matpredict_python
