"""Type stubs of matpredict's extension module."""
import os
from typing import Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

class InputError(ValueError):
    """A bad file, key or value; the message names the file, the JSON pointer or key, and the problem."""

class DatasetError(InputError):
    """A dataset's file missing, unreadable or refused; the message names it."""

class DatasetReader:
    """The samples of a MatPredict dataset, each a dict of numpy arrays."""
    def __init__(self, root: Union[str, "os.PathLike[str]"], *, size: int = 224, linear_albedo: bool = False, read_normal: bool = False,
                 split_file: Optional[str] = None, split: str = "train") -> None: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Dict[str, object]: ...
    @property
    def ids(self) -> List[str]: ...
    @property
    def root(self) -> str: ...

def make_dataset(configuration: Dict[str, object], *, output: Union[None, str, "os.PathLike[str]"] = None, threads: int = 0,
                 shard: str = "0/1", progress: Optional[Callable[[int, int], object]] = None) -> Dict[str, object]:
    """Renders the dataset the configuration describes (make_dataset's YAML keys); resumable."""

def verify_dataset(root: Union[str, "os.PathLike[str]"]) -> Dict[str, object]:
    """{'variants': int, 'frames': int, 'problems': List[str]}"""

class Mesh:
    """A triangle mesh from numpy arrays, for a scene dict's object {"mesh": Mesh(...)}."""
    def __init__(self, positions: npt.ArrayLike, triangles: npt.ArrayLike, *, uvs: Optional[npt.ArrayLike] = None,
                 normals: Optional[npt.ArrayLike] = None, parts: Optional[npt.ArrayLike] = None,
                 part_names: Optional[Sequence[str]] = None) -> None: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def part_names(self) -> List[str]: ...

class Camera:
    """A pinhole camera placed in a scene, Blender's convention (looks down its -Z, +Y up in the image)."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def fov_deg(self) -> float:
        """Vertical field of view in degrees."""
    @property
    def camera_to_world(self) -> npt.NDArray[np.float64]:
        """(4, 4): columns are the camera's +X (right), +Y (up), +Z (backward) and its position, world frame."""
    @property
    def position(self) -> npt.NDArray[np.float64]:
        """(3,) metres, world frame (Z up)."""
    @property
    def intrinsics(self) -> npt.NDArray[np.float64]:
        """(3, 3) OpenCV K: camera frame x right, y down, z forward; (0, 0) the top-left pixel's centre."""

class Scene:
    """A scene loaded and built, ready to render (load_scene)."""
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def spp(self) -> int: ...
    @property
    def seed(self) -> int: ...
    @property
    def exposure_stops(self) -> float: ...
    @property
    def bounds(self) -> Tuple[Tuple[float, float, float], float]:
        """((x, y, z), radius): the smallest sphere around all objects, metres."""
    @property
    def notes(self) -> List[str]:
        """What the scene's mesh files hold that their readers do not apply: '<file>: <note>'."""
    @property
    def camera(self) -> Camera:
        """The scene file's camera."""
    def make_camera(self, description: Dict[str, object]) -> Camera:
        """The camera a dict with a scene file camera's keys places in this scene."""
    def grid_cameras(self, grid: Optional[Dict[str, object]] = None) -> Dict[str, Camera]:
        """Every cell of a grid around the objects ({view name: Camera}); None: the paper's 16 x 32 grid."""

def load_scene(scene: Union[str, "os.PathLike[str]", Dict[str, object]]) -> Scene:
    """Reads a JSON scene file (docs/scene_format.md), or a dict with its keys, and builds it."""

def render(
    scene: Scene,
    *,
    camera: Union[None, Camera, Dict[str, object]] = None,
    spp: Optional[int] = None,
    seed: Optional[int] = None,
    threads: int = 0,
    aovs: Union[None, str, Sequence[str]] = None,
    progress: Optional[Callable[[float], object]] = None,
) -> Dict[str, npt.NDArray[Union[np.float32, np.int32]]]:
    """Renders the scene; a dict of (height, width, channels) arrays: 'color' and the AOVs asked for."""

def aov_names() -> List[str]:
    """Every AOV's name, in the order render() returns them."""

def display_image(color: npt.ArrayLike, *, exposure_stops: float = 0.0) -> npt.NDArray[np.uint8]:
    """Linear RGB (H, W, 3) as the 8-bit sRGB image render_object's PNG holds."""

def builtin_objects() -> List[str]:
    """The built-in objects' names ({"builtin": name})."""

def material_classes() -> Dict[str, int]:
    """{class name: label id} of the procedural library's classes ({"class": name})."""

def isolate(image: npt.ArrayLike, *, mask: Optional[npt.ArrayLike] = None,
            box: Optional[Tuple[int, int, int, int]] = None, points: Optional[Sequence[Sequence[int]]] = None,
            segmenter: str = "grabcut", size: int = 224, background: str = "black") -> Dict[str, object]:
    """The object isolated as evaluate --image does: {'mask', 'input', 'input_mask', 'crop'}."""

def aov_info() -> Dict[str, Dict[str, object]]:
    """{name: {'dtype', 'channels', 'default', 'description'}} for 'color' and every AOV."""

ImageArray = npt.ArrayLike  # (H, W) or (H, W, C), any numeric dtype
MaskArray = Optional[npt.ArrayLike]  # None, or (H, W) with nonzero entries inside

def rmse(truth: ImageArray, prediction: ImageArray, *, data_range: float = 1.0, mask: MaskArray = None) -> float: ...
def psnr(truth: ImageArray, prediction: ImageArray, *, data_range: float = 1.0, mask: MaskArray = None) -> float: ...
def ssim(truth: ImageArray, prediction: ImageArray, *, data_range: float = 1.0, mask: MaskArray = None) -> float: ...
def fsim(truth: ImageArray, prediction: ImageArray, *, data_range: float = 1.0, mask: MaskArray = None) -> float: ...
def sre(truth: ImageArray, prediction: ImageArray, *, mask: MaskArray = None) -> float: ...
def issm(truth: ImageArray, prediction: ImageArray, *, mask: MaskArray = None) -> float: ...
def uiq(truth: ImageArray, prediction: ImageArray, *, mask: MaskArray = None) -> float: ...
def sam_degrees(truth: ImageArray, prediction: ImageArray, *, mask: MaskArray = None) -> float: ...
def score_map(truth: ImageArray, prediction: ImageArray, *, mask: MaskArray = None,
              convention: str = "correct") -> Dict[str, float]:
    """All eight metrics: {'RMSE', 'PSNR', 'SRE', 'SSIM', 'FSIM', 'UIQ', 'SAM', 'ISSM'}."""
