#!/usr/bin/env python3
"""Writes the hand-made seeds under fuzz/seeds/ (run by fuzz/seed.sh --regenerate): small
glTF/GLB scenes, OBJs with and without a camera sidecar, PFM and NPY passes, camera.json and
settings files. EXR seeds come from `aokit render --gbuffer` (fuzz/seed.sh)."""
import base64, json, os, struct, sys

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "seeds")


def put(target, name, data):
    os.makedirs(os.path.join(out, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(out, target, name), "wb") as f:
        f.write(data)


# glTF: a unit cube (indexed, with normals) under a translated parent, and a camera.
cube_pos, cube_nrm, cube_idx = [], [], []
for axis in range(3):
    for sign in (-1.0, 1.0):
        n = [0.0, 0.0, 0.0]
        n[axis] = sign
        u, v = [(axis + 1) % 3, (axis + 2) % 3]
        base = len(cube_pos)
        for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [0.0, 0.0, 0.0]
            p[axis], p[u], p[v] = sign * 0.5, a * 0.5, b * 0.5
            cube_pos.append(p)
            cube_nrm.append(n)
        quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
        cube_idx += [base + i for i in quad]
pos = b"".join(struct.pack("<3f", *p) for p in cube_pos)
nrm = b"".join(struct.pack("<3f", *n) for n in cube_nrm)
idx = b"".join(struct.pack("<H", i) for i in cube_idx)
idx += b"\0" * (-len(idx) % 4)
blob = pos + nrm + idx


def gltf(uri):
    buffer = {"byteLength": len(blob)}
    if uri:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0, 2]}],
        "nodes": [
            {"translation": [0, 0.5, 0], "children": [1]},
            {"mesh": 0, "scale": [2, 1, 2]},
            {"camera": 0, "translation": [0, 1, 4], "name": "front"},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "znear": 0.1}}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.2, 1]}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3", "min": [-0.5] * 3, "max": [0.5] * 3},
            {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 36, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pos)},
            {"buffer": 0, "byteOffset": len(pos), "byteLength": len(nrm)},
            {"buffer": 0, "byteOffset": len(pos) + len(nrm), "byteLength": 72},
        ],
        "buffers": [buffer],
    }


put("gltf", "cube.gltf", json.dumps(gltf(True)))
js = json.dumps(gltf(False)).encode()
js += b" " * (-len(js) % 4)
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(blob))
glb += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(blob), b"BIN\0") + blob
put("gltf", "cube.glb", glb)
# A triangle without indices or normals, an orthographic camera.
tri = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
put("gltf", "triangle.gltf", json.dumps({
    "asset": {"version": "2.0"},
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}],
    "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64," + base64.b64encode(tri).decode()}],
}))

# OBJ: a quad without normals, a cube with normals and texture coordinates, negative indices,
# and one with a camera sidecar after a NUL byte.
put("obj", "ramp.obj", "v 0 0 0\nv 2 0 0\nv 2 1 -2\nv 0 1 -2\nf 1 2 3 4\n")
lines = ["o cube", "mtllib cube.mtl", "usemtl red"]
lines += ["v %g %g %g" % tuple(p) for p in cube_pos]
lines += ["vn %g %g %g" % tuple(n) for n in cube_nrm]
lines += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1"]
for t in range(0, len(cube_idx), 3):
    a, b, c = (cube_idx[t + k] + 1 for k in range(3))
    lines.append("f %d/%d/%d %d/%d/%d %d/%d/%d" % (a, 1, a, b, 2, b, c, 3, c))
put("obj", "cube.obj", "\n".join(lines) + "\n")
put("obj", "negative.obj", "g tri\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-1\ns 1\nl 1 2\np 3\n")
sidecar = {"suggested_ao_radius": 0.3, "cameras": [
    {"name": "side", "eye": [5, 1, 0], "target": [1, 0.5, -1], "fov_y_deg": 50},
    {"name": "up", "eye": [0, 1, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 70}]}
put("obj", "ramp-with-sidecar.obj", "v 0 0 0\nv 2 0 0\nv 2 1 -2\nv 0 1 -2\nf 1 2 3 4\n\0" + json.dumps(sidecar))

# camera.json: perspective and orthographic, jittered.
view = [[1, 0, 0, 0], [0, 1, 0, -1], [0, 0, 1, -5], [0, 0, 0, 1]]
put("camera_json", "perspective.json", json.dumps({"width": 8, "height": 6, "projection": "perspective",
    "fov_y_deg": 60, "near": 0.1, "far": None, "reverse_z": True, "view_from_world": view}))
put("camera_json", "orthographic.json", json.dumps({"width": 16, "height": 9, "projection": "orthographic",
    "ortho_height": 4, "near": 0.5, "far": 50, "reverse_z": False, "ndc_offset": [0.01, -0.02],
    "view_from_world": view}))


# PFM and NPY: depth (1 channel) and normals (3), both byte orders and dtypes.
def pfm(channels, w, h, little, values):
    head = b"%s\n%d %d\n%s\n" % (b"Pf" if channels == 1 else b"PF", w, h, b"-1.0" if little else b"1.0")
    return head + b"".join(struct.pack("<f" if little else ">f", v) for v in values)


depth = [0.0, 1.5, 2.0, float("inf"), 3.0, float("nan")]
normals = [0, 0, 1] * 6
put("pfm", "depth-le.pfm", pfm(1, 3, 2, True, depth))
put("pfm", "depth-be.pfm", pfm(1, 2, 3, False, depth))
put("pfm", "normals.pfm", pfm(3, 3, 2, True, normals))


def npy(descr, shape, values, version=1):
    header = "{'descr': '%s', 'fortran_order': False, 'shape': (%s), }" % (
        descr, ", ".join(str(s) for s in shape) + ("," if len(shape) == 1 else ""))
    fmt = {"<f4": "<f", ">f4": ">f", "<f8": "<d", ">f8": ">d"}[descr]
    pre = 10 if version == 1 else 12
    header += " " * (-(pre + len(header) + 1) % 64) + "\n"
    size = struct.pack("<H", len(header)) if version == 1 else struct.pack("<I", len(header))
    return b"\x93NUMPY" + bytes([version, 0]) + size + header.encode() + b"".join(struct.pack(fmt, v) for v in values)


put("npy", "depth-f4.npy", npy("<f4", (2, 3), depth))
put("npy", "depth-f8-hw1.npy", npy(">f8", (3, 2, 1), depth, version=2))
put("npy", "normals.npy", npy("<f4", (2, 3, 3), normals))

# Settings: a file, then `--set` lines after a NUL byte.
put("settings", "gtao.toml", 'method = "gtao"\nradius = 0.5\n[gtao]\nslice_count = 4\n[spatial]\nenabled = true\nkind = "guided"\n')
put("settings", "sets.toml", 'intensity = 1.2\n\0radius=2\ngtao.slice_count=5\nspatial.sigma=1.5\nnoise.kind=blue\nmin_radius_px=3\nmax_radius_px=2\n')
put("settings", "vbao.toml", 'method = "vbao"\n[vbao]\nback_faces = true\n[temporal]\nenabled = true\nblend = 0.9\n\0resolution=half\nupsample_threshold=0.1\n')
