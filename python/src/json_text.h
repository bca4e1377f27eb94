#pragma once
// A Python dict as JSON text, the way scene dicts and configuration dicts reach the libraries'
// document reader (matbase/document): strings become text, numbers numbers.
#include <string>

#include <pybind11/pybind11.h>

#include "matbase/document/document_node.h"

namespace matpredict_python {

// Besides JSON's own types (dict with text keys, list, tuple, str, int, float, bool, None), takes
// what a user computing a scene in Python holds: numpy scalars and arrays (as their values and
// nested lists) and paths (os.PathLike, as text). Refuses, naming the value's place in `source`'s
// style: NaN and infinities (matpredict.InputError), other types and keys that are not text
// (TypeError), nesting deeper than matbase::kMaxDocumentDepth (which also ends a dict that
// contains itself).
std::string json_text(const pybind11::handle& value, const matbase::DocumentSource& source);

}  // namespace matpredict_python
