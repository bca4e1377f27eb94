#include "matlearn/training/checkpoint.h"

#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "matgeom/atomic_file.h"
#include "matgeom/input_file.h"

namespace matlearn {
namespace {

using nlohmann::json;

// Marks the file as ours and its layout version.
constexpr const char* kFormat = "matpredict-checkpoint-1";

json header_json(const CheckpointHeader& h) {
  json groups = json::array();
  for (const OutputGroup& g : h.layout.groups)
    groups.push_back({{"map", map_name(g.map)}, {"channels", g.channels}, {"weight", g.weight}});
  return {{"format", kFormat},
          {"network", h.network},
          {"width_divisor", h.width_divisor},
          {"outputs", groups},
          {"material_classes", h.layout.material_classes},
          {"material_weight", h.layout.material_weight},
          {"image_size", h.image_size},
          {"linear_albedo", h.linear_albedo},
          {"epochs_done", h.epochs_done},
          {"schedule",
           {{"epochs", h.schedule.epochs},
            {"rate", h.schedule.rate},
            {"best_loss", h.schedule.best_loss},
            {"has_best", h.schedule.has_best},
            {"epochs_without_improvement", h.schedule.epochs_without_improvement}}},
          {"best_validation_loss", h.best_validation_loss},
          {"has_best_validation", h.has_best_validation},
          {"config", h.config_text}};
}

CheckpointHeader header_from_json(const json& j) {
  CheckpointHeader h;
  h.network = j.at("network").get<std::string>();
  h.width_divisor = j.at("width_divisor").get<int64_t>();
  for (const json& g : j.at("outputs"))
    h.layout.groups.push_back({map_kind_named(g.at("map").get<std::string>()), g.at("channels").get<int64_t>(),
                               g.at("weight").get<double>()});
  h.layout.material_classes = j.at("material_classes").get<int64_t>();
  h.layout.material_weight = j.at("material_weight").get<double>();
  h.image_size = j.at("image_size").get<int>();
  // Written since the normal-map outputs; earlier checkpoints were evaluated on stored albedo.
  h.linear_albedo = j.value("linear_albedo", false);
  h.epochs_done = j.at("epochs_done").get<int>();
  const json& s = j.at("schedule");
  h.schedule.epochs = s.at("epochs").get<int>();
  h.schedule.rate = s.at("rate").get<double>();
  h.schedule.best_loss = s.at("best_loss").get<double>();
  h.schedule.has_best = s.at("has_best").get<bool>();
  h.schedule.epochs_without_improvement = s.at("epochs_without_improvement").get<int>();
  h.best_validation_loss = j.at("best_validation_loss").get<double>();
  h.has_best_validation = j.at("has_best_validation").get<bool>();
  h.config_text = j.at("config").get<std::string>();
  return h;
}

torch::serialize::InputArchive open_archive(const std::filesystem::path& path) {
  if (const std::optional<std::string> problem = matgeom::input_file_problem(path.string()))
    throw std::runtime_error(path.string() + (*problem == "no such file" ? ": no such checkpoint file" : ": " + *problem));
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(path.string());
  } catch (const c10::Error& e) {
    throw std::runtime_error(path.string() + " is not a checkpoint: " + e.what_without_backtrace());
  }
  return archive;
}

}  // namespace

void save_checkpoint(const std::filesystem::path& path, const CheckpointHeader& header, RegressorImpl& model,
                     torch::optim::Optimizer& optimizer) {
  torch::serialize::OutputArchive archive, model_archive, optimizer_archive;
  archive.write("header", c10::IValue(header_json(header).dump()));
  model.save(model_archive);
  archive.write("model", model_archive);
  optimizer.save(optimizer_archive);
  archive.write("optimizer", optimizer_archive);
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  // Serialised in memory, then written by the checked helper: libtorch's file writer finishes the
  // zip in its destructor, so a full disk there ended the process (std::terminate on a c10::Error).
  std::ostringstream bytes;
  archive.save_to(bytes);
  matgeom::write_file_atomically(path, bytes.str());
}

CheckpointHeader read_checkpoint_header(const std::filesystem::path& path) {
  torch::serialize::InputArchive archive = open_archive(path);
  c10::IValue text;
  try {
    archive.read("header", text);
    const json j = json::parse(text.toStringRef());
    if (j.value("format", "") != kFormat) throw std::runtime_error("unknown format");
    return header_from_json(j);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + " is not a matpredict checkpoint (" + e.what() + ")");
  }
}

std::shared_ptr<RegressorImpl> load_checkpoint_model(const std::filesystem::path& path, const CheckpointHeader& header) {
  std::shared_ptr<RegressorImpl> model = make_regressor(architecture_named(header.network).architecture,
                                                        header.layout.output_channels(), header.width_divisor);
  torch::serialize::InputArchive archive = open_archive(path), model_archive;
  archive.read("model", model_archive);
  model->load(model_archive);
  return model;
}

void load_checkpoint_optimizer(const std::filesystem::path& path, torch::optim::Optimizer& optimizer) {
  torch::serialize::InputArchive archive = open_archive(path), optimizer_archive;
  archive.read("optimizer", optimizer_archive);
  optimizer.load(optimizer_archive);
}

}  // namespace matlearn
