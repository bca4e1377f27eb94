#pragma once
// One frame of a dataset as a render_object scene file (docs/scene_format.md), made from the
// dataset's own records: the configuration metadata.json holds (the object, its slots' materials,
// the render settings), the variant's materials and the frame's seed (metadata.json's provenance),
// and the frame's camera, lighting and exposure (transforms.json). render_object --dataset-frame
// renders it; the image it writes is the dataset's, bit for bit.
#include <filesystem>
#include <string>

namespace matdataset {

struct FrameScene {
  std::string json;    // the scene file's text
  std::string folder;  // what its relative paths resolve against
};

// `frame`: a variant folder and a frame's stem ("dataset/vase/var000/003"), or any of the frame's
// files ("dataset/vase/var000/images/003.png"). The recorded configuration's relative paths (mesh
// files, material folders) resolve against the folder it was read from: the one its provenance
// records, or else the dataset's parent folder, where make_dataset's configuration usually sits. Throws matbase::InputError naming the file and what is missing.
FrameScene dataset_frame_scene(const std::filesystem::path& frame);

}  // namespace matdataset
