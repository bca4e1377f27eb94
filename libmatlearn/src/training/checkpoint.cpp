#include "matlearn/training/checkpoint.h"

#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <zlib.h>

#include "matbase/file/atomic_file.h"
#include "matbase/file/input_file.h"
#include "models/torch_error.h"

namespace matlearn {
namespace {

using nlohmann::json;

// Marks the file as ours and its layout version. Version 2 added the checksum and stores the
// network's and the optimiser's archives as bytes, so that the checksum covers exactly what loads.
constexpr const char* kFormat = "matpredict-checkpoint-2";

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

// Throws (json or std::invalid_argument) when a field is missing or describes no network this
// build can make.
CheckpointHeader header_from_json(const json& j) {
  CheckpointHeader h;
  h.network = j.at("network").get<std::string>();
  const ArchitectureInfo& network = architecture_named(h.network);
  h.width_divisor = j.at("width_divisor").get<int64_t>();
  if (h.width_divisor < 1) throw std::invalid_argument("width divisor below 1");
  for (const json& g : j.at("outputs"))
    h.layout.groups.push_back({map_kind_named(g.at("map").get<std::string>()), g.at("channels").get<int64_t>(),
                               g.at("weight").get<double>()});
  h.layout.material_classes = j.at("material_classes").get<int64_t>();
  h.layout.material_weight = j.at("material_weight").get<double>();
  validate(h.layout);
  h.image_size = j.at("image_size").get<int>();
  if (h.image_size < network.side_multiple || h.image_size % network.side_multiple != 0)
    throw std::invalid_argument("image size " + std::to_string(h.image_size) + " does not suit " + h.network);
  h.linear_albedo = j.at("linear_albedo").get<bool>();
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

// A torch archive's bytes as a uint8 tensor that owns them.
torch::Tensor serialised(torch::serialize::OutputArchive& archive) {
  std::ostringstream stream;
  archive.save_to(stream);
  const std::string bytes = stream.str();
  return torch::from_blob(const_cast<char*>(bytes.data()), {static_cast<int64_t>(bytes.size())}, torch::kUInt8).clone();
}

// A torch archive read back from the bytes serialised() made.
torch::serialize::InputArchive open_state(const torch::Tensor& state) {
  torch::serialize::InputArchive archive;
  archive.load_from(reinterpret_cast<const char*>(state.data_ptr<uint8_t>()), static_cast<size_t>(state.numel()));
  return archive;
}

// zlib's CRC-32 (the one zip and PNG use) of the header text and both states, in that order.
int64_t checksum(const std::string& header_text, const torch::Tensor& model_state,
                 const torch::Tensor& optimizer_state) {
  uLong crc = crc32_z(0L, Z_NULL, 0);
  crc = crc32_z(crc, reinterpret_cast<const Bytef*>(header_text.data()), header_text.size());
  for (const torch::Tensor* state : {&model_state, &optimizer_state})
    crc = crc32_z(crc, state->data_ptr<uint8_t>(), static_cast<size_t>(state->numel()));
  return static_cast<int64_t>(crc);
}

std::runtime_error not_ours(const std::filesystem::path& path, const std::string& why) {
  return std::runtime_error(path.string() + " is not a matpredict checkpoint (" + why + ")");
}

}  // namespace

void save_checkpoint(const std::filesystem::path& path, const CheckpointHeader& header, RegressorImpl& model,
                     torch::optim::Optimizer& optimizer) {
  torch::serialize::OutputArchive model_archive, optimizer_archive;
  model.save(model_archive);
  optimizer.save(optimizer_archive);
  const torch::Tensor model_state = serialised(model_archive);
  const torch::Tensor optimizer_state = serialised(optimizer_archive);
  const std::string header_text = header_json(header).dump();

  torch::serialize::OutputArchive archive;
  archive.write("header", c10::IValue(header_text));
  archive.write("model", model_state);
  archive.write("optimizer", optimizer_state);
  archive.write("crc32", c10::IValue(checksum(header_text, model_state, optimizer_state)));
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  // Serialised in memory, then written by the checked helper: libtorch's file writer finishes the
  // zip in its destructor, so a full disk there ended the process (std::terminate on a c10::Error).
  std::ostringstream bytes;
  archive.save_to(bytes);
  matbase::write_file_atomically(path, bytes.str());
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  if (const std::optional<std::string> problem = matbase::input_file_problem(path.string()))
    throw std::runtime_error(path.string() + (*problem == "no such file" ? ": no such checkpoint file" : ": " + *problem));
  torch::serialize::InputArchive archive;
  try {
    archive.load_from(path.string());
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + " is not a checkpoint: " + torch_error_text(e));
  }
  Checkpoint checkpoint;
  checkpoint.path = path;
  c10::IValue header_text, stored_checksum;
  json header;
  try {
    archive.read("header", header_text);
    header = json::parse(header_text.toStringRef());
  } catch (const std::exception& e) {
    throw not_ours(path, e.what());
  }
  const auto stated = header.is_object() ? header.find("format") : header.end();
  const std::string format = stated != header.end() && stated->is_string() ? stated->get<std::string>() : "";
  if (format == "matpredict-checkpoint-1")
    throw not_ours(path, "written by an earlier matpredict, without a checksum: train it again");
  if (format != kFormat) throw not_ours(path, "unknown format \"" + format + "\"");
  try {
    archive.read("model", checkpoint.model_state);
    archive.read("optimizer", checkpoint.optimizer_state);
    archive.read("crc32", stored_checksum);
  } catch (const std::exception& e) {
    throw not_ours(path, torch_error_text(e));
  }
  for (const torch::Tensor* state : {&checkpoint.model_state, &checkpoint.optimizer_state})
    if (state->scalar_type() != torch::kUInt8 || state->dim() != 1 || !state->is_contiguous())
      throw not_ours(path, "its states are not byte arrays");
  if (!stored_checksum.isInt() ||
      stored_checksum.toInt() != checksum(header_text.toStringRef(), checkpoint.model_state, checkpoint.optimizer_state))
    throw std::runtime_error(path.string() +
                             " is damaged: its contents do not match the checksum written with them (a copy cut "
                             "short or changed on disk); use another checkpoint or train again");
  try {
    checkpoint.header = header_from_json(header);
  } catch (const json::exception& e) {
    // nlohmann's text after its "[json.exception.type_error.302] " tag: "type must be string, but is number".
    const std::string text = e.what();
    const size_t tag_end = text.find("] ");
    throw not_ours(path, "its header is damaged: " + (tag_end == std::string::npos ? text : text.substr(tag_end + 2)));
  } catch (const std::exception& e) {
    throw not_ours(path, e.what());
  }
  return checkpoint;
}

std::shared_ptr<RegressorImpl> load_model(const Checkpoint& checkpoint) {
  const CheckpointHeader& h = checkpoint.header;
  std::shared_ptr<RegressorImpl> model =
      make_regressor(architecture_named(h.network).architecture, h.layout.output_channels(), h.width_divisor);
  try {
    torch::serialize::InputArchive archive = open_state(checkpoint.model_state);
    model->load(archive);
  } catch (const std::exception& e) {
    throw std::runtime_error(checkpoint.path.string() + ": its weights do not fit " + h.network + " with " +
                             std::to_string(h.layout.output_channels()) + " outputs (" +
                             torch_error_text(e) + ")");
  }
  if (const std::optional<std::string> tensor = first_non_finite_tensor(*model))
    throw std::runtime_error(checkpoint.path.string() + ": its weight " + *tensor +
                             " holds a NaN or an infinity (the training that wrote it diverged); use an earlier "
                             "checkpoint or train again with a lower learning rate");
  return model;
}

std::optional<std::string> first_non_finite_tensor(const torch::nn::Module& module) {
  for (const auto& named : {module.named_parameters(), module.named_buffers()})
    for (const auto& tensor : named)
      if (tensor.value().is_floating_point() && !torch::isfinite(tensor.value()).all().item<bool>())
        return tensor.key();
  return std::nullopt;
}

void load_optimizer(const Checkpoint& checkpoint, torch::optim::Optimizer& optimizer) {
  try {
    torch::serialize::InputArchive archive = open_state(checkpoint.optimizer_state);
    optimizer.load(archive);
  } catch (const std::exception& e) {
    throw std::runtime_error(checkpoint.path.string() + ": its optimiser state does not fit this optimiser (" +
                             torch_error_text(e) + ")");
  }
}

}  // namespace matlearn
