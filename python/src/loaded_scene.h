#pragma once
// A scene as described and as built, ready to render any number of times (matpredict.Scene).
#include "matrender/scene_builder.h"
#include "matrender/scene_description.h"

namespace matpredict_python {

struct LoadedScene {
  matrender::SceneDescription description;
  matrender::BuiltScene built;
};

}  // namespace matpredict_python
