// matpredict._core: the extension the matpredict package (python/matpredict/__init__.py) exports.
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "camera_bindings.h"
#include "dataset_bindings.h"
#include "dataset_maker_bindings.h"
#include "display_bindings.h"
#include "isolation_bindings.h"
#include "matlearn/isolation/grabcut.h"
#include "mesh_arrays.h"
#include "name_bindings.h"
#include "metric_bindings.h"
#include "python_errors.h"
#include "render_bindings.h"

PYBIND11_MODULE(_core, module) {
  module.doc() = "matpredict's libraries from Python: rendering to numpy arrays, the image metrics, datasets.";
  matpredict_python::bind_errors(module);
  matpredict_python::bind_mesh(module);
  matpredict_python::bind_camera(module);
  matpredict_python::bind_render(module);
  matpredict_python::bind_display(module);
  matpredict_python::bind_names(module);
  matpredict_python::bind_metrics(module);
  matpredict_python::bind_datasets(module);
  matpredict_python::bind_dataset_maker(module);
  matpredict_python::bind_isolation(module, [](const std::string&) -> std::shared_ptr<const matlearn::Segmenter> {
    return std::make_shared<matlearn::GrabCutSegmenter>();  // "sam:" goes to matpredict._learn's isolate
  });
  matpredict_python::bind_mask_box(module);
}
