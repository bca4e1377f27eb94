#pragma once
// A scene file's lamps (docs/scene_format.md, "Lights"): each described lamp of matrender/lamp.h
// has its "type" and reads its own keys, every value checked where it is read.
#include <string>
#include <vector>

#include "matbase/document/document_node.h"
#include "matrender/lamp.h"

namespace matrender {

// The "type" of each alternative of `Lamp`, in its order: "area", "point", "spot", "sun".
const std::vector<std::string>& scene_file_lamp_types();

// One entry of a scene file's "lights" list, as its "type" says.
Lamp read_lamp(const matbase::DocumentNode& node);

}  // namespace matrender
