#pragma once
// A problem with what the user gave (a file, an option, a configuration), as opposed to a failure
// while working or writing: the apps end the two with different exit codes.
#include <stdexcept>

namespace matbase {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace matbase
