#!/usr/bin/env python3
"""Converts a Quake III / OpenArena map (IBSP version 46) to a Wavefront OBJ that aokit reads.

Only geometry is kept: the polygon and mesh surfaces as they are, curved patches tessellated,
in metres with +Y up (a map unit is an inch, +Z up). Surfaces nobody sees as solid are left out:
sky, nodraw, fog, water, lava, slime and billboards. Vertices at the same place are welded, so
aokit's generated normals run smooth over the seams between a patch's pieces.

    python3 scripts/bsp_to_obj.py MAP.bsp OUT.obj [--patch-steps N]
"""
import argparse
import json
import math
import re
import struct
import sys

INCH = 0.0254
# A player's eye above the spawn point's origin (bg_public.h DEFAULT_VIEWHEIGHT).
EYE_HEIGHT = 26.0
# Surface flags and contents (q_shared.h) that make a surface invisible or not solid.
SURF_SKY, SURF_NODRAW = 0x4, 0x80
CONTENTS_LIQUID_OR_FOG = 8 | 16 | 32 | 64
# Surface types; the fourth, billboards (flares), is left out.
POLYGON, PATCH, MESH = 1, 2, 3


def lumps(data):
    magic, version = struct.unpack_from("<4si", data, 0)
    if magic != b"IBSP" or version != 46:
        sys.exit(f"not a Quake III map (IBSP 46): magic {magic!r}, version {version}")
    return [struct.unpack_from("<ii", data, 8 + 8 * i) for i in range(17)]


def records(data, lump, fmt):
    offset, length = lump
    size = struct.calcsize(fmt)
    return [struct.unpack_from(fmt, data, offset + i * size) for i in range(length // size)]


def bezier3(a, b, c, t):
    s = 1.0 - t
    return tuple(s * s * a[k] + 2 * s * t * b[k] + t * t * c[k] for k in range(3))


def patch_triangles(points, width, height, steps):
    """Tessellates a patch's grid of control points (3x3 biquadratic pieces) into triangles."""
    out = []
    for py in range(0, height - 1, 2):
        for px in range(0, width - 1, 2):
            ctrl = [[points[(py + j) * width + px + i] for i in range(3)] for j in range(3)]
            grid = []
            for v in range(steps + 1):
                rows = [bezier3(*ctrl[j], v / steps) for j in range(3)]
                # ctrl[j] runs along x, so each row j gives the point at v along x; then along y.
                grid.append([bezier3(rows[0], rows[1], rows[2], u / steps) for u in range(steps + 1)])
            for a in range(steps):
                for b in range(steps):
                    p00, p01 = grid[a][b], grid[a][b + 1]
                    p10, p11 = grid[a + 1][b], grid[a + 1][b + 1]
                    out += [(p00, p10, p11), (p00, p11, p01)]
    return out


def convert(data, steps):
    lump = lumps(data)
    shaders = records(data, lump[1], "<64sii")
    positions = [v[0:3] for v in records(data, lump[10], "<3f2f2f3f4B")]
    meshverts = [m[0] for m in records(data, lump[11], "<i")]
    faces = records(data, lump[13], "<12i3f3f3f3f2i")
    triangles, skipped = [], 0
    for face in faces:
        shader, _, kind, first, count, first_index, index_count = face[:7]
        _, flags, contents = shaders[shader]
        if flags & (SURF_SKY | SURF_NODRAW) or contents & CONTENTS_LIQUID_OR_FOG:
            skipped += 1
            continue
        if kind in (POLYGON, MESH):
            idx = [first + meshverts[first_index + k] for k in range(index_count)]
            triangles += [tuple(positions[i] for i in idx[k:k + 3]) for k in range(0, len(idx) - 2, 3)]
        elif kind == PATCH:
            width, height = face[-2:]
            triangles += patch_triangles(positions[first:first + count], width, height, steps)
        else:
            skipped += 1
    return triangles, skipped


def spawn_cameras(data):
    """The player spawn points as cameras at eye height, looking where the player would."""
    offset, length = lumps(data)[0]
    text = data[offset:offset + length].decode("latin-1")
    cameras = []
    for body in re.findall(r"\{([^{}]*)\}", text):
        keys = dict(re.findall(r'"([^"]*)"\s+"([^"]*)"', body))
        if not keys.get("classname", "").startswith("info_player"):
            continue
        x, y, z = (float(v) for v in keys["origin"].split())
        yaw = math.radians(float(keys.get("angle", "0")))
        z += EYE_HEIGHT
        eye = (x, y, z)
        target = (x + 100 * math.cos(yaw), y + 100 * math.sin(yaw), z)
        cameras.append({
            "name": f"spawn{len(cameras)}",
            "eye": [round(c, 3) for c in to_metres(eye)],
            "target": [round(c, 3) for c in to_metres(target)],
            "fov_y_deg": 60.0,
        })
    return cameras


def to_metres(p):
    # Quake's (x, y, z) with +Z up becomes (x, z, -y) with +Y up: a rotation, so windings keep.
    x, y, z = p
    return (round(x * INCH, 4), round(z * INCH, 4), round(-y * INCH, 4))


def write_obj(triangles, path, source):
    index, vertices, faces = {}, [], []
    for tri in triangles:
        ids = []
        for corner in tri:
            p = to_metres(corner)
            if p not in index:
                index[p] = len(vertices) + 1
                vertices.append(p)
            ids.append(index[p])
        if len(set(ids)) == 3:
            faces.append(ids)
    with open(path, "w") as out:
        out.write(f"# {source}: converted by scripts/bsp_to_obj.py (metres, +Y up)\n")
        out.writelines(f"v {x:.4f} {y:.4f} {z:.4f}\n" for x, y, z in vertices)
        out.writelines(f"f {a} {b} {c}\n" for a, b, c in faces)
    return len(vertices), len(faces)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bsp")
    parser.add_argument("obj")
    parser.add_argument("--patch-steps", type=int, default=6, help="segments per patch piece side")
    parser.add_argument("--source", default=None, help="what to name as the source in the header")
    parser.add_argument("--spawn-cameras", metavar="JSON",
                        help="also write the spawn points as a camera sidecar, to choose views from")
    args = parser.parse_args()
    if args.patch_steps < 1:
        sys.exit(f"--patch-steps {args.patch_steps}: needs at least 1")
    data = open(args.bsp, "rb").read()
    try:
        cameras = spawn_cameras(data)
        triangles, skipped = convert(data, args.patch_steps)
    except (struct.error, IndexError, KeyError, ValueError) as error:
        sys.exit(f"{args.bsp}: truncated or corrupt map ({error})")
    if args.spawn_cameras:
        with open(args.spawn_cameras, "w") as out:
            json.dump({"cameras": cameras}, out, indent=1)
    if not triangles:
        sys.exit(f"{args.bsp}: no solid surfaces")
    vertices, faces = write_obj(triangles, args.obj, args.source or args.bsp)
    print(f"{args.obj}: {vertices} vertices, {faces} triangles ({skipped} surfaces left out)")


if __name__ == "__main__":
    main()
