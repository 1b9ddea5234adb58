# Export the passes `aokit ao` reads from a Blender scene's active camera.
#
#   blender -b scene.blend -P tools/blender/export_aokit.py -- --out DIR [--scale S]
#
# writes DIR/depth.exr (channel Z: linear view depth, 0 where nothing is hit), DIR/normal.exr
# (channels R, G, B: view-space unit normals, x right, y up, camera looking down -Z; 0 where
# nothing is hit) and DIR/camera.json (docs/camera-json.md), at the scene's render resolution
# times its percentage (times S). Every pixel centre is ray-cast with `scene.ray_cast`, so no
# render engine and no GPU are needed. From Blender's UI, open this file in the Text Editor, set
# UI_OUT below (or leave it to write `aokit-export/` beside the saved .blend) and press Run Script.
# See docs/blender.md. Needs only Blender's bundled Python (no numpy).

import json
import math
import os
import struct
import sys
import time

import bpy
from mathutils import Matrix, Vector

# Output folder when run from Blender's UI (no `-- --out DIR`); "//" is the .blend's folder.
UI_OUT = "//aokit-export"
UI_SCALE = 1.0


# Object types with surfaces that `scene.ray_cast` (Blender 3.4) does not intersect.
UNSEEN_TYPES = {"CURVE", "SURFACE", "FONT", "CURVES", "POINTCLOUD", "VOLUME", "GPENCIL"}


class ExportError(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# OpenEXR, written by hand: single part, scan lines, no compression, 32-bit float channels.


def _attr(name, kind, payload):
    return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(payload)) + payload


def write_exr(path, width, height, channels):
    """channels: {name: list of width*height floats, rows from the top}."""
    names = sorted(channels)
    chlist = b"".join(n.encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for n in names) + b"\0"
    box = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (
        struct.pack("<ii", 20000630, 2)
        + _attr("channels", "chlist", chlist)
        + _attr("compression", "compression", b"\0")
        + _attr("dataWindow", "box2i", box)
        + _attr("displayWindow", "box2i", box)
        + _attr("lineOrder", "lineOrder", b"\0")
        + _attr("pixelAspectRatio", "float", struct.pack("<f", 1.0))
        + _attr("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
        + _attr("screenWindowWidth", "float", struct.pack("<f", 1.0))
        + b"\0"
    )
    line_bytes = 4 * width * len(names)
    first = len(header) + 8 * height
    offsets = struct.pack("<%dQ" % height, *(first + y * (8 + line_bytes) for y in range(height)))
    row_fmt = "<%df" % width
    with open(path, "wb") as f:
        f.write(header)
        f.write(offsets)
        for y in range(height):
            f.write(struct.pack("<ii", y, line_bytes))
            for n in names:
                f.write(struct.pack(row_fmt, *channels[n][y * width : (y + 1) * width]))


# ---------------------------------------------------------------------------------------------
# The camera.


def render_size(scene, scale):
    r = scene.render
    if abs(r.pixel_aspect_x - r.pixel_aspect_y) > 1e-6 * max(r.pixel_aspect_x, r.pixel_aspect_y):
        raise ExportError(
            "pixel aspect %g:%g is not square; aokit assumes square pixels (set Output > "
            "Format > Aspect X = Y)" % (r.pixel_aspect_x, r.pixel_aspect_y)
        )
    # Blender's own size: resolution * percentage / 100, rounded down.
    w = r.resolution_x * r.resolution_percentage // 100
    h = r.resolution_y * r.resolution_percentage // 100
    w, h = int(round(w * scale)), int(round(h * scale))
    if w < 1 or h < 1:
        raise ExportError("render size %dx%d is empty (check --scale)" % (w, h))
    return w, h


def camera_params(cam, width, height):
    """What camera.json needs, derived as Blender's BKE_camera_params_compute_viewplane does:
    the sensor fit picks which image side the sensor (or ortho_scale) spans, AUTO the longer
    one with the sensor width; shift is in units of that side."""
    data = cam.data
    if data.type not in ("PERSP", "ORTHO"):
        raise ExportError(
            "camera %r is %s; only perspective and orthographic cameras can be exported"
            % (cam.name, {"PANO": "panoramic"}.get(data.type, data.type))
        )
    fit = data.sensor_fit
    if fit == "AUTO":
        horizontal, sensor = width >= height, data.sensor_width
    elif fit == "HORIZONTAL":
        horizontal, sensor = True, data.sensor_width
    elif fit == "VERTICAL":
        horizontal, sensor = False, data.sensor_height
    else:
        raise ExportError("unknown sensor fit %r" % fit)
    fit_pixels = width if horizontal else height
    # The frustum's extent along the fitted side: at distance 1 (perspective) or in world units.
    extent = sensor / data.lens if data.type == "PERSP" else data.ortho_scale
    extent_y = extent if not horizontal else extent * height / width
    # Blender moves the image window by shift * (fitted side); the view axis moves the other way.
    ndc_offset = [-2.0 * data.shift_x * fit_pixels / width, -2.0 * data.shift_y * fit_pixels / height]
    out = {"width": width, "height": height}
    if data.type == "PERSP":
        out["projection"] = "perspective"
        out["fov_y_deg"] = math.degrees(2.0 * math.atan(extent_y / 2.0))
    else:
        out["projection"] = "orthographic"
        out["ortho_height"] = extent_y
    out["near"] = data.clip_start
    out["far"] = data.clip_end
    out["reverse_z"] = False
    if ndc_offset != [0.0, 0.0]:
        out["ndc_offset"] = ndc_offset
    return out, extent_y


def check_against_blender(cam, depsgraph, params, extent_y):
    """Blender's own projection matrix for this size must say what camera.json says."""
    w, h = params["width"], params["height"]
    p = cam.evaluated_get(depsgraph).calc_matrix_camera(depsgraph, x=w, y=h, scale_x=1.0, scale_y=1.0)
    off = params.get("ndc_offset", [0.0, 0.0])
    if params["projection"] == "perspective":
        want = [(1, 1, 2.0 / extent_y), (0, 0, 2.0 / extent_y * h / w), (0, 2, -off[0]), (1, 2, -off[1])]
    else:
        want = [(1, 1, 2.0 / extent_y), (0, 0, 2.0 / extent_y * h / w), (0, 3, off[0]), (1, 3, off[1])]
    for r, c, v in want:
        if abs(p[r][c] - v) > 1e-4 * max(1.0, abs(v)):
            raise ExportError(
                "internal: Blender's projection[%d][%d] = %g, camera.json implies %g" % (r, c, p[r][c], v)
            )


# ---------------------------------------------------------------------------------------------
# The passes.


def trace(scene, depsgraph, cam, params, extent_y, progress=True):
    w, h = params["width"], params["height"]
    near, far = params["near"], params["far"]
    ortho = params["projection"] == "orthographic"
    off = params.get("ndc_offset", [0.0, 0.0])
    loc, rot, _scale = cam.matrix_world.decompose()  # Blender ignores the camera's scale
    world_from_view = Matrix.LocRotScale(loc, rot, None)
    basis = rot.to_matrix()  # view -> world rotation
    half_y = extent_y / 2.0
    half_x = half_y * w / h
    forward = basis @ Vector((0.0, 0.0, -1.0))
    depth = [0.0] * (w * h)
    nx, ny, nz = [0.0] * (w * h), [0.0] * (w * h), [0.0] * (w * h)
    basis_t = basis.transposed()
    cam_x, cam_y, cam_z = loc
    f_x, f_y, f_z = forward
    ray_cast = scene.ray_cast
    last = time.time()
    for y in range(h):
        ndc_y = 1.0 - (y + 0.5) / h * 2.0 - off[1]
        for x in range(w):
            ndc_x = (x + 0.5) / w * 2.0 - 1.0 - off[0]
            if ortho:
                origin = world_from_view @ Vector((ndc_x * half_x, ndc_y * half_y, -near))
                direction = forward
                dist = far - near
            else:
                d = basis @ Vector((ndc_x * half_x, ndc_y * half_y, -1.0))
                origin = loc + d * near  # on the near plane
                dist = (far - near) * d.length
                direction = d.normalized()
            hit, p, n, _i, _o, _m = ray_cast(depsgraph, origin, direction, distance=dist)
            if not hit:
                continue
            i = y * w + x
            depth[i] = (p[0] - cam_x) * f_x + (p[1] - cam_y) * f_y + (p[2] - cam_z) * f_z
            nv = basis_t @ n
            if nv.length_squared == 0.0:
                continue
            nv.normalize()
            dv = basis_t @ direction
            if nv.dot(dv) > 0.0:  # turned towards the camera, as aokit's reference does
                nv.negate()
            nx[i], ny[i], nz[i] = nv
        if progress and time.time() - last > 2.0:
            last = time.time()
            print("aokit export: row %d of %d" % (y + 1, h), flush=True)
    return depth, (nx, ny, nz)


def view_from_world(cam):
    loc, rot, _scale = cam.matrix_world.decompose()
    m = Matrix.LocRotScale(loc, rot, None).inverted()
    return [[m[r][c] for c in range(4)] for r in range(4)]


def camera_json(params):
    """camera.json with one matrix row a line; floats as Python's repr (exact round trip)."""
    lines = ["{"]
    for key, value in params.items():
        if key == "view_from_world":
            rows = ",\n".join("    " + json.dumps(row) for row in value)
            lines.append('  "view_from_world": [\n%s\n  ],' % rows)
        else:
            lines.append("  %s: %s," % (json.dumps(key), json.dumps(value)))
    lines[-1] = lines[-1].rstrip(",")
    return "\n".join(lines) + "\n}\n"


def export(scene, out_dir, scale=1.0, camera=None, progress=True):
    if camera is not None:
        cam = bpy.data.objects.get(camera)
        if cam is None:
            raise ExportError("no object named %r" % camera)
    else:
        cam = scene.camera
    if cam is None:
        raise ExportError("scene %r has no active camera (Scene Properties > Camera)" % scene.name)
    if cam.type != "CAMERA":
        raise ExportError("object %r is a %s, not a camera" % (cam.name, cam.type))
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise ExportError("--out %s exists and is not a folder" % out_dir)
    if not scale > 0.0 or math.isinf(scale):
        raise ExportError("--scale must be a positive number, not %r" % scale)
    if scene == bpy.context.scene:
        depsgraph = bpy.context.evaluated_depsgraph_get()
    else:  # another scene: evaluate its first rendered view layer
        layer = next((v for v in scene.view_layers if v.use), scene.view_layers[0])
        with bpy.context.temp_override(scene=scene, view_layer=layer):
            depsgraph = bpy.context.evaluated_depsgraph_get()
    width, height = render_size(scene, scale)
    params, extent_y = camera_params(cam, width, height)
    check_against_blender(cam, depsgraph, params, extent_y)
    params["view_from_world"] = view_from_world(cam)
    os.makedirs(out_dir, exist_ok=True)
    unseen = [ob.name for ob in scene.objects if ob.type in UNSEEN_TYPES and ob.visible_get()]
    if unseen:
        print(
            "aokit export: warning: scene.ray_cast does not see curve, surface, text, hair, point "
            "cloud, volume or grease pencil objects; convert them to meshes (Object > Convert > "
            "Mesh) to include them: %s" % ", ".join(sorted(unseen)[:10] + (["..."] if len(unseen) > 10 else [])),
            file=sys.stderr,
            flush=True,
        )
    start = time.time()
    depth, (nx, ny, nz) = trace(scene, depsgraph, cam, params, extent_y, progress)
    seconds = time.time() - start
    write_exr(os.path.join(out_dir, "depth.exr"), width, height, {"Z": depth})
    write_exr(os.path.join(out_dir, "normal.exr"), width, height, {"R": nx, "G": ny, "B": nz})
    with open(os.path.join(out_dir, "camera.json"), "w") as f:
        f.write(camera_json(params))
    hits = sum(1 for d in depth if d > 0.0)
    print(
        "aokit export: %dx%d from camera %r, %d pixels hit, %.1f s (%.0f rays/s) -> %s"
        % (width, height, cam.name, hits, seconds, width * height / max(seconds, 1e-9), out_dir),
        flush=True,
    )
    return params


def parse_args(argv):
    import argparse

    p = argparse.ArgumentParser(
        prog="blender -b scene.blend -P export_aokit.py --",
        description="Export depth.exr, normal.exr and camera.json for `aokit ao` from the active camera.",
    )
    p.add_argument("--out", required=True, help="output folder (created; must not be a file)")
    p.add_argument("--scale", type=float, default=1.0, help="multiply the render size (default 1)")
    p.add_argument("--scene", default=None, help="scene name (default: the current scene)")
    p.add_argument("--camera", default=None, help="camera object name (default: the scene's active camera)")
    return p.parse_args(argv)


def main():
    if "--" in sys.argv:
        args = parse_args(sys.argv[sys.argv.index("--") + 1 :])
        out, scale, scene_name, camera = args.out, args.scale, args.scene, args.camera
    elif bpy.app.background:
        parse_args([])  # prints the usage and exits with status 2
        return
    else:
        out, scale, scene_name, camera = UI_OUT, UI_SCALE, None, None
        if out.startswith("//") and not bpy.data.filepath:
            raise ExportError("save the .blend first, or set UI_OUT to an absolute folder")
        out = bpy.path.abspath(out)
    scene = bpy.data.scenes.get(scene_name) if scene_name else bpy.context.scene
    if scene is None:
        raise ExportError("no scene named %r" % scene_name)
    export(scene, out, scale, camera)


if __name__ == "__main__":
    try:
        main()
    except ExportError as e:
        if bpy.app.background:
            print("aokit export: error: %s" % e, file=sys.stderr, flush=True)
            sys.exit(2)
        raise
    except Exception:
        # Blender -b would print the traceback and still exit 0; a failed export must not.
        if bpy.app.background:
            import traceback

            traceback.print_exc()
            sys.exit(1)
        raise
