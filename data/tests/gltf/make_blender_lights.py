# Makes blender_lights.glb: a floor, a point light of 100 W, a spot of 50 W (60° cone, blend 0.2)
# and a sun of 3 W/m², exported by Blender's own glTF exporter (its default "Standard" lighting
# units). Run from this folder with Debian's Blender 3.4:
#   blender -b --factory-startup --python make_blender_lights.py
# tests/scene/test_gltf_loader.cpp reads the file and checks the converted intensities.
import math
import bpy

bpy.ops.object.select_all(action='SELECT')
bpy.ops.object.delete()

bpy.ops.mesh.primitive_plane_add(size=4, location=(0, 0, 0))

def add_light(name, kind, energy, location, rotation=(0, 0, 0)):
    data = bpy.data.lights.new(name, kind)
    data.energy = energy
    data.color = (1, 1, 1)
    obj = bpy.data.objects.new(name, data)
    obj.location = location
    obj.rotation_euler = rotation
    bpy.context.scene.collection.objects.link(obj)
    return data

add_light("Point", 'POINT', 100.0, (1, 2, 3))
spot = add_light("Spot", 'SPOT', 50.0, (0, 0, 2))  # points down its -z: straight down
spot.spot_size = math.radians(60)
spot.spot_blend = 0.2
add_light("Sun", 'SUN', 3.0, (0, 0, 5), (math.radians(30), 0, 0))

bpy.ops.export_scene.gltf(filepath="blender_lights.glb", export_format='GLB',
                          export_lights=True, export_cameras=False)
