#include "prompt_options.h"

#include <cstdint>
#include <vector>

#include "matbase/input_error.h"
#include "matbase/number_text.h"

namespace evaluate_app {
namespace {

// Pixel indices: whole numbers of at least 0 (the image's size is checked once it is read).
constexpr int64_t kLargestIndex = 1 << 20;

std::vector<int> whole_numbers(const std::string& option, const std::string& text, const std::vector<const char*>& names,
                               size_t required, const std::string& form) {
  std::vector<std::string> parts{""};
  for (const char c : text) {
    if (c == ',') parts.emplace_back();
    else parts.back() += c;
  }
  if (parts.size() < required || parts.size() > names.size())
    throw matbase::InputError(option + ": expected " + form + ", got \"" + text + "\"");
  std::vector<int> numbers;
  for (size_t k = 0; k < parts.size(); ++k) {
    const int64_t high = std::string(names[k]) == "label" ? 1 : kLargestIndex;
    if (const std::optional<std::string> problem = matbase::whole_number_problem(parts[k], 0, high))
      throw matbase::InputError(option + " " + names[k] + ": " + *problem);
    numbers.push_back(static_cast<int>(*matbase::whole_number(parts[k])));
  }
  return numbers;
}

}  // namespace

matbase::PixelBox parse_box(const std::string& text) {
  const std::vector<int> n = whole_numbers("--box", text, {"X0", "Y0", "X1", "Y1"}, 4, "X0,Y0,X1,Y1 (pixel columns and rows)");
  return {n[0], n[1], n[2], n[3]};
}

matlearn::PromptPoint parse_point(const std::string& text) {
  const std::vector<int> n = whole_numbers("--point", text, {"X", "Y", "label"}, 2, "X,Y or X,Y,1 (on the object) or X,Y,0 (off it)");
  return {n[0], n[1], n.size() < 3 || n[2] == 1};
}

}  // namespace evaluate_app
