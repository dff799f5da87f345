"""Renders one of the project's scenes (OBJ + MTL, camera JSON, sky and sun) with Blender's Cycles
under the project's conventions, so that a Cycles image and a `radiosity render` image of the same
scene show the same physics (docs/peer.md):

- every material is a Lambertian reflector of reflectance Kd (times its map_Kd, sRGB, bilinear)
  whatever its `illum` says, except mirrors (illum 3 or 5: a sharp reflector of colour Ks) and
  glass (illum 7: a sharp Fresnel dielectric of index Ni and colour Tf), as the project reads them
  (docs/physics.md); a material without Kd, or faces without a material, reflect 0.5 (the
  project's default material); Kd 0 with a map_Kd reads as Kd 1;
- Ke is emitted radiance (an Emission shader of strength 1);
- surfaces are one-sided: the back of a surface absorbs and emits nothing (a black closure where
  the Geometry node says Backfacing), unless `--two-sided` or `--two-sided-materials` names it;
  emitters stay one-sided under `--two-sided`, as in the project; glass is never one-sided;
- flat shading (the project ignores `vn`); the OBJ's y-up frame becomes Blender's z-up one as
  Blender's OBJ importer makes it ((x, y, z) -> (x, -z, y));
- `--sky R G B`: uniform radiance over the hemisphere above the horizon, black ground; `--sun DX DY
  DZ R G B`: a sun of irradiance R G B (W/m^2 facing it) travelling along DX DY DZ, angular
  diameter `--sun-angle` (0.53 degrees, the project's);
- a 1-pixel box filter, no denoising, no adaptive sampling, no clamping, no glossy blur, caustics
  on, 1024 bounces of every kind (the project's path tracer has no depth limit but Russian roulette;
  Cycles' own roulette runs past its min bounces), and the seed given (two renders with different
  seeds are independent);
- written as a linear 32-bit float OpenEXR (RGB), as `radiosity render` writes render.exr.

    blender -b --factory-startup --python-exit-code 1 --python bench/peer/cycles_render.py -- \\
        SCENE.obj --camera CAMERA.json --spp 64 --out IMAGE.exr [--seed 1] [--threads 2]
        [--sky R G B] [--sun DX DY DZ R G B] [--two-sided | --two-sided-materials A,B]
        [--report REPORT.json] [--max-bounces N]

The report holds Blender's version, the seconds spent loading and converting the scene and the
seconds inside Cycles' render (the driver, bench/peer/race.py, times the whole process too).
"""
import argparse
import json
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

DEFAULT_REFLECTANCE = (0.5, 0.5, 0.5)  # the project's material for faces without one
BOUNCES = 1024


def fail(message):
    print("cycles_render: error: " + message, file=sys.stderr)
    sys.exit(1)


def to_blender(p):
    """The project's y-up (x, y, z) as Blender's OBJ and glTF importers place it, z-up."""
    return Vector((p[0], -p[2], p[1]))


# Texture options of an MTL map statement and how many values each takes (the file name follows).
MAP_OPTION_VALUES = {"-bm": 1, "-boost": 1, "-mm": 2, "-texres": 1, "-blendu": 1, "-blendv": 1,
                     "-cc": 1, "-clamp": 1, "-imfchan": 1, "-type": 1, "-s": 3, "-o": 3, "-t": 3}


def map_file(tokens, mtl_dir):
    i = 0
    while i < len(tokens) and tokens[i] in MAP_OPTION_VALUES:
        i += 1 + MAP_OPTION_VALUES[tokens[i]]
    name = " ".join(tokens[i:]).replace("\\", "/")
    return os.path.join(mtl_dir, name)


def parse_mtl(path):
    """The MTL statements the project reads, per material name (a deliberately small reader: the
    project's own checks the files; this one only mirrors what it takes from them)."""
    materials, current = {}, None
    mtl_dir = os.path.dirname(path)
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            tokens = line.split("#", 1)[0].split()
            if not tokens:
                continue
            key, values = tokens[0], tokens[1:]
            if key == "newmtl":
                current = materials.setdefault(" ".join(values), {"illum": 0})
            elif current is None:
                continue
            elif key in ("Kd", "Ke", "Ks", "Tf"):
                numbers = [float(v) for v in values[:3]]
                current[key] = tuple(numbers * 3 if len(numbers) == 1 else numbers)
            elif key == "Ni":
                current["Ni"] = float(values[0])
            elif key == "illum":
                current["illum"] = int(values[0])
            elif key == "map_Kd":
                current["map_Kd"] = map_file(values, mtl_dir)
    return materials


def mtl_paths(obj_path):
    paths = []
    with open(obj_path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("mtllib"):
                paths.append(os.path.join(os.path.dirname(obj_path),
                                          line.split(None, 1)[1].strip().replace("\\", "/")))
    return paths


class Nodes:
    """A material's node tree, built from the output backwards."""

    def __init__(self, material):
        material.use_nodes = True
        self.tree = material.node_tree
        self.tree.nodes.clear()
        self.output = self.tree.nodes.new("ShaderNodeOutputMaterial")

    def new(self, kind, **inputs):
        node = self.tree.nodes.new(kind)
        for name, value in inputs.items():
            node.inputs[name].default_value = value
        return node

    def link(self, from_socket, to_socket):
        self.tree.links.new(from_socket, to_socket)


def rgba(c):
    return (c[0], c[1], c[2], 1.0)


def build_material(material, spec, two_sided):
    nodes = Nodes(material)
    illum = spec.get("illum", 0)
    if illum in (3, 5):
        surface = nodes.new("ShaderNodeBsdfGlossy", Color=rgba(spec.get("Ks", (1, 1, 1))))
        surface.distribution = "SHARP"
    elif illum == 7:
        surface = nodes.new("ShaderNodeBsdfGlass", Color=rgba(spec.get("Tf", (1, 1, 1))),
                            IOR=spec.get("Ni", 1.5))
        surface.distribution = "SHARP"
        nodes.link(surface.outputs[0], nodes.output.inputs["Surface"])
        return  # glass has no back: its inside is where refraction carries on
    else:
        kd = spec.get("Kd", DEFAULT_REFLECTANCE)
        texture = spec.get("map_Kd")
        if texture and max(kd) == 0:
            kd = (1.0, 1.0, 1.0)
        surface = nodes.new("ShaderNodeBsdfDiffuse", Color=rgba(kd), Roughness=0.0)
        if texture:
            image = nodes.new("ShaderNodeTexImage")
            if not os.path.isfile(texture):
                fail(f"material '{material.name}': texture {texture} not found")
            image.image = bpy.data.images.load(texture, check_existing=True)
            image.image.colorspace_settings.name = "sRGB"
            image.interpolation = "Linear"
            tint = nodes.new("ShaderNodeMixRGB", Fac=1.0, Color2=rgba(kd))
            tint.blend_type = "MULTIPLY"
            nodes.link(image.outputs["Color"], tint.inputs["Color1"])
            nodes.link(tint.outputs["Color"], surface.inputs["Color"])
    back = surface if two_sided else nodes.new("ShaderNodeBsdfDiffuse", Color=(0, 0, 0, 1))
    front = surface
    ke = spec.get("Ke", (0, 0, 0))
    if max(ke) > 0:
        emission = nodes.new("ShaderNodeEmission", Color=rgba(ke), Strength=1.0)
        front = nodes.new("ShaderNodeAddShader")
        nodes.link(surface.outputs[0], front.inputs[0])
        nodes.link(emission.outputs[0], front.inputs[1])
    facing = nodes.new("ShaderNodeNewGeometry")
    sided = nodes.new("ShaderNodeMixShader")
    nodes.link(facing.outputs["Backfacing"], sided.inputs["Fac"])
    nodes.link(front.outputs[0], sided.inputs[1])
    nodes.link(back.outputs[0], sided.inputs[2])
    nodes.link(sided.outputs[0], nodes.output.inputs["Surface"])


def material_specs(obj_path):
    """The materials of the OBJ's MTL files, by name."""
    specs = {}
    for path in mtl_paths(obj_path):
        if not os.path.isfile(path):
            fail(f"{obj_path}: mtllib {path} not found")
        specs.update(parse_mtl(path))
    return specs


def flat_shaded(mesh):
    """Face normals only, as the project shades (it ignores the file's normals)."""
    mesh.polygons.foreach_set("use_smooth", [False] * len(mesh.polygons))
    if mesh.has_custom_normals:
        mesh.free_normals_split()  # Blender 3.4


def convert_materials(specs, two_sided_all, two_sided_names, source):
    """Every material of the Blender file rebuilt from its MTL spec (`source` names the file for
    errors); "default" is the project's material for faces without one."""
    for material in bpy.data.materials:
        spec = specs.get(material.name)
        if spec is None and material.name != "default":
            fail(f"{source}: material '{material.name}' is not in the scene's MTL files")
        spec = spec or {}
        emitter = max(spec.get("Ke", (0, 0, 0))) > 0
        named = material.name in two_sided_names
        build_material(material, spec, named or (two_sided_all and not emitter))


def import_scene(obj_path, two_sided_all, two_sided_names):
    specs = material_specs(obj_path)
    result = bpy.ops.wm.obj_import(filepath=obj_path, forward_axis="NEGATIVE_Z", up_axis="Y")
    if "FINISHED" not in result:
        fail(f"Blender's OBJ importer did not finish on {obj_path}: {result}")
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    if not meshes:
        fail(f"{obj_path}: no mesh imported")
    default = None
    for obj in meshes:
        mesh = obj.data
        flat_shaded(mesh)
        if not mesh.materials:
            if default is None:
                default = bpy.data.materials.new("default")
            mesh.materials.append(default)
    triangles = 0
    for obj in meshes:
        obj.data.calc_loop_triangles()
        triangles += len(obj.data.loop_triangles)
    convert_materials(specs, two_sided_all, two_sided_names, obj_path)
    return len(meshes), triangles, len(bpy.data.materials)


def add_camera(camera_json, width, height):
    with open(camera_json) as f:
        cam = json.load(f)
    position, target = to_blender(cam["position"]), to_blender(cam["look_at"])
    up = to_blender(cam.get("up", [0, 1, 0]))
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(cam["vfov_degrees"])
    data.clip_start, data.clip_end = 1e-4, 1e6
    camera = bpy.data.objects.new("camera", data)
    bpy.context.scene.collection.objects.link(camera)
    camera.location = position
    # A camera looks along its local -Z with +Y up: its columns are right, up and -forward, with
    # right = forward x up as the project's camera (radiosity/render/camera.cpp) takes it.
    forward = (target - position).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    camera.rotation_euler = Matrix((right, true_up, -forward)).transposed().to_euler()
    scene = bpy.context.scene
    scene.camera = camera
    scene.render.resolution_x = width or cam.get("width", 256)
    scene.render.resolution_y = height or cam.get("height", 256)
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1


def add_world(sky):
    """Uniform radiance `sky` above the horizon (Blender's +Z, the project's +y), black below."""
    world = bpy.data.worlds.new("sky")
    bpy.context.scene.world = world
    world.use_nodes = True
    tree = world.node_tree
    tree.nodes.clear()
    output = tree.nodes.new("ShaderNodeOutputWorld")
    background = tree.nodes.new("ShaderNodeBackground")
    background.inputs["Color"].default_value = rgba(sky or (0, 0, 0))
    tree.links.new(background.outputs[0], output.inputs["Surface"])
    if not sky:
        background.inputs["Strength"].default_value = 0.0
        return
    # The world's Generated coordinate is the direction looked along; above the horizon: z > 0.
    coordinates = tree.nodes.new("ShaderNodeTexCoord")
    split = tree.nodes.new("ShaderNodeSeparateXYZ")
    above = tree.nodes.new("ShaderNodeMath")
    above.operation = "GREATER_THAN"
    above.inputs[1].default_value = 0.0
    tree.links.new(coordinates.outputs["Generated"], split.inputs[0])
    tree.links.new(split.outputs["Z"], above.inputs[0])
    tree.links.new(above.outputs[0], background.inputs["Strength"])


def add_sun(sun, angle_degrees):
    direction = to_blender(sun[:3]).normalized()
    irradiance = sun[3:]
    strength = max(irradiance)
    data = bpy.data.lights.new("sun", "SUN")
    data.energy = strength  # Cycles: a sun's strength is its irradiance in W/m^2
    data.color = tuple(c / strength for c in irradiance) if strength > 0 else (0, 0, 0)
    data.angle = math.radians(angle_degrees)
    sun_object = bpy.data.objects.new("sun", data)
    bpy.context.scene.collection.objects.link(sun_object)
    # A sun shines along its local -Z.
    sun_object.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()


def configure_cycles(spp, seed, threads, max_bounces):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = spp
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    cycles.seed = seed
    cycles.use_animated_seed = False
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    for bounces in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                    "transparent_max_bounces", "volume_bounces"):
        setattr(cycles, bounces, max_bounces)
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if threads > 0:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = threads
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGB"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_render.py")
    parser.add_argument("scene")
    parser.add_argument("--camera", required=True)
    parser.add_argument("--spp", type=int, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--width", type=int, default=0)
    parser.add_argument("--height", type=int, default=0)
    parser.add_argument("--sky", type=float, nargs=3)
    parser.add_argument("--sun", type=float, nargs=6)
    parser.add_argument("--sun-angle", type=float, default=0.53)
    parser.add_argument("--two-sided", action="store_true")
    parser.add_argument("--two-sided-materials", default="")
    parser.add_argument("--report")
    # Fewer bounces for checks of one term at a time: 0 is the light seen and direct light (the
    # project's bounce_sum_1 of --bounces-separate), 1 adds one diffuse bounce (bounce_sum_2).
    parser.add_argument("--max-bounces", type=int, default=BOUNCES)
    args = parser.parse_args(argv)
    if not os.path.isfile(args.scene):
        fail(f"{args.scene}: no such file")
    if args.spp < 1:
        fail("--spp must be positive")
    if args.max_bounces < 0:
        fail("--max-bounces must be at least 0")

    start = time.perf_counter()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    names = {n for n in args.two_sided_materials.split(",") if n}
    objects, triangles, materials = import_scene(args.scene, args.two_sided, names)
    add_camera(args.camera, args.width, args.height)
    add_world(args.sky)
    if args.sun:
        add_sun(args.sun, args.sun_angle)
    configure_cycles(args.spp, args.seed, args.threads, args.max_bounces)
    scene = bpy.context.scene
    scene.render.filepath = os.path.abspath(args.out)
    scene.render.use_file_extension = False
    setup = time.perf_counter() - start
    start = time.perf_counter()
    bpy.ops.render.render(write_still=True)
    rendered = time.perf_counter() - start
    if not os.path.isfile(args.out):
        fail(f"Cycles wrote no image to {args.out}")
    report = {"blender": bpy.app.version_string, "spp": args.spp, "seed": args.seed,
              "width": scene.render.resolution_x, "height": scene.render.resolution_y,
              "objects": objects, "triangles": triangles, "materials": materials,
              "setup_seconds": setup, "render_seconds": rendered}
    if args.report:
        with open(args.report, "w") as f:
            json.dump(report, f, indent=1)
    print("cycles_render: " + json.dumps(report))


if __name__ == "__main__":  # cycles_bake.py imports the conversion
    main()
