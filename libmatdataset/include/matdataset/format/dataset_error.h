#pragma once
// The error of a dataset's files: a map missing, unreadable, of the wrong size, format or channel
// count, or holding a value the reader refuses; a split file that contradicts itself. Its message
// names the file and the problem. It is the input's fault, not the program's: the tools exit 2
// for it (apps/common/exit_codes.h), wherever in a run the file is read.
#include <stdexcept>

namespace matdataset {

struct DatasetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace matdataset
