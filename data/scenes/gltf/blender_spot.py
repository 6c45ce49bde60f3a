"""Builds data/scenes/gltf/blender_spot.gltf (+ .bin) with Blender's own
glTF exporter: a spot scene as Blender users export it (issue 24).

Run in background mode (Debian's blender 3.4.1; not needed by the build or
CI, which use the committed files):

    blender --background --factory-startup --python data/scenes/gltf/blender_spot.py

The scene: a 12 m floor, a cube and a UV sphere on it, a spot lamp above
them rotated to shine down and sideways (Blender's spot points down its
local -Z; the exporter writes the node's rotation, outerConeAngle =
spot_size / 2 and innerConeAngle = outer - outer * spot_blend), whose cone
edge crosses the floor and the cube, a point lamp, and a camera.
Blender writes intensities in its photometric units (W become candela);
umbra reads them as unitless, so the lamps' powers are chosen small.
"""
import math
import os

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

bpy.ops.mesh.primitive_plane_add(size=12, location=(0, 0, 0))
bpy.context.object.name = "floor"
bpy.ops.mesh.primitive_cube_add(size=1.5, location=(0.5, -0.5, 0.75), rotation=(0, 0, math.radians(25)))
bpy.context.object.name = "cube"
bpy.ops.mesh.primitive_uv_sphere_add(radius=0.8, segments=16, ring_count=8, location=(-1.8, 1.0, 0.8))
bpy.context.object.name = "sphere"

spot_data = bpy.data.lights.new("spot", type="SPOT")
spot_data.energy = 0.02  # W: a few candela after the exporter's conversion
spot_data.spot_size = math.radians(50)  # full angle: outerConeAngle 25°
spot_data.spot_blend = 0.3
spot = bpy.data.objects.new("spot", spot_data)
spot.location = (3.0, -2.0, 5.0)
spot.rotation_euler = (math.radians(30), math.radians(20), math.radians(10))
scene.collection.objects.link(spot)

lamp_data = bpy.data.lights.new("lamp", type="POINT")
lamp_data.energy = 0.01
lamp = bpy.data.objects.new("lamp", lamp_data)
lamp.location = (-3.0, -3.0, 4.0)
scene.collection.objects.link(lamp)

camera_data = bpy.data.cameras.new("camera")
camera_data.lens = 30
camera = bpy.data.objects.new("camera", camera_data)
camera.location = (0.0, -10.0, 6.0)
camera.rotation_euler = (math.radians(62), 0, 0)
scene.collection.objects.link(camera)
scene.camera = camera
scene.render.resolution_x = 320
scene.render.resolution_y = 240

bpy.ops.export_scene.gltf(
    filepath=os.path.join(HERE, "blender_spot.gltf"),
    export_format="GLTF_SEPARATE",
    export_lights=True,
    export_cameras=True,
    export_apply=True,
)
