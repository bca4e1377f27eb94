#pragma once
// Pictures of predictions as 8-bit PNG files, one tile per map at the map's size, one-channel maps
// in grey. Files are written whole or not at all; given an AtomicFileSet, each is staged there to
// appear with the set's other files.
#include <filesystem>

#include "matbase/file/atomic_file.h"
#include "matlearn/evaluation/evaluator.h"
#include "matlearn/evaluation/inference.h"

namespace matlearn {

// The sample's input beside, per map, truth | prediction | absolute error on the object (x4,
// clamped, black off it): one row per map.
void write_panel(const std::filesystem::path& path, const SamplePredictions& sample,
                 matbase::AtomicFileSet* set = nullptr);

// The input, then each predicted map, in one row; map pixels off the mask are black.
void write_prediction_strip(const std::filesystem::path& path, const matbase::FloatImage& input, const matbase::Mask& mask,
                            const PredictedMaps& predicted, matbase::AtomicFileSet* set = nullptr);

// One map as a PNG (RGB, or grey for one channel), black off the mask.
void write_map_png(const std::filesystem::path& path, const matbase::FloatImage& map, const matbase::Mask& mask,
                   matbase::AtomicFileSet* set = nullptr);

}  // namespace matlearn
