#include "matdataset/maker/dataset_checks.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "matbase/file/output_folder.h"
#include "matbase/image/image_header.h"
#include "matbase/memory_limit.h"
#include "matbase/pi.h"
#include "matdataset/format/dataset_folders.h"
#include "matdataset/format/dataset_writer.h"
#include "matdataset/maker/distractors.h"
#include "matdataset/maker/object_renderer.h"
#include "matgeom/bounding_sphere.h"
#include "matgeom/builtin/builtin_objects.h"
#include "matgeom/io/mesh_io.h"
#include "matgeom/mesh_parts.h"
#include "matmaterial/folder/material_folder.h"
#include "matmaterial/material_classes.h"

namespace matdataset {
namespace {

std::string object_key(size_t object) { return "objects." + std::to_string(object); }

std::string quoted(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "\"" : ", \"") + name + "\"";
  return text.empty() ? "none" : text;
}

}  // namespace

std::vector<std::vector<uint32_t>> parts_of_slots(const DatasetConfig& config, size_t index,
                                                  const std::vector<std::string>& part_names, size_t part_count) {
  const ObjectConfig& object = config.objects[index];
  std::vector<int> slot_of_part(part_count, -1);
  std::vector<std::vector<uint32_t>> parts(object.slots.size());
  for (size_t s = 0; s < object.slots.size(); ++s)
    for (const std::string& name : object.slots[s].parts) {
      const auto it = std::find(part_names.begin(), part_names.end(), name);
      const std::string key = config.source + ": " + object_key(index) + ".slots." + object.slots[s].key;
      if (it == part_names.end() || static_cast<size_t>(it - part_names.begin()) >= part_count)
        throw matbase::InputError(key + ": the object has no part named \"" + name + "\" (its parts: " +
                         quoted(part_names) + ")");
      const auto part = static_cast<size_t>(it - part_names.begin());
      if (slot_of_part[part] >= 0)
        throw matbase::InputError(key + ": part \"" + name + "\" is in slot \"" +
                         object.slots[static_cast<size_t>(slot_of_part[part])].key + "\" already");
      slot_of_part[part] = static_cast<int>(s);
      parts[s].push_back(static_cast<uint32_t>(part));
    }
  for (size_t s = 0; s < object.slots.size(); ++s)
    if (object.slots[s].parts.empty())
      for (size_t part = 0; part < part_count; ++part)
        if (slot_of_part[part] < 0) slot_of_part[part] = static_cast<int>(s), parts[s].push_back(static_cast<uint32_t>(part));
  for (size_t part = 0; part < part_count; ++part)
    if (slot_of_part[part] < 0)
      throw matbase::InputError(config.source + ": " + object_key(index) + ".slots: part \"" +
                       (part < part_names.size() ? part_names[part] : std::to_string(part)) +
                       "\" is in no slot, so it would have no material and no label; list it in a slot, or leave "
                       "one slot's part list out so it takes every part not listed");
  return parts;
}


namespace {

// Throws matbase::InputError when the cameras would see object `o` (framed as `f`) smaller than a
// pixel in every frame, as a fixed radius of 5 km does: frames without the object train to a loss
// of 0. The radius rule and the sphere's angular size are the renderer's (object_renderer.h).
void check_object_in_view(const DatasetConfig& config, size_t o, const ObjectFraming& f) {
  const matgeom::Sphere& bounds = f.bounds;
  const int height = config.render.height;
  const double radius = f.grid.radius;
  const double farthest = radius + glm::length(bounds.center - f.grid.center);
  const double half_fov = 0.5 * config.camera.vertical_fov_deg * matbase::kPi / 180.0;
  // The sphere's projected radius in pixels at the frame's centre, seen from its farthest camera.
  const double pixels = bounds.radius / farthest / std::tan(half_fov) * 0.5 * height;
  if (pixels < 0.5)
    throw matbase::InputError(fmt::format("{}: camera.radius: the cameras are {:.4g} m from {}, which is {:.3g} m across: it "
                                 "would cover less than a pixel of every frame",
                                 config.source, radius, object_key(o), 2.0 * bounds.radius));
}

// Throws matbase::InputError when object `o`'s distractors, at their most, largest and closest,
// could not stand apart on its floor (distractors_fit).
void check_distractors_fit(const DatasetConfig& config, size_t o, const matgeom::TriangleMesh& mesh, const ObjectFraming& f) {
  const SurroundingsConfig& surroundings = config.objects[o].surroundings;
  if (surroundings.kind != SurroundingsKind::Distractors) return;
  const DistractorsConfig& distractors = surroundings.distractors;
  // Their mesh files are read when the object's scene is built, after earlier objects' files.
  for (const DistractorObject& object : distractors.objects)
    if (const auto* file = std::get_if<matrender::MeshFile>(&object)) try {
        matgeom::read_object(file->path, file->read_options);
      } catch (const std::exception& e) {
        throw matbase::InputError(config.source + ": " + object_key(o) + ".surroundings.distractors.objects: " + e.what());
      }
  const matgeom::Sphere& bounds = f.bounds;
  const double reach = kDistractorReachOfRoom * surroundings.room_size() * f.grid.radius;
  const double target_radius = footprint(mesh).radius;
  if (!distractors_fit(distractors, target_radius, bounds.radius, reach))
    throw matbase::InputError(fmt::format(
        "{}: {}.surroundings.distractors.count: {} distractors up to {} times {}'s size ({:.3g} m across), {} of "
        "its footprint apart, cannot stand apart within the {:.3g} m the floor reaches from it; ask for fewer or smaller ones, "
        "or a larger surroundings.size",
        config.source, object_key(o), distractors.count.high, distractors.scale.high, config.objects[o].name,
        2.0 * bounds.radius, distractors.gap.low, reach));
}

// Object `o`'s target parts of its scan alone, or matbase::InputError when the scan has no part of
// a target's name or nothing but the target (no room to put it back in).
matgeom::ObjectAsset scan_target(const DatasetConfig& config, size_t o, const matgeom::ObjectAsset& scan) {
  const std::string key = config.source + ": " + object_key(o) + ".surroundings.target: ";
  const matgeom::NamedParts target = matgeom::named_parts(scan.mesh, config.objects[o].surroundings.scan.target);
  if (target.missing)
    throw matbase::InputError(fmt::format("{}the scan {} has no part \"{}\" (its parts: {})", key,
                                          std::get<matrender::MeshFile>(config.objects[o].source).path,
                                          *target.missing, quoted(scan.mesh.part_names)));
  std::vector<bool> rest = target.named;
  rest.flip();
  try {
    matgeom::kept_parts(scan, rest);
  } catch (const std::invalid_argument&) {
    throw matbase::InputError(key + "every part of the scan with a triangle is the target, so no room is left to put "
                              "it back in; name fewer parts, or use surroundings `floor`");
  }
  try {
    return matgeom::kept_parts(scan, target.named);
  } catch (const std::invalid_argument&) {
    throw matbase::InputError(key + "the target's parts have no triangle");
  }
}

}  // namespace

std::vector<std::string> check_before_writing(const DatasetConfig& config) {
  std::vector<std::string> notes;
  if (const std::optional<std::string> problem = matbase::output_folder_problem(config.output))
    throw matbase::InputError("output: " + *problem + "; give --output a folder you can write to");
  // A frame's buffers, and the maps the writer encodes from them (about as much again).
  const int w = config.render.width, h = config.render.height;
  if (const auto problem = matbase::memory_problem(
          2.0 * matrender::FrameBuffers::bytes_for(w, h, dataset_aovs()),
          fmt::format("the buffers and maps of a {} x {} frame", w, h)))
    throw matbase::InputError(config.source + ": render.resolution: " + *problem);
  for (size_t o = 0; o < config.objects.size(); ++o) {
    const ObjectConfig& object = config.objects[o];
    matgeom::ObjectAsset asset;
    const auto* mesh_file = std::get_if<matrender::MeshFile>(&object.source);
    try {
      if (mesh_file) {
        asset = matgeom::read_object(mesh_file->path, mesh_file->read_options);
      } else {
        const auto& builtin = std::get<matrender::BuiltinObject>(object.source);
        asset = matgeom::make_builtin_object(builtin.name, builtin.seed);
      }
    } catch (const std::exception& e) {
      throw matbase::InputError(config.source + ": " + object_key(o) + ": " + e.what());
    }
    if (object.surroundings.kind == SurroundingsKind::Scan) asset = scan_target(config, o, asset);
    if (mesh_file)
      for (const std::string& note : asset.notes) matgeom::add_note(notes, mesh_file->path + ": " + note);
    // Every candidate is a textured material, and without UVs a texture shows one texel.
    if (object.uv_pass == matrender::UvPassMode::Never && asset.mesh.uvs.empty())
      throw matbase::InputError(config.source + ": " + object_key(o) +
                       ".uv_pass: never, but the mesh has no texture coordinates, so each material would show one "
                       "texel of its maps; use when_missing (the default) to give it the paper's UV pass");
    // A scale of the UV pass's density needs the pass to run.
    if (object.uv_scales != std::vector<double>{1.0} && object.uv_pass == matrender::UvPassMode::WhenMissing && !asset.mesh.uvs.empty())
      throw matbase::InputError(config.source + ": " + object_key(o) +
                                ".uv_scale: the mesh has texture coordinates of its own, so the UV pass does not run "
                                "(uv_pass: when_missing) and there is no texel density to scale; use uv_pass: always");
    const ObjectFraming framing = object_framing(config, asset.mesh);
    check_object_in_view(config, o, framing);
    check_distractors_fit(config, o, asset.mesh, framing);
    const size_t part_count = std::max({static_cast<size_t>(asset.mesh.part_count()), asset.materials.size(), size_t{1}});
    parts_of_slots(config, o, asset.mesh.part_names, part_count);
    if (config.paper_texture_layout && object.slots.size() != 1)
      throw matbase::InputError(config.source + ": paper_texture_layout: object \"" + object.name + "\" has " +
                       std::to_string(object.slots.size()) +
                       " slots, but the paper's layout files a screenshot under one material: give it one slot");
    for (const SlotConfig& slot : object.slots)
      for (const MaterialCandidate& candidate : slot.candidates) {
        const auto* folder = std::get_if<std::string>(&candidate.source);
        if (!folder) continue;
        // Its maps are decoded when a variant first uses them, after records are written.
        for (const std::filesystem::directory_entry& file : std::filesystem::directory_iterator(*folder))
          if (const std::optional<std::string> problem = matbase::declared_size_problem(file.path()))
            throw matbase::InputError(config.source + ": " + object_key(o) + ".materials." + slot.key + ": " +
                             file.path().string() + ": " + *problem);
        if (matmaterial::material_class_of_folder(candidate.name)) continue;
        // A folder whose name names no class may still say it in its metadata.
        std::optional<matmaterial::MaterialClass> found;
        try {
          found = matmaterial::read_material_folder(*folder).material_class;
        } catch (const std::exception& e) {
          throw matbase::InputError(config.source + ": " + object_key(o) + ".materials." + slot.key + ": " + e.what());
        }
        if (!found || *found == matmaterial::MaterialClass::Background)
          throw matbase::InputError(config.source + ": " + object_key(o) + ".materials." + slot.key + ": material folder \"" +
                           candidate.spelled +
                           "\" has no material class, so its pixels would be labelled background; name the folder "
                           "after its class (\"wood_oak\") or give its metadata.json a category");
      }
  }
  return notes;
}

// The configuration a variant folder's metadata.json records (its provenance), or nothing when
// it has none that parses.
std::optional<std::string> recorded_configuration(const std::filesystem::path& variant) {
  std::ifstream in(variant / "metadata.json");
  if (!in) return std::nullopt;
  const nlohmann::json metadata = nlohmann::json::parse(in, nullptr, false);
  const nlohmann::json::json_pointer pointer("/provenance/configuration");
  if (metadata.is_discarded() || !metadata.is_object() || !metadata.contains(pointer) || !metadata[pointer].is_string())
    return std::nullopt;
  return metadata[pointer].get<std::string>();
}

void check_output_matches_plan(const DatasetConfig& config, const DatasetPlan& plan) {
  namespace fs = std::filesystem;
  const fs::path root(config.output);
  if (!fs::is_directory(root)) return;
  // Hidden entries are the writer's temporaries (atomic_file.h).
  const auto listed_folders = [](const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
      if (entry.is_directory() && entry.path().filename().string()[0] != '.')
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  };
  std::vector<std::string> strangers;  // folders the plan does not make
  std::vector<fs::path> made;           // variant folders it makes, from an earlier run
  for (const std::string& name : listed_folders(root)) {
    if (name == kConfigFolder || name == kPreviewFolder || name == kPaperTexturesFolder) continue;
    const auto object = std::find_if(config.objects.begin(), config.objects.end(),
                                     [&](const ObjectConfig& o) { return o.name == name; });
    if (object == config.objects.end()) {
      strangers.push_back(name + "/");
      continue;
    }
    const size_t index = static_cast<size_t>(object - config.objects.begin());
    const size_t count = plan.variants[index].size();
    for (const std::string& variant : listed_folders(root / name)) {
      bool planned = false;
      for (size_t v = 0; v < count && !planned; ++v) planned = variant == variant_folder_name(v, count);
      if (planned) made.push_back(root / name / variant);
      else strangers.push_back(name + "/" + variant + "/");
    }
  }
  if (!strangers.empty()) {
    std::string shown;
    for (size_t k = 0; k < std::min<size_t>(strangers.size(), 5); ++k) shown += (k ? ", " : "") + strangers[k];
    if (strangers.size() > 5) shown += fmt::format(" and {} more", strangers.size() - 5);
    throw matbase::InputError(config.output + ": holds " + shown +
                     ", which this configuration does not make; their frames would be in none of its split files. "
                     "Render into another --output, or remove them");
  }
  // Found before the split files are written, which a refusal at the variant would leave listing
  // this run's frames.
  for (const fs::path& variant : made)
    if (const std::optional<std::string> recorded = recorded_configuration(variant);
        recorded && *recorded != config.canonical_yaml)
      throw matbase::InputError((variant / "metadata.json").string() +
                       ": this variant was made with other settings (the configuration it records differs from "
                       "this run's); render into another --output, or delete the folder to render it again");
}

}  // namespace matdataset
