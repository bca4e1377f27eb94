#include "dataset_bindings.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "matdataset/format/dataset_index.h"
#include "matdataset/format/sample_reader.h"
#include "matdataset/format/verify_dataset.h"
#include "owned_array.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;
namespace fs = std::filesystem;

// A dataset's samples (all of them, or one split of a split file) and how each is read.
struct DatasetReader {
  fs::path root;
  std::vector<matdataset::SampleId> samples;
  matdataset::SampleSettings settings;
};

DatasetReader open_dataset(const fs::path& root, int size, bool linear_albedo, bool read_normal,
                           const std::optional<fs::path>& split_file, const std::string& split) {
  if (size < 1 || size > 16384) throw py::value_error("size: expected a side from 1 to 16384, got " + std::to_string(size));
  if (split != "train" && split != "val" && split != "test")
    throw py::value_error("split: expected \"train\", \"val\" or \"test\", got \"" + split + "\"");
  DatasetReader reader{root, {}, {}};
  reader.settings.size = size;
  reader.settings.linear_albedo = linear_albedo;
  reader.settings.read_normal = read_normal;
  py::gil_scoped_release release;
  reader.samples = split_file ? matdataset::split_samples(matdataset::read_split_file(*split_file), split, root)
                              : matdataset::index_dataset(root);
  return reader;
}

py::array_t<float> image_array(matbase::FloatImage&& image) {
  const std::vector<py::ssize_t> shape = {image.height, image.width, image.channels};
  return owned_array<float>(std::move(image.values), shape);
}

py::dict sample(const DatasetReader& reader, py::ssize_t index) {
  const auto count = static_cast<py::ssize_t>(reader.samples.size());
  if (index < 0) index += count;
  if (index < 0 || index >= count) throw py::index_error("sample index out of range");
  const matdataset::SampleId& id = reader.samples[static_cast<size_t>(index)];
  matdataset::MaterialSample s;
  {
    py::gil_scoped_release release;
    s = matdataset::read_sample(reader.root, id, reader.settings);
  }
  const py::ssize_t h = s.input.height, w = s.input.width;
  py::dict result;
  result["id"] = id.str();
  result["input"] = image_array(std::move(s.input));
  result["albedo"] = image_array(std::move(s.albedo));
  result["roughness"] = image_array(std::move(s.roughness));
  if (!s.metallic.values.empty()) result["metallic"] = image_array(std::move(s.metallic));
  if (!s.normal.values.empty()) result["normal"] = image_array(std::move(s.normal));
  if (s.has_label) result["material_id"] = owned_array<int32_t>(std::move(s.material_id), {h, w});
  result["mask"] = owned_array<bool, uint8_t>(std::move(s.mask), {h, w});
  return result;
}

py::dict verify(const fs::path& root) {
  matdataset::VerifyReport report;
  {
    py::gil_scoped_release release;
    report = matdataset::verify_dataset(root);
  }
  py::dict result;
  result["variants"] = report.variants;
  result["frames"] = report.frames;
  result["problems"] = report.problems;
  return result;
}

}  // namespace

void bind_datasets(py::module_& module) {
  py::class_<DatasetReader>(module, "DatasetReader",
                            "The samples of a MatPredict dataset (the repository's layout or the paper's texture\n"
                            "targets), each read as libmatlearn's trainer reads it: a dict of numpy arrays.")
      .def(py::init(&open_dataset), py::arg("root"), py::kw_only(), py::arg("size") = 224,
           py::arg("linear_albedo") = false, py::arg("read_normal") = false, py::arg("split_file") = py::none(),
           py::arg("split") = "train",
           "Indexes the dataset under `root` (every frame in the repository loader's order), or the\n"
           "`split` ('train', 'val', 'test') of a split file. Maps are resized to size x size\n"
           "(targets weighted by the object mask); linear_albedo decodes the stored sRGB albedo.\n"
           "Raises matpredict.DatasetError naming the files a frame lacks.")
      .def("__len__", [](const DatasetReader& r) { return r.samples.size(); })
      .def("__getitem__", &sample, py::arg("index"),
           "Sample `index` as a dict: 'id' ('object/variant/stem'); 'input' (size, size, 3) float32 RGB\n"
           "in [0, 1] as stored (sRGB); 'albedo' (size, size, 3) float32 (sRGB as stored, or linear);\n"
           "'roughness' and 'metallic' (size, size, 1) float32 (ORM's G and B); 'normal' (size, size,\n"
           "3) with read_normal (0.5 n + 0.5); 'material_id' (size, size) int32 label ids where the\n"
           "dataset has labels; 'mask' (size, size) bool, the object's pixels.")
      .def_property_readonly("ids", [](const DatasetReader& r) {
        std::vector<std::string> ids;
        for (const matdataset::SampleId& id : r.samples) ids.push_back(id.str());
        return ids;
      }, "Every sample's id, in order.")
      .def_property_readonly("root", [](const DatasetReader& r) { return r.root; }, "The dataset's folder.");
  module.def("verify_dataset", &verify, py::arg("root"),
             "make_dataset --verify from Python: reads every file of the dataset under `root` and returns\n"
             "{'variants': n, 'frames': n, 'problems': [each naming its file]}; no problems: a sound dataset.");
}

}  // namespace matpredict_python
