"""Bakes the lightmap of a `radiosity bake` with Blender's Cycles, on the project's own lightmap UVs
and under the project's conventions, so that the two lightmaps can be compared texel by texel
(docs/peer.md, "Lightmaps"):

- the geometry and the lightmap UVs come from the bake's `scene_baked.glb` (TEXCOORD_1, one page:
  `radiosity bake --lightmap-size N`); its materials are rebuilt from the scene's OBJ + MTL as
  cycles_render.py builds them (Lambert of Kd, mirrors, glass, Ke as radiance, one-sided), so the
  glTF's emissive lightmap texture takes no part in the light;
- `--content radiance` bakes Cycles' Combined pass (emission, direct and indirect light of every
  kind): the outgoing radiance of a Lambertian surface, which is what the project's default
  lightmap holds; `--content irradiance` bakes the Diffuse pass without its colour (direct +
  indirect), the light arriving over pi, H/pi, as `--lightmap-content irradiance`;
- texels whose centre no triangle covers keep alpha 0 (no margin, no dilation), so a comparison
  takes the texels Cycles baked; Cycles box-filters each texel over its footprint (clamped to the
  triangle), where the project takes the texel's centre;
- written as a linear 32-bit float OpenEXR (RGBA) and as a NumPy array (H x W x 4, float32, row 0
  at the top as in the project's lightmap.exr), for bench/peer/race.py's texel errors.

    blender -b --factory-startup --python-exit-code 1 --python bench/peer/cycles_bake.py -- \\
        BAKE_DIR SCENE.obj --spp 64 --out LIGHTMAP.exr [--seed 1] [--threads 2]
        [--content radiance|irradiance] [--sky R G B] [--sun DX DY DZ R G B]
        [--two-sided | --two-sided-materials A,B] [--report REPORT.json]

BAKE_DIR is the output directory of a `radiosity bake` (its scene_baked.glb and bake.json).
"""
import argparse
import json
import os
import sys
import time

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles_render as conventions  # noqa: E402  (the scene conversion, one place)

fail = conventions.fail

# Blender 3.4's glTF importer still uses numpy.bool, which NumPy 1.24 removed (as in
# scripts/blender_import_check.py; fixed in Blender 3.5).
if "bool" not in np.__dict__:
    np.bool = bool


def lightmap_size(bake_dir):
    path = os.path.join(bake_dir, "bake.json")
    if not os.path.isfile(path):
        fail(f"{bake_dir}: no bake.json (not the output of `radiosity bake`?)")
    with open(path) as f:
        bake = json.load(f)
    lightmap = bake.get("lightmap", {})
    pages = lightmap.get("pages", 1)
    if pages != 1:
        fail(f"{path}: {pages} lightmap pages; bake one page (`radiosity bake --lightmap-size N`)")
    width, height = lightmap.get("width"), lightmap.get("height")
    if not width or not height:
        fail(f"{path}: /lightmap/width and /lightmap/height missing")
    return width, height


def import_baked(bake_dir, obj_path, two_sided_all, two_sided_names):
    """The bake's geometry with the scene's materials; returns the mesh objects."""
    glb = os.path.join(bake_dir, "scene_baked.glb")
    if not os.path.isfile(glb):
        fail(f"{bake_dir}: no scene_baked.glb")
    specs = conventions.material_specs(obj_path)
    result = bpy.ops.import_scene.gltf(filepath=glb)
    if "FINISHED" not in result:
        fail(f"Blender's glTF importer did not finish on {glb}: {result}")
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    if not meshes:
        fail(f"{glb}: no mesh imported")
    for obj in meshes:
        mesh = obj.data
        conventions.flat_shaded(mesh)
        if len(mesh.uv_layers) < 2:
            fail(f"{glb}: mesh '{mesh.name}' has no TEXCOORD_1 (lightmap UVs)")
        # Textures read the scene's UVs (TEXCOORD_0, the render layer); the bake writes through
        # the lightmap's (TEXCOORD_1, the active layer).
        mesh.uv_layers[0].active_render = True
        mesh.uv_layers.active_index = 1
    conventions.convert_materials(specs, two_sided_all, two_sided_names, glb)
    return meshes


def bake_target(width, height):
    """A float RGBA image, alpha 0 everywhere: the bake sets alpha 1 on the texels it writes."""
    image = bpy.data.images.new("lightmap", width, height, alpha=True, float_buffer=True)
    image.colorspace_settings.name = "Linear"
    image.generated_color = (0, 0, 0, 0)
    for material in bpy.data.materials:
        if not material.use_nodes:
            continue
        node = material.node_tree.nodes.new("ShaderNodeTexImage")
        node.image = image
        material.node_tree.nodes.active = node  # the bake writes into the active image node
    return image


def bake(meshes, content):
    settings = bpy.context.scene.render.bake
    settings.margin = 0
    settings.use_clear = False
    settings.target = "IMAGE_TEXTURES"
    settings.use_selected_to_active = False
    for obj in bpy.context.view_layer.objects:
        obj.select_set(obj in meshes)
    bpy.context.view_layer.objects.active = meshes[0]
    if content == "radiance":
        for flag in ("use_pass_direct", "use_pass_indirect", "use_pass_emit", "use_pass_diffuse",
                     "use_pass_glossy", "use_pass_transmission"):
            setattr(settings, flag, True)
        result = bpy.ops.object.bake(type="COMBINED", margin=0, use_clear=False)
    else:
        settings.use_pass_direct = settings.use_pass_indirect = True
        settings.use_pass_color = False
        result = bpy.ops.object.bake(type="DIFFUSE", pass_filter={"DIRECT", "INDIRECT"}, margin=0,
                                     use_clear=False)
    if "FINISHED" not in result:
        fail(f"Cycles' bake did not finish: {result}")


def write(image, out):
    width, height = image.size
    pixels = np.empty(width * height * 4, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    # Blender's rows run bottom-up; the project's lightmap.exr is top-down, as glTF's UVs are.
    array = pixels.reshape(height, width, 4)[::-1]
    np.save(os.path.splitext(out)[0] + ".npy", array)
    image.filepath_raw = os.path.abspath(out)
    image.file_format = "OPEN_EXR"
    image.save()
    return array


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    parser = argparse.ArgumentParser(prog="cycles_bake.py")
    parser.add_argument("bake_dir")
    parser.add_argument("scene")
    parser.add_argument("--spp", type=int, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--content", choices=("radiance", "irradiance"), default="radiance")
    parser.add_argument("--sky", type=float, nargs=3)
    parser.add_argument("--sun", type=float, nargs=6)
    parser.add_argument("--sun-angle", type=float, default=0.53)
    parser.add_argument("--two-sided", action="store_true")
    parser.add_argument("--two-sided-materials", default="")
    parser.add_argument("--report")
    args = parser.parse_args(argv)
    if not os.path.isfile(args.scene):
        fail(f"{args.scene}: no such file")
    if args.spp < 1:
        fail("--spp must be positive")

    start = time.perf_counter()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    width, height = lightmap_size(args.bake_dir)
    names = {n for n in args.two_sided_materials.split(",") if n}
    meshes = import_baked(args.bake_dir, args.scene, args.two_sided, names)
    conventions.add_world(args.sky)
    if args.sun:
        conventions.add_sun(args.sun, args.sun_angle)
    conventions.configure_cycles(args.spp, args.seed, args.threads, conventions.BOUNCES)
    image = bake_target(width, height)
    setup = time.perf_counter() - start
    start = time.perf_counter()
    bake(meshes, args.content)
    baked = time.perf_counter() - start
    array = write(image, args.out)
    covered = int((array[..., 3] > 0).sum())
    report = {"blender": bpy.app.version_string, "spp": args.spp, "seed": args.seed,
              "content": args.content, "width": width, "height": height,
              "texels_baked": covered, "setup_seconds": setup, "bake_seconds": baked}
    if args.report:
        with open(args.report, "w") as f:
            json.dump(report, f, indent=1)
    print("cycles_bake: " + json.dumps(report))


if __name__ == "__main__":
    main()
