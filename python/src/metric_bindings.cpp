#include "metric_bindings.h"

#include <string>

#include <pybind11/numpy.h>

#include "image_arrays.h"
#include "matlearn/image_metrics.h"
#include "matlearn/metric_scores.h"

namespace matpredict_python {
namespace {

namespace py = pybind11;

// Both images and the mask, read and checked for one metric call.
struct MetricInputs {
  matbase::FloatImage truth, prediction;
  matbase::Mask mask;
};

MetricInputs metric_inputs(const py::array& truth, const py::array& prediction, const py::object& mask) {
  MetricInputs inputs{float_image(truth, "truth"), float_image(prediction, "prediction"), {}};
  inputs.mask = mask_of(mask, inputs.truth.width, inputs.truth.height);
  return inputs;
}

using RangedMetric = double (*)(const matbase::FloatImage&, const matbase::FloatImage&, double, const matbase::Mask&);
using UnrangedMetric = double (*)(const matbase::FloatImage&, const matbase::FloatImage&, const matbase::Mask&);

void def_ranged(py::module_& module, const char* name, RangedMetric metric, const char* doc) {
  module.def(
      name,
      [metric](const py::array& truth, const py::array& prediction, double data_range, const py::object& mask) {
        const MetricInputs in = metric_inputs(truth, prediction, mask);
        py::gil_scoped_release release;
        return metric(in.truth, in.prediction, data_range, in.mask);
      },
      py::arg("truth"), py::arg("prediction"), py::kw_only(), py::arg("data_range") = 1.0, py::arg("mask") = py::none(),
      doc);
}

void def_unranged(py::module_& module, const char* name, UnrangedMetric metric, const char* doc) {
  module.def(
      name,
      [metric](const py::array& truth, const py::array& prediction, const py::object& mask) {
        const MetricInputs in = metric_inputs(truth, prediction, mask);
        py::gil_scoped_release release;
        return metric(in.truth, in.prediction, in.mask);
      },
      py::arg("truth"), py::arg("prediction"), py::kw_only(), py::arg("mask") = py::none(), doc);
}

py::dict score_map(const py::array& truth, const py::array& prediction, const py::object& mask,
                   const std::string& convention) {
  if (convention != "correct" && convention != "paper_compat")
    throw py::value_error("convention: expected \"correct\" or \"paper_compat\", got \"" + convention + "\"");
  const MetricInputs in = metric_inputs(truth, prediction, mask);
  const matlearn::MetricScores scores = matlearn::score_map(
      in.truth, in.prediction, in.mask,
      convention == "correct" ? matlearn::MetricConvention::correct : matlearn::MetricConvention::paper_compat);
  py::dict result;
  for (const matlearn::Metric metric : matlearn::kAllMetrics) result[matlearn::metric_name(metric).c_str()] = scores[metric];
  return result;
}

}  // namespace

void bind_metrics(py::module_& module) {
  // Each image is (H, W) or (H, W, C), of any numeric dtype (read as float32); `mask` is None or
  // (H, W) with nonzero entries inside. std::invalid_argument (sizes that differ) is a ValueError.
  def_ranged(module, "rmse", &matlearn::rmse, "sqrt(mean (Y - X)^2) / data_range, over the mask's pixels.");
  def_ranged(module, "psnr", &matlearn::psnr, "10 log10(data_range^2 / mean (Y - X)^2) in dB; inf for identical images.");
  def_ranged(module, "ssim", &matlearn::ssim,
             "Structural similarity with scikit-image's defaults (7 x 7 uniform windows, K1 = 0.01, K2 = 0.03),\n"
             "per channel, averaged over the window centres that fit (and lie in the mask).");
  def_ranged(module, "fsim", &matlearn::fsim, "Feature similarity (Zhang et al. 2011) per channel, averaged.");
  def_unranged(module, "sre", &matlearn::sre, "10 log10(sum X^2 / sum (Y - X)^2) in dB.");
  def_unranged(module, "issm", &matlearn::issm, "1 / (1 + ||Y - X||_F / ||X||_F), in (0, 1].");
  def_unranged(module, "uiq", &matlearn::uiq, "Wang and Bovik's universal image quality index on 8 x 8 windows.");
  def_unranged(module, "sam_degrees", &matlearn::sam_degrees,
               "The mean spectral angle between the pixels' channel vectors, in degrees.");
  module.def("score_map", &score_map, py::arg("truth"), py::arg("prediction"), py::kw_only(),
             py::arg("mask") = py::none(), py::arg("convention") = "correct",
             "All eight metrics of a predicted map in [0, 1] against its truth, as evaluate tabulates them:\n"
             "a dict {'RMSE', 'PSNR', 'SRE', 'SSIM', 'FSIM', 'UIQ', 'SAM', 'ISSM'}. 'correct': on the float\n"
             "maps over the mask; 'paper_compat': the paper's package's conventions (8-bit, unmasked).");
}

}  // namespace matpredict_python
