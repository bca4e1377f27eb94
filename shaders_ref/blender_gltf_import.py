# Imports a glTF file with the glTF importer Blender 3.4 ships and writes, for every material it
# made, the inputs of its Principled BSDF and of the Velvet BSDF added to it (KHR_materials_sheen),
# if any: each input's default value, whether a node feeds it, and the Mapping node
# (KHR_texture_transform) in front of the image that feeds it, if any. A velvet counts only where
# an Add Shader joins it to the Principled BSDF on the way to the Material Output.
# The optional tests compare this with what read_gltf makes of the same file.
#
#   blender -b --factory-startup -noaudio --python-exit-code 1 -P blender_gltf_import.py -- FILE.glb OUT.json
import json
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # blender_gltf.py lies beside this script
from blender_gltf import import_gltf  # noqa: E402


def upstream_image(socket):
    """The first Image Texture node found walking the links up from `socket`."""
    pending = [link.from_node for link in socket.links]
    seen = set()
    while pending:
        node = pending.pop(0)
        if node.name in seen:
            continue
        seen.add(node.name)
        if node.type == "TEX_IMAGE":
            return node
        for upstream in node.inputs:
            pending.extend(link.from_node for link in upstream.links)
    return None


def uv_mapping(socket):
    """The Mapping node feeding the image behind `socket`: location, Z rotation, scale (x, y)."""
    image = upstream_image(socket)
    if image is None or not image.inputs["Vector"].is_linked:
        return None
    mapping = image.inputs["Vector"].links[0].from_node
    if mapping.type != "MAPPING":
        return None
    return {
        "vector_type": mapping.vector_type,
        "location": list(mapping.inputs["Location"].default_value)[:2],
        "rotation_z": mapping.inputs["Rotation"].default_value[2],
        "scale": list(mapping.inputs["Scale"].default_value)[:2],
    }


def node_inputs(node):
    inputs = {}
    for socket in node.inputs:
        if not hasattr(socket, "default_value"):
            continue
        value = socket.default_value
        value = list(value)[:3] if hasattr(value, "__len__") else value
        inputs[socket.name] = {"value": value, "linked": socket.is_linked,
                               "mapping": uv_mapping(socket) if socket.is_linked else None}
    return inputs


def only_node(material, node_type, allow_none=False):
    nodes = [n for n in material.node_tree.nodes if n.type == node_type]
    if len(nodes) > 1 or (not nodes and not allow_none):
        raise RuntimeError(f"material {material.name}: {len(nodes)} {node_type} nodes")
    return nodes[0] if nodes else None


def feeds_output_through_add(node, principled, output):
    """node and principled are the two inputs of an Add Shader linked to the output's Surface."""
    surface = output.inputs["Surface"]
    if not surface.is_linked or surface.links[0].from_node.type != "ADD_SHADER":
        return False
    add = surface.links[0].from_node
    sources = {link.from_node.name for socket in add.inputs for link in socket.links}
    return sources == {node.name, principled.name}


def material_nodes(material):
    principled = only_node(material, "BSDF_PRINCIPLED")
    nodes = {"Principled BSDF": node_inputs(principled)}
    velvet = only_node(material, "BSDF_VELVET", allow_none=True)
    if velvet is not None:
        if not feeds_output_through_add(velvet, principled, only_node(material, "OUTPUT_MATERIAL")):
            raise RuntimeError(f"material {material.name}: the Velvet BSDF is not added to the Principled BSDF")
        nodes["Velvet BSDF"] = node_inputs(velvet)
    return nodes


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 2:
        sys.exit("usage: blender -b --factory-startup -P blender_gltf_import.py -- FILE.glb OUT.json")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import_gltf(arguments[0])
    materials = {m.name: material_nodes(m) for m in bpy.data.materials if m.use_nodes}
    with open(arguments[1], "w") as f:
        json.dump(materials, f)


main()
