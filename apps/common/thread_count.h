#pragma once
// The thread count a command-line option asks for, as the libraries will run it.
#include <string>

namespace app_support {

// matbase::worker_threads(requested), with a note on stderr ("<program>: note: <option> 1000 is
// more than this machine's 2 hardware threads; using 2") when the request was capped.
int announced_worker_threads(const std::string& program, const std::string& option, int requested);

}  // namespace app_support
