"""matpredict from Python: render material scenes to numpy arrays.

    import matpredict
    scene = matpredict.load_scene("scene.json")
    frame = matpredict.render(scene, spp=64, aovs="all")
    frame["color"].shape, frame["roughness"].dtype   # (H, W, 3), float32

Every array is (height, width, channels), row 0 at the top; help(matpredict.render) and
matpredict.aov_info() give each one's dtype, colour space and frame. One built scene renders from
any number of cameras, e.g. every view of the paper's 16 x 32 grid around its objects:

    for name, camera in scene.grid_cameras().items():
        frame = matpredict.render(scene, camera=camera)   # camera.camera_to_world, camera.intrinsics

A scene may also be a dict with the scene file's keys, holding numpy values, paths and meshes
from arrays (matpredict.Mesh). The paper's eight image metrics take numpy arrays too:

    matpredict.ssim(truth, prediction, data_range=1.0, mask=object_mask)
    matpredict.score_map(truth, prediction, mask=object_mask)   # {"RMSE": ..., "PSNR": ..., ...}

and datasets are read as dicts of arrays (matpredict.DatasetReader), or as a torch Dataset
(matpredict.torch_data.MaterialDataset, which imports torch). A trained checkpoint predicts maps:

    model = matpredict.load_model("train_output/checkpoints/best.pt")   # loads libtorch
    maps = model.predict(sample["input"])                               # {"base_color": ..., ...}

make_dataset(dict) makes a dataset as the command line does. Errors in a scene file, a
configuration or a dataset raise matpredict.InputError (a ValueError) naming the file, the JSON
pointer or key, and the problem. docs/python.md documents every array.
"""
from . import _core
from ._core import (
    Camera,
    DatasetError,
    DatasetReader,
    InputError,
    Mesh,
    Scene,
    aov_info,
    aov_names,
    builtin_objects,
    display_image,
    fsim,
    issm,
    load_scene,
    make_dataset,
    mask_box,
    material_classes,
    psnr,
    render,
    rmse,
    sam_degrees,
    score_map,
    sre,
    ssim,
    uiq,
    verify_dataset,
)

__all__ = [
    "Camera",
    "DatasetError",
    "DatasetReader",
    "InputError",
    "Mesh",
    "Scene",
    "aov_info",
    "aov_names",
    "builtin_objects",
    "display_image",
    "fsim",
    "isolate",
    "issm",
    "load_scene",
    "make_dataset",
    "mask_box",
    "material_classes",
    "psnr",
    "render",
    "rmse",
    "sam_degrees",
    "score_map",
    "sre",
    "ssim",
    "uiq",
    "verify_dataset",
]


# The trained networks load libtorch, so their module is imported when first asked for.
_LEARN = ("Model", "load_model")


def isolate(image, *, segmenter="grabcut", **options):
    if isinstance(segmenter, str) and segmenter.startswith("sam:"):
        return _learn_module("isolate").isolate(image, segmenter=segmenter, **options)
    return _core.isolate(image, segmenter=segmenter, **options)


isolate.__doc__ = _core.isolate.__doc__


def _learn_module(name):
    """matpredict._learn, imported on first use (libtorch), for `name`."""
    import importlib

    try:
        return importlib.import_module("._learn", __name__)
    except ModuleNotFoundError as missing:
        raise ImportError(f"matpredict.{name} needs the extension matpredict._learn (libtorch), which this build "
                          "has not made: cmake --build build --target matpredict_python_learn") from missing


def __getattr__(name):
    if name in _LEARN:
        return getattr(_learn_module(name), name)
    raise AttributeError(f"module 'matpredict' has no attribute '{name}'")


def __dir__():
    return sorted(list(globals()) + list(_LEARN))
