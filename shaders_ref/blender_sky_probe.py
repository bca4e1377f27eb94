# Evaluates Blender 3.4's Sky Texture (Nishita) as Cycles shows it as a World: an equirectangular
# panoramic camera at the origin sees the world along each pixel's direction, one sample per
# pixel at its centre (a 0.01-pixel filter). Renders twice with the same samples: once a world
# whose colour is the ray direction d as (d + 1) / 2, once the sky. Writes DIRECTIONS.exr and
# SKY.exr (linear RGB), so that a caller evaluates its own sky along exactly Cycles' directions.
#
#   blender -b --factory-startup -noaudio --python-exit-code 1 -P blender_sky_probe.py -- SKY.json DIRECTIONS.exr SKY.exr
# SKY.json: {"width", "sun_elevation", "sun_rotation", "sun_size", "sun_intensity", "sun_disc",
#            "altitude", "air_density", "dust_density", "ozone_density"} (radians, metres).
import json
import math
import sys

import bpy

SKY_KEYS = ("sun_elevation", "sun_rotation", "sun_size", "sun_intensity", "sun_disc", "altitude", "air_density",
            "dust_density", "ozone_density")


def world_of_directions():
    """Background colour (d + 1) / 2 for the ray direction d (a world's Generated coordinates)."""
    world = bpy.data.worlds.new("directions")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    coordinates = nodes.new("ShaderNodeTexCoord")
    half = nodes.new("ShaderNodeVectorMath")
    half.operation = "MULTIPLY_ADD"
    half.inputs[1].default_value = (0.5, 0.5, 0.5)
    half.inputs[2].default_value = (0.5, 0.5, 0.5)
    links.new(coordinates.outputs["Generated"], half.inputs[0])
    links.new(half.outputs[0], nodes["Background"].inputs["Color"])
    return world


def world_of_sky(sky):
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    texture = nodes.new("ShaderNodeTexSky")
    texture.sky_type = "NISHITA"
    for key in SKY_KEYS:
        setattr(texture, key, sky[key])
    links.new(texture.outputs["Color"], nodes["Background"].inputs["Color"])
    return world


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 3:
        sys.exit("usage: blender -b --factory-startup -P blender_sky_probe.py -- SKY.json DIRECTIONS.exr SKY.exr")
    with open(arguments[0]) as file:
        sky = json.load(file)
    width = int(sky["width"])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    camera_data = bpy.data.cameras.new("camera")
    camera_data.type = "PANO"
    camera_data.cycles.panorama_type = "EQUIRECTANGULAR"
    camera = bpy.data.objects.new("camera", camera_data)
    camera.rotation_euler = (math.pi / 2.0, 0.0, -math.pi / 2.0)  # looking along +X, +Z up
    scene.collection.objects.link(camera)
    scene.camera = camera

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.filter_width = 0.01
    scene.cycles.max_bounces = 0
    scene.render.resolution_x, scene.render.resolution_y = width, width // 2
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGB"
    for world, path in ((world_of_directions(), arguments[1]), (world_of_sky(sky), arguments[2])):
        scene.world = world
        scene.render.filepath = path
        bpy.ops.render.render(write_still=True)


main()
