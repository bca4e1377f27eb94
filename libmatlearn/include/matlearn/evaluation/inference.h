#pragma once
// A trained regressor applied to one image: the predicted maps, each in [0, 1] (the sigmoid of
// its channels, as in training and evaluation).
#include <string>
#include <vector>

#include "matbase/image/float_image.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/checkpoint.h"

namespace matlearn {

struct PredictedMaps {
  std::vector<std::string> names;  // map_name of each output group
  std::vector<matbase::FloatImage> maps;         // the input's size, the group's channels
};

// `rgb`: H x W x 3 in [0, 1]; H and W must suit the network (multiples of its side_multiple).
PredictedMaps predict_maps(RegressorImpl& model, const CheckpointHeader& header, const matbase::FloatImage& rgb);

}  // namespace matlearn
