#pragma once
// How the libraries' exceptions reach Python.
#include <pybind11/pybind11.h>

namespace matpredict_python {

// matpredict.InputError, a ValueError: a bad file, key or value, with the library's message
// (the file, the JSON pointer or key, the problem); matpredict.DatasetError, an InputError: a
// dataset's file missing or unreadable, named. Other std exceptions become pybind11's usual
// RuntimeError or ValueError, an interrupted render KeyboardInterrupt.
void bind_errors(pybind11::module_& module);

}  // namespace matpredict_python
