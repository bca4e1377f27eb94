#pragma once
// numpy arrays as the libraries' float images and masks, checked: the wrong dtype is a TypeError,
// the wrong shape a ValueError naming the argument.
#include <string>

#include <pybind11/numpy.h>

#include "matbase/image/float_image.h"

namespace matpredict_python {

// An (H, W) or (H, W, C) array of floats, integers or booleans, copied into a float image.
matbase::FloatImage float_image(const pybind11::array& array, const std::string& name);
// None (every pixel), or an (H, W) or (H, W, 1) array whose nonzero entries are inside, for an
// image `height` x `width`.
matbase::Mask mask_of(const pybind11::object& mask, int width, int height);

}  // namespace matpredict_python
