"""Imports a baked scene (scene_baked.glb from `radiosity bake`) into Blender, headless, and checks
that Blender sees what the bake meant it to: every material shows an embedded lightmap page as its
emission through the UV map that holds TEXCOORD_1, a base-colour texture (the scene's, when it has
one) through the UV map that holds TEXCOORD_0, and COLOR_0, where the bake writes it (vertex
colours only), is a colour attribute. Optionally renders the imported scene (Cycles, CPU) from a camera JSON such as
data/cornell_box/cornell_box.camera.json: the picture comes from the lightmap alone.

    blender -b --factory-startup --python-exit-code 1 --python scripts/blender_import_check.py \\
        -- out/bake/scene_baked.glb [--render picture.png --camera camera.json [--size 320]]

Exit status 0 when every check passes, 1 otherwise (with the failed check on stderr).
"""
import argparse
import json
import math
import os
import sys

import bpy
import numpy
from mathutils import Matrix, Vector

# Blender 3.4's glTF importer (Debian 12's blender package) still uses numpy.bool, which NumPy
# 1.24 (Debian 12's python3-numpy) removed: importing any mesh fails with AttributeError.
# Fixed in Blender 3.5 (KhronosGroup/glTF-Blender-IO#1844, #1831); restore the alias meanwhile.
if "bool" not in numpy.__dict__:
    numpy.bool = bool

# Blender's glTF importer names UV maps by set: TEXCOORD_0 -> "UVMap", TEXCOORD_1 -> "UVMap.001".
TEXTURE_UV_MAP = "UVMap"
LIGHTMAP_UV_MAP = "UVMap.001"


def fail(message):
    print("blender_import_check: FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def upstream_nodes(node, seen=None):
    """Every node whose output reaches `node` through links."""
    seen = set() if seen is None else seen
    for socket in node.inputs:
        for link in socket.links:
            if link.from_node.name not in seen:
                seen.add(link.from_node.name)
                yield link.from_node
                yield from upstream_nodes(link.from_node, seen)


def check_mesh(obj):
    mesh = obj.data
    # With a lightmap the bake keeps the scene's base colour and writes no COLOR_0 (glTF multiplies
    # the base colour by it); when there is one it must have come through.
    colours = [a for a in mesh.color_attributes if a.data_type in ("FLOAT_COLOR", "BYTE_COLOR")]
    described = "no colour attribute"
    if colours:
        values = [c.color[k] for c in colours[0].data for k in range(3)]
        if not values or max(values) <= 0:
            fail(f"mesh '{obj.name}': the colour attribute '{colours[0].name}' is all black")
        described = (f"colour attribute '{colours[0].name}' ({colours[0].domain}, "
                     f"max {max(values):.3f})")
    uv_maps = [uv.name for uv in mesh.uv_layers]
    for name, role in ((TEXTURE_UV_MAP, "TEXCOORD_0"), (LIGHTMAP_UV_MAP, "TEXCOORD_1")):
        if name not in uv_maps:
            fail(f"mesh '{obj.name}' has UV maps {uv_maps}, not {name} ({role})")
    print(f"mesh '{obj.name}': {len(mesh.polygons)} triangles, {described}, UV maps {uv_maps}")


def check_material(material):
    if not material.use_nodes:
        fail(f"material '{material.name}' has no node tree")
    nodes = material.node_tree.nodes
    bsdf = next((n for n in nodes if n.type == "BSDF_PRINCIPLED"), None)
    output = next((n for n in nodes if n.type == "OUTPUT_MATERIAL"), None)
    if bsdf is None or output is None or bsdf not in list(upstream_nodes(output)):
        fail(f"material '{material.name}': no Principled BSDF feeding the material output")
    emission = bsdf.inputs["Emission"]
    images = [n for n in upstream_nodes(bsdf) if n.type == "TEX_IMAGE"]
    lit = [n for n in images if n in {l.from_node for l in emission.links} or
           any(n in list(upstream_nodes(l.from_node)) for l in emission.links)]
    if not lit:
        fail(f"material '{material.name}': no image texture feeds the Emission input")
    image_node = lit[0]
    if image_node.image is None or image_node.image.size[0] == 0:
        fail(f"material '{material.name}': the emission texture has no image")
    uv_nodes = [n for n in upstream_nodes(image_node) if n.type == "UVMAP"]
    if not uv_nodes or uv_nodes[0].uv_map != LIGHTMAP_UV_MAP:
        found = uv_nodes[0].uv_map if uv_nodes else "the default (first) UV map"
        fail(f"material '{material.name}': the lightmap is looked up in {found}, "
             f"not {LIGHTMAP_UV_MAP} (TEXCOORD_1)")
    strength = bsdf.inputs["Emission Strength"].default_value
    if strength <= 0:
        fail(f"material '{material.name}': emission strength {strength}")
    base_input = bsdf.inputs["Base Color"]
    base = str(tuple(round(c, 3) for c in base_input.default_value[:3]))
    base_images = [n for l in base_input.links for n in [l.from_node, *upstream_nodes(l.from_node)]
                   if n.type == "TEX_IMAGE"]
    if base_images:
        # The base-colour texture reads TEXCOORD_0: the default (first) UV map or a UV Map node.
        uv_nodes = [n for n in upstream_nodes(base_images[0]) if n.type == "UVMAP"]
        if uv_nodes and uv_nodes[0].uv_map != TEXTURE_UV_MAP:
            fail(f"material '{material.name}': the base colour texture is looked up in "
                 f"{uv_nodes[0].uv_map}, not {TEXTURE_UV_MAP} (TEXCOORD_0)")
        if base_images[0].image is None or base_images[0].image.size[0] == 0:
            fail(f"material '{material.name}': the base colour texture has no image")
        base = f"image '{base_images[0].image.name}' on {TEXTURE_UV_MAP}"
    print(f"material '{material.name}': emission = image '{image_node.image.name}' "
          f"{tuple(image_node.image.size)} on {LIGHTMAP_UV_MAP}, strength {strength}, "
          f"base colour {base}")
    return image_node.image


def render(path, camera_json, size):
    with open(camera_json) as f:
        cam = json.load(f)
    # glTF (and the scene) are y-up; the importer turns (x, y, z) into Blender's (x, -z, y).
    to_blender = lambda p: Vector((p[0], -p[2], p[1]))
    position, target = to_blender(cam["position"]), to_blender(cam["look_at"])
    up = to_blender(cam.get("up", [0, 1, 0]))
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(cam["vfov_degrees"])
    camera = bpy.data.objects.new("camera", data)
    bpy.context.scene.collection.objects.link(camera)
    camera.location = position
    # A camera looks along its local -Z with +Y up: its columns are right, up and -forward.
    forward = (target - position).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    camera.rotation_euler = Matrix((right, true_up, -forward)).transposed().to_euler()
    # The lightmap already holds the light the base colour reflects: a black base keeps Cycles
    # from reflecting the emitted lightmap once more.
    for material in bpy.data.materials:
        if material.use_nodes:
            for bsdf in (n for n in material.node_tree.nodes if n.type == "BSDF_PRINCIPLED"):
                for link in list(bsdf.inputs["Base Color"].links):
                    material.node_tree.links.remove(link)
                bsdf.inputs["Base Color"].default_value = (0, 0, 0, 1)
    scene = bpy.context.scene
    scene.camera = camera
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 16
    scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
    scene.render.resolution_x = scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    # Standard view transform: the lightmap's sRGB colours come out as they are in the PNG.
    scene.view_settings.view_transform = "Standard"
    scene.world = bpy.data.worlds.new("black")
    scene.world.color = (0, 0, 0)
    scene.render.filepath = path
    scene.render.image_settings.file_format = "PNG"
    bpy.ops.render.render(write_still=True)
    print(f"rendered {path} ({size}x{size}, Cycles, lightmap emission only)")


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="blender_import_check.py")
    parser.add_argument("glb")
    parser.add_argument("--render", help="also render the imported scene to this PNG")
    parser.add_argument("--camera", help="camera JSON for --render")
    parser.add_argument("--size", type=int, default=320)
    args = parser.parse_args(argv)
    if args.render and not args.camera:
        fail("--render needs --camera")

    if not os.path.isfile(args.glb):
        fail(f"{args.glb}: no such file")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.import_scene.gltf(filepath=args.glb)
    if "FINISHED" not in result:
        fail(f"the glTF importer did not finish: {result}")
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    if not meshes:
        fail("no mesh imported")
    print(f"Blender {bpy.app.version_string} imported {args.glb}: {len(meshes)} mesh object(s)")
    images = set()
    for obj in meshes:
        check_mesh(obj)
        for slot in obj.material_slots:
            if slot.material is None:
                fail(f"mesh '{obj.name}' has an empty material slot")
            images.add(check_material(slot.material).name)
    print(f"lightmap pages: {sorted(images)}")
    print("blender_import_check: OK (base colour on TEXCOORD_0 and lightmap on TEXCOORD_1 attached)")
    if args.render:
        render(args.render, args.camera, args.size)


main()
