#pragma once
// What a libtorch failure says, for messages that name the user's file. libtorch's readers throw
// more than c10::Error on bad bytes (the TorchScript unpickler throws torch::jit::ErrorReport,
// which the checkpoint fuzzer found), so every boundary catches std::exception and asks here.
#include <exception>
#include <string>

#include <c10/util/Exception.h>

namespace matlearn {

// c10::Error's message without its C++ backtrace; any other exception's what(), which for an
// ErrorReport of libtorch 1.13 is empty.
inline std::string torch_error_text(const std::exception& e) {
  if (const auto* error = dynamic_cast<const c10::Error*>(&e)) return error->what_without_backtrace();
  const std::string text = e.what();
  return text.empty() ? "libtorch could not parse its contents" : text;
}

}  // namespace matlearn
