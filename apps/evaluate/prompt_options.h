#pragma once
// evaluate's prompt options as text: --box X0,Y0,X1,Y1 and --point X,Y[,0|1].
#include <string>

#include "matbase/image/object_crop.h"
#include "matlearn/isolation/prompt.h"

namespace evaluate_app {

// Throws matbase::InputError naming the option and the part that is wrong.
matbase::PixelBox parse_box(const std::string& text);
matlearn::PromptPoint parse_point(const std::string& text);

}  // namespace evaluate_app
