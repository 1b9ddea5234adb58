# Build the exporter's test scene in Blender and save it, with the same triangles as an OBJ.
#
#   blender -b --factory-startup -P tools/blender/tests/make_scene.py -- BLEND OBJ
#
# A 6 m floor, a 1 m box and a 0.5 m sphere resting on it 0.15 m apart, and two cameras:
#   persp: 30 mm lens, VERTICAL sensor fit on a landscape image (20 mm sensor height), shift
#          (0.1, -0.05), render size 640x480 at 50 %;
#   ortho: orthographic, ortho_scale 5 with HORIZONTAL fit, shift (-0.05, 0.1).
# The OBJ holds the evaluated meshes' loop triangles in Blender's world coordinates (Z up), the
# triangles `scene.ray_cast` intersects.

import math
import sys

import bpy
from mathutils import Vector

blend, obj_path = sys.argv[sys.argv.index("--") + 1 :][:2]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.resolution_x = 640
scene.render.resolution_y = 480
scene.render.resolution_percentage = 50

bpy.ops.mesh.primitive_plane_add(size=6.0, location=(0.0, 0.0, 0.0))
bpy.context.object.name = "floor"
bpy.ops.mesh.primitive_cube_add(size=1.0, location=(-0.4, 0.0, 0.5), rotation=(0.0, 0.0, math.radians(20)))
bpy.context.object.name = "box"
bpy.ops.mesh.primitive_uv_sphere_add(radius=0.5, segments=48, ring_count=24, location=(0.55, -0.45, 0.5))
bpy.context.object.name = "sphere"


def add_camera(name, location, target):
    data = bpy.data.cameras.new(name)
    cam = bpy.data.objects.new(name, data)
    scene.collection.objects.link(cam)
    cam.location = location
    direction = Vector(target) - Vector(location)
    cam.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
    return cam


persp = add_camera("persp", (3.2, -3.6, 2.4), (0.0, 0.0, 0.3))
persp.data.lens = 30.0
persp.data.sensor_fit = "VERTICAL"
persp.data.sensor_height = 20.0
persp.data.shift_x = 0.1
persp.data.shift_y = -0.05
persp.data.clip_start = 0.1
persp.data.clip_end = 100.0

ortho = add_camera("ortho", (-3.0, -4.0, 3.5), (0.0, 0.0, 0.3))
ortho.data.type = "ORTHO"
ortho.data.ortho_scale = 5.0
ortho.data.sensor_fit = "HORIZONTAL"
ortho.data.shift_x = -0.05
ortho.data.shift_y = 0.1
ortho.data.clip_start = 0.5
ortho.data.clip_end = 30.0

scene.camera = persp
bpy.ops.wm.save_as_mainfile(filepath=blend)

depsgraph = bpy.context.evaluated_depsgraph_get()
lines, base = [], 1
for ob in scene.objects:
    if ob.type != "MESH":
        continue
    ev = ob.evaluated_get(depsgraph)
    mesh = ev.to_mesh()
    mesh.calc_loop_triangles()
    m = ev.matrix_world
    lines.append("o %s" % ob.name)
    for v in mesh.vertices:
        p = m @ v.co
        lines.append("v %r %r %r" % (p.x, p.y, p.z))
    for t in mesh.loop_triangles:
        a, b, c = (i + base for i in t.vertices)
        lines.append("f %d %d %d" % (a, b, c))
    base += len(mesh.vertices)
    ev.to_mesh_clear()
with open(obj_path, "w") as f:
    f.write("\n".join(lines) + "\n")
print("test scene: %s, %s" % (blend, obj_path))
