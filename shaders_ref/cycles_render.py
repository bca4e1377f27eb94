# Renders a scene described by shaders_ref's cycles_reference.cpp with Blender 3.4 Cycles into
# linear EXRs, once per requested (samples, seed), and records how long each render call took.
# Blender is only a reference for the optional tests and the bench, never a product dependency.
#
#   blender -b --factory-startup -noaudio --python-exit-code 1 -P cycles_render.py -- SCENE.json
#
# SCENE.json holds the mesh (with UVs when a base colour image is given) and material, or in
# their place "gltf", a file Blender's glTF importer brings in with its own node setups, or in
# place of the mesh "mesh_file", an OBJ or PLY file Blender's importer reads, in the material; the
# lamps, camera, background, bounces and "settings", plus "threads", "renders" ([{"spp", "seed",
# "noise_threshold", "path"}], rendered in order) and "timings_path", where {"<path>": seconds}
# is written. Settings "parity" switch off what would make Cycles' converged image differ from
# the unbiased integral libmatrender computes (clamping, glossy blur); "blender_defaults" keep
# Cycles' defaults, as a Blender user has them. Either way there is no denoising (Debian's build
# has no denoiser), and adaptive sampling is on only for a render given a noise threshold; the
# shadow terminator geometry offset of the mesh comes from the description.
import json
import math
import os
import sys
import time

import bpy
import mathutils
from mathutils import Matrix

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # blender_gltf.py lies beside this script
from blender_gltf import import_gltf  # noqa: E402


def matrix_from_columns(values):
    """A 4x4 matrix from 16 numbers in column-major order (glm's layout)."""
    return Matrix([[values[4 * column + row] for column in range(4)] for row in range(4)])


def add_mesh(scene, description, material):
    mesh = bpy.data.meshes.new("object")
    mesh.from_pydata([tuple(p) for p in description["positions"]], [],
                     [tuple(t) for t in description["triangles"]])
    mesh.update()
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    mesh.use_auto_smooth = True  # custom split normals need it in 3.4
    mesh.auto_smooth_angle = math.pi  # and no edge may be split by angle
    mesh.normals_split_custom_set_from_vertices([tuple(n) for n in description["normals"]])
    if description.get("uvs"):
        layer = mesh.uv_layers.new(name="UVMap")
        for loop in mesh.loops:
            layer.data[loop.index].uv = description["uvs"][loop.vertex_index]
    mesh.materials.append(material)
    obj = bpy.data.objects.new("object", mesh)
    obj.cycles.shadow_terminator_geometry_offset = description["shadow_terminator_geometry_offset"]
    scene.collection.objects.link(obj)


def import_mesh_file(scene, description, material):
    """An OBJ or PLY file through Blender's own importer with its defaults, as a user imports it,
    every slot of every object it makes given `material`."""
    path = description["path"]
    if path.lower().endswith(".obj"):
        bpy.ops.wm.obj_import(filepath=path)
    elif path.lower().endswith(".ply"):
        bpy.ops.import_mesh.ply(filepath=path)
    else:
        sys.exit("cycles_render.py: mesh_file must be .obj or .ply: " + path)
    for obj in scene.objects:
        if obj.type != "MESH":
            continue
        obj.data.materials.clear()
        obj.data.materials.append(material)
        obj.data.polygons.foreach_set("material_index", [0] * len(obj.data.polygons))
        obj.cycles.shadow_terminator_geometry_offset = description["shadow_terminator_geometry_offset"]


def make_material(description, distribution, base_color_image):
    """description: node name -> {input name -> value}, one input per row of the material table."""
    material = bpy.data.materials.new("material")
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    bsdf = nodes["Principled BSDF"]
    bsdf.distribution = distribution  # "GGX" (single scatter) or "MULTI_GGX", as ours
    set_inputs(bsdf, description["Principled BSDF"])
    velvet_inputs = description["Velvet BSDF"]
    if any(velvet_inputs["Color"]):
        # What Blender's glTF importer builds for KHR_materials_sheen: Velvet + Principled.
        velvet = nodes.new("ShaderNodeBsdfVelvet")
        set_inputs(velvet, velvet_inputs)
        add = nodes.new("ShaderNodeAddShader")
        links.new(velvet.outputs["BSDF"], add.inputs[0])
        links.new(bsdf.outputs["BSDF"], add.inputs[1])
        links.new(add.outputs["Shader"], nodes["Material Output"].inputs["Surface"])
    if base_color_image:
        # An sRGB image on the active UV map, bilinear and repeating, as ours.
        texture = nodes.new("ShaderNodeTexImage")
        texture.image = bpy.data.images.load(base_color_image)
        texture.interpolation = "Linear"
        texture.extension = "REPEAT"
        links.new(texture.outputs["Color"], bsdf.inputs["Base Color"])
    return material


def set_inputs(node, inputs):
    for name, value in inputs.items():
        node.inputs[name].default_value = (*value, 1.0) if isinstance(value, list) else value


def aimed_along(position, direction):
    """The world matrix of a lamp at `position` whose -Z (where Blender lamps shine) is `direction`."""
    rotation = mathutils.Vector(direction).to_track_quat("-Z", "Y").to_matrix().to_4x4()
    return Matrix.Translation(position) @ rotation


def add_lamps(scene, lamps):
    for k, lamp in enumerate(lamps):
        kind = lamp["type"]
        light = bpy.data.lights.new(f"lamp_{k}", {"area": "AREA", "point": "POINT", "spot": "SPOT", "sun": "SUN"}[kind])
        light.color = lamp["color"]
        if "blackbody_kelvin" in lamp:
            # The lamp's emission coloured by Blender's own Blackbody node.
            light.use_nodes = True
            tree = light.node_tree
            blackbody = tree.nodes.new("ShaderNodeBlackbody")
            blackbody.inputs["Temperature"].default_value = lamp["blackbody_kelvin"]
            tree.links.new(blackbody.outputs["Color"], tree.nodes["Emission"].inputs["Color"])
        if kind == "area":
            light.shape = "RECTANGLE"
            light.size = lamp["size_x"]
            light.size_y = lamp["size_y"]
            light.energy = lamp["power"]
            matrix = matrix_from_columns(lamp["light_to_world"])
        elif kind == "sun":
            light.energy = lamp["strength"]
            light.angle = lamp["angle"]
            matrix = aimed_along((0.0, 0.0, 0.0), lamp["direction"])
        else:
            light.energy = lamp["power"]
            light.shadow_soft_size = lamp["radius"]
            if kind == "spot":
                light.spot_size = lamp["spot_angle"]
                light.spot_blend = lamp["blend"]
                matrix = aimed_along(lamp["position"], lamp["direction"])
            else:
                matrix = Matrix.Translation(lamp["position"])
        obj = bpy.data.objects.new(f"lamp_{k}", light)
        obj.matrix_world = matrix
        scene.collection.objects.link(obj)


def add_camera(scene, camera):
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = camera["vertical_fov"]
    obj = bpy.data.objects.new("camera", data)
    obj.matrix_world = matrix_from_columns(camera["camera_to_world"])
    scene.collection.objects.link(obj)
    scene.camera = obj
    scene.render.resolution_x = camera["width"]
    scene.render.resolution_y = camera["height"]
    scene.render.resolution_percentage = 100


def set_world(scene, background, environment, sky):
    """A uniform colour, an equirectangular EXR looked up along a Mapping node's Z rotation of
    the ray direction (Generated coordinates of a world are its direction), or a Sky Texture."""
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    node = nodes["Background"]
    node.inputs["Color"].default_value = (*background, 1.0)
    node.inputs["Strength"].default_value = 1.0
    if environment:
        texture = nodes.new("ShaderNodeTexEnvironment")
        texture.image = bpy.data.images.load(environment["path"])
        texture.interpolation = "Linear"
        texture.projection = "EQUIRECTANGULAR"
        mapping = nodes.new("ShaderNodeMapping")
        mapping.vector_type = "VECTOR"
        mapping.inputs["Rotation"].default_value = (0.0, 0.0, environment["rotation_z"])
        coordinates = nodes.new("ShaderNodeTexCoord")
        links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
        links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
        links.new(texture.outputs["Color"], node.inputs["Color"])
        node.inputs["Strength"].default_value = environment["strength"]
    if sky:
        texture = nodes.new("ShaderNodeTexSky")
        texture.sky_type = "NISHITA"
        for key in ("sun_elevation", "sun_rotation", "sun_size", "sun_intensity", "sun_disc", "altitude",
                    "air_density", "dust_density", "ozone_density"):
            setattr(texture, key, sky[key])
        links.new(texture.outputs["Color"], node.inputs["Color"])
        node.inputs["Strength"].default_value = sky["strength"]
    scene.world = world


def set_cycles(scene, threads, settings, bounces):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.use_denoising = False
    if settings == "parity":
        cycles.sample_clamp_direct = 0.0
        cycles.sample_clamp_indirect = 0.0
        cycles.blur_glossy = 0.0
    cycles.max_bounces = bounces["total"]
    cycles.diffuse_bounces = bounces["diffuse"]
    cycles.glossy_bounces = bounces["glossy"]
    cycles.transmission_bounces = bounces["transmission"]
    cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    cycles.filter_width = 1.5
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.film_transparent = False
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_depth = "32"
    settings.color_mode = "RGB"
    settings.exr_codec = "ZIP"


def main():
    arguments = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(arguments) != 1:
        sys.exit("usage: blender -b --factory-startup -P cycles_render.py -- SCENE.json")
    with open(arguments[0]) as f:
        description = json.load(f)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    if "gltf" in description:
        import_gltf(description["gltf"])
    elif "mesh_file" in description:
        material = make_material(description["material"], description["distribution"], None)
        import_mesh_file(scene, description["mesh_file"], material)
    else:
        material = make_material(description["material"], description["distribution"],
                                 description.get("base_color_image"))
        add_mesh(scene, description["mesh"], material)
    add_lamps(scene, description["lamps"])
    add_camera(scene, description["camera"])
    set_world(scene, description["background"], description.get("environment"), description.get("sky"))
    set_cycles(scene, description["threads"], description["settings"], description["bounces"])

    timings = {}
    for render in description["renders"]:
        # Samples is Max Samples under adaptive sampling; Min Samples 0 is Cycles' automatic.
        threshold = render["noise_threshold"]
        scene.cycles.use_adaptive_sampling = threshold is not None
        if threshold is not None:
            scene.cycles.adaptive_threshold = threshold
            scene.cycles.adaptive_min_samples = 0
        scene.cycles.samples = render["spp"]
        scene.cycles.seed = render["seed"]
        scene.render.filepath = render["path"]
        start = time.perf_counter()
        bpy.ops.render.render(write_still=True)
        timings[render["path"]] = time.perf_counter() - start
    with open(description["timings_path"], "w") as f:
        json.dump(timings, f)


main()
