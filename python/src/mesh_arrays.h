#pragma once
// matpredict.Mesh: a triangle mesh from numpy arrays, checked as the mesh readers check theirs,
// which a scene dict's object takes as its "mesh".
#include <memory>

#include <pybind11/pybind11.h>

#include "matgeom/object_asset.h"

namespace matpredict_python {

struct MeshArrays {
  std::shared_ptr<const matgeom::ObjectAsset> asset;
};

void bind_mesh(pybind11::module_& module);

}  // namespace matpredict_python
