#pragma once
// What can be checked before anything is written: each object loads, every one of its parts is
// in exactly one slot, and every candidate material has a class, so that its pixels are never
// labelled background (the repository's silent label loss, its W12). A run that would fail on
// these fails before its first file.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/dataset_plan.h"

namespace matdataset {

// The parts of each slot of object `object`, given its part names and count: those a slot
// names, and for the one slot that names none, every other part. Throws matbase::InputError naming the
// configuration's key for an unknown part, a part in two slots, or a part in none.
std::vector<std::vector<uint32_t>> parts_of_slots(const DatasetConfig& config, size_t object,
                                                  const std::vector<std::string>& part_names, size_t part_count);

// Loads each object's geometry (not its textures) and checks its slots, and checks each
// candidate's class. Throws matbase::InputError. Returns what the mesh files hold that their
// readers do not apply, "<file>: <note>" (matgeom::ObjectAsset::notes).
std::vector<std::string> check_before_writing(const DatasetConfig& config);

// Throws matbase::InputError when the output folder holds object or variant folders the plan does not make
// (a second run with other objects, or fewer variants, into the same folder): their frames would
// be in none of the split files this run writes, and two datasets would pass for one. Also when a
// variant folder records another configuration: both before the split files are written.
void check_output_matches_plan(const DatasetConfig& config, const DatasetPlan& plan);

}  // namespace matdataset
