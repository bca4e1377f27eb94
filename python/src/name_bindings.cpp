#include "name_bindings.h"

#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "matgeom/builtin/builtin_objects.h"
#include "matmaterial/material_classes.h"

namespace matpredict_python {

void bind_names(pybind11::module_& module) {
  module.def("builtin_objects", [] { return matgeom::builtin_object_names(); },
             "The built-in objects' names, what a scene dict's object names as {\"builtin\": name}.");
  module.def("material_classes", [] {
    pybind11::dict classes;
    for (const matmaterial::MaterialClassInfo& info : matmaterial::kMaterialClasses)
      if (info.id != matmaterial::MaterialClass::Background)
        classes[info.name] = matmaterial::label_id(info.id);
    return classes;
  }, "{class name: label id}: the procedural library's classes, what a material names as {\"class\": name},\n"
     "and the id the 'label' AOV holds on its pixels.");
}

}  // namespace matpredict_python
