# The glTF importer Blender 3.4 ships, as Debian 12 can run it: imported by the scripts here that
# read glTF files (blender_gltf_import.py, cycles_render.py).
import bpy
import numpy

# Debian 12's Blender 3.4 importer still uses numpy.bool, which Debian's numpy 1.24 removed
# (set_poly_smoothing fails on every file with normals); the alias is what it meant.
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def import_gltf(path):
    """Imports the file into the current scene with the importer's defaults, as a user would."""
    bpy.ops.import_scene.gltf(filepath=path)
