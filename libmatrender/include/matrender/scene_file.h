#pragma once
// Reading a JSON scene file (format: docs/scene_format.md) into a SceneDescription. Only checks
// and describes: referenced files must exist, but nothing is loaded here.
#include <string>
#include <vector>

#include "matbase/document/document_node.h"
#include "matrender/scene_description.h"

namespace matrender {

// Throws matbase::InputError naming the file and the JSON pointer of the offending value, e.g.
// "scene.json: /objects/1/transform/scale: expected a positive number".
SceneDescription read_scene_file(const std::string& path);
// The same from JSON text: `source` names it in errors ("the scene: /render/spp: ..."), and its
// relative paths resolve against `folder`. A mesh object whose "mesh" is {"given": K} takes the
// K-th of `given`: an object a program made in memory (the Python package's meshes from arrays),
// with every other key of a mesh object read as for a file.
SceneDescription read_scene_text(const std::string& json, const std::string& source, const std::string& folder,
                                 const std::vector<GivenObject>& given = {});
// A scene file's "camera" value alone, as JSON text; pointers start at it ("the camera: /grid/cell/0: ...").
CameraDescription read_camera_text(const std::string& json, const std::string& source);
// A scene file's lighting alone: a JSON object with its "lights" (required) and "background"
// (default black), read as the scene file reads them.
struct SceneLighting {
  LightsDescription lights;
  BackgroundDescription background = glm::vec3(0.0f);
};
SceneLighting read_lighting_text(const std::string& json, const std::string& source, const std::string& folder);
// A mesh object's "auto_smooth_deg" (matgeom::ObjectReadOptions), an angle in (0, 180]: the one
// reading of it, which make_dataset's objects share.
double read_auto_smooth_deg(const matbase::DocumentNode& node);

}  // namespace matrender
