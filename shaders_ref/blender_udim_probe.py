# Renders, with Blender 3.4 Cycles, three quads whose UVs lie in three UDIM tiles of a set made
# of tiles 1001 (red) and 1011 (blue): u in (-0.8, -0.2) (left of tile 1001), tile 1002 (which
# the set lacks) and tile 1011, each through an emission of the image. Writes each quad's
# centre pixel as linear RGB to OUT.json, and leaves the tiles in FOLDER for our lookups.
#
#   blender -b --factory-startup -noaudio --python-exit-code 1 -P blender_udim_probe.py -- FOLDER OUT.json
import json
import os
import sys

import bpy


def write_tile(folder, number, rgba):
    image = bpy.data.images.new(f"tile{number}", 4, 4)
    image.pixels = list(rgba) * 16
    image.filepath_raw = os.path.join(folder, f"probe.{number}.png")
    image.file_format = "PNG"
    image.save()


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 2:
        sys.exit("usage: blender -b --factory-startup -P blender_udim_probe.py -- FOLDER OUT.json")
    folder, out_path = arguments
    bpy.ops.wm.read_factory_settings(use_empty=True)
    write_tile(folder, 1001, (1.0, 0.0, 0.0, 1.0))
    write_tile(folder, 1011, (0.0, 0.0, 1.0, 1.0))
    udim = bpy.data.images.load(os.path.join(folder, "probe.1001.png"))
    udim.source = "TILED"
    udim.filepath = os.path.join(folder, "probe.<UDIM>.png")
    udim.reload()
    udim.colorspace_settings.name = "Non-Color"

    # Quads side by side in x (each 1.9 m wide), facing the camera at -Y.
    quads = {"left_of_1001": (-0.8, 0.2), "missing_1002": (1.2, 0.2), "tile_1011": (0.2, 1.2)}
    vertices, faces, uvs = [], [], []
    for k, (u0, v0) in enumerate(quads.values()):
        x0 = -3.0 + 2.0 * k
        vertices += [(x0, 0, -1), (x0 + 1.9, 0, -1), (x0 + 1.9, 0, 1), (x0, 0, 1)]
        uvs += [(u0, v0), (u0 + 0.6, v0), (u0 + 0.6, v0 + 0.6), (u0, v0 + 0.6)]
        faces.append(tuple(range(4 * k, 4 * k + 4)))
    mesh = bpy.data.meshes.new("quads")
    mesh.from_pydata(vertices, [], faces)
    layer = mesh.uv_layers.new(name="UVMap")
    for loop in mesh.loops:
        layer.data[loop.index].uv = uvs[loop.vertex_index]
    scene = bpy.context.scene
    scene.collection.objects.link(bpy.data.objects.new("quads", mesh))

    material = bpy.data.materials.new("emission")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    for node in list(nodes):
        if node.type != "OUTPUT_MATERIAL":
            nodes.remove(node)
    texture = nodes.new("ShaderNodeTexImage")
    texture.image = udim
    texture.interpolation = "Closest"
    emission = nodes.new("ShaderNodeEmission")
    links.new(texture.outputs["Color"], emission.inputs["Color"])
    links.new(emission.outputs[0], nodes["Material Output"].inputs[0])
    mesh.materials.append(material)

    camera = bpy.data.cameras.new("camera")
    camera.type = "ORTHO"
    camera.ortho_scale = 6.0
    camera_object = bpy.data.objects.new("camera", camera)
    camera_object.location = (0, -5, 0)
    camera_object.rotation_euler = (1.5707963, 0, 0)
    scene.collection.objects.link(camera_object)
    scene.camera = camera_object
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 4
    scene.cycles.use_denoising = False
    scene.view_settings.view_transform = "Standard"
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 12, 4, 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.filepath = os.path.join(folder, "probe.exr")
    bpy.ops.render.render(write_still=True)

    pixels = list(bpy.data.images.load(scene.render.filepath).pixels)
    result = {}
    for k, name in enumerate(quads):
        i = (2 * 12 + 4 * k + 1) * 4  # row 2, the second of each quad's four columns
        result[name] = {"rgb": pixels[i:i + 3], "uv": [quads[name][0] + 0.3, quads[name][1] + 0.3]}
    with open(out_path, "w") as f:
        json.dump(result, f)


main()
