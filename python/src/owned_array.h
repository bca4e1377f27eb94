#pragma once
// A vector handed to numpy: the array owns it (through a capsule), so no copy is made.
#include <memory>
#include <vector>

#include <pybind11/numpy.h>

namespace matpredict_python {

// `values` as an array of `shape` (C order), owned by the array. Element type Stored may differ
// from the array's T when they share a layout (uint8_t as numpy's bool).
template <class T, class Stored = T>
pybind11::array_t<T> owned_array(std::vector<Stored>&& values, std::vector<pybind11::ssize_t> shape) {
  static_assert(sizeof(T) == sizeof(Stored), "the array reads the vector's bytes");
  auto owned = std::make_unique<std::vector<Stored>>(std::move(values));
  const pybind11::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<Stored>*>(p); });
  const auto* data = reinterpret_cast<const T*>(owned.release()->data());  // the capsule's now
  return pybind11::array_t<T>(std::move(shape), data, owner);
}

}  // namespace matpredict_python
