// matpredict._learn: a trained regressor from Python (libmatlearn, libtorch), in a module of its
// own so that `import matpredict` does not load libtorch; matpredict.load_model imports it.
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "image_arrays.h"
#include "isolation_bindings.h"
#include "matbase/input_error.h"
#include "matlearn/evaluation/inference.h"
#include "matlearn/evaluation/segmenter_choice.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/checkpoint.h"
#include "owned_array.h"

namespace {

namespace py = pybind11;

// A checkpoint's network with its weights, and the header that says how it reads images.
struct Model {
  matlearn::CheckpointHeader header;
  std::shared_ptr<matlearn::RegressorImpl> network;
};

Model load_model(const std::filesystem::path& path) {
  py::gil_scoped_release release;
  try {
    const matlearn::Checkpoint checkpoint = matlearn::read_checkpoint(path);
    return Model{checkpoint.header, matlearn::load_model(checkpoint)};
  } catch (const std::runtime_error& e) {  // the file is no checkpoint of this build's networks: bad input
    throw matbase::InputError(e.what());
  }
}

py::dict predict(Model& model, const py::array& image) {
  const matbase::FloatImage rgb = matpredict_python::float_image(image, "image");
  const int side = model.header.image_size;
  if (rgb.channels != 3 || rgb.width != side || rgb.height != side)
    throw py::value_error("image: expected (" + std::to_string(side) + ", " + std::to_string(side) +
                          ", 3), the network's input size, got (" + std::to_string(rgb.height) + ", " +
                          std::to_string(rgb.width) + ", " + std::to_string(rgb.channels) + ")");
  matlearn::PredictedMaps predicted;
  {
    py::gil_scoped_release release;
    predicted = matlearn::predict_maps(*model.network, model.header, rgb);
  }
  py::dict maps;
  for (size_t m = 0; m < predicted.maps.size(); ++m) {
    matbase::FloatImage& map = predicted.maps[m];
    const std::vector<py::ssize_t> shape = {map.height, map.width, map.channels};
    maps[predicted.names[m].c_str()] = matpredict_python::owned_array<float>(std::move(map.values), shape);
  }
  return maps;
}

// The last segmenter made, kept: loading Segment Anything's weights takes longer than a mask.
std::shared_ptr<const matlearn::Segmenter> kept_segmenter(const std::string& choice) {
  static std::mutex guard;
  static std::string kept_choice;
  static std::shared_ptr<const matlearn::Segmenter> kept;
  const std::lock_guard<std::mutex> lock(guard);
  if (!kept || kept_choice != choice) {
    kept = matlearn::make_segmenter(choice);
    kept_choice = choice;
  }
  return kept;
}

}  // namespace

PYBIND11_MODULE(_learn, module) {
  module.doc() = "matpredict's trained regressors (libmatlearn): load a checkpoint, predict maps.";
  py::module_::import("matpredict._core");  // its InputError translation
  py::class_<Model>(module, "Model", "A trained regressor, as evaluate loads it (matpredict.load_model).")
      .def_property_readonly("network", [](const Model& m) { return m.header.network; }, "The architecture's name.")
      .def_property_readonly("image_size", [](const Model& m) { return m.header.image_size; },
                             "The side of the square RGB images it reads.")
      .def_property_readonly("outputs", [](const Model& m) {
        std::vector<std::string> names;
        for (const matlearn::OutputGroup& group : m.header.layout.groups) names.push_back(matlearn::map_name(group.map));
        return names;
      }, "The maps it predicts, in order.")
      .def_property_readonly("linear_albedo", [](const Model& m) { return m.header.linear_albedo; },
                             "Whether its base colour is linear (else sRGB as the dataset stores it).")
      .def_property_readonly("epochs_done", [](const Model& m) { return m.header.epochs_done; },
                             "Epochs the checkpoint was trained for.")
      .def("predict", &predict, py::arg("image"),
           "The maps for one (image_size, image_size, 3) RGB image in [0, 1] (as a dataset sample's\n"
           "'input'): a dict of (image_size, image_size, C) float32 arrays in [0, 1], named as `outputs`;\n"
           "the same maps evaluate --image writes (before its 8-bit PNGs and the mask).");
  matpredict_python::bind_isolation(module, &kept_segmenter);
  module.def("load_model", &load_model, py::arg("path"),
             "Reads and verifies a checkpoint (train_regressor's checkpoints/last.pt or best.pt) and builds its\n"
             "network. Raises matpredict.InputError naming the file when it is not a checkpoint, is damaged,\n"
             "or describes a network this build has not.");
}
