#!/usr/bin/env python3
"""Check a Blender export against `aokit reference` on the same triangles (pure Python 3).

    check_export.py AOKIT SCENE.obj EXPORT_DIR WORK_DIR [--radius R] [--spp N]

The reference camera is built from EXPORT_DIR/camera.json alone: eye, view axis and up from
view_from_world, the field of view (or ortho height) from fov_y_deg (ortho_height). The reference
cannot shift its lens, so it renders a larger centred frame whose centre is the exported view
axis, and the exported image is cut out of it (the shift must be a whole number of pixels).
Then:
  (a) depth: the exported depth against the reference's depth.exr where both hit;
  (b) AO: `aokit ao` on the exported passes against the cropped reference.exr.
Prints the numbers and exits 1 when a limit is broken.
"""

import json
import math
import os
import struct
import subprocess
import sys
import zlib


def read_exr(path):
    """Single-part scan-line OpenEXR, NONE/ZIPS/ZIP compression, HALF/FLOAT channels."""
    data = open(path, "rb").read()
    magic, version = struct.unpack_from("<ii", data, 0)
    if magic != 20000630 or version & 0x200:
        raise ValueError("%s: not a scan-line OpenEXR file" % path)
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        (size,) = struct.unpack_from("<i", data, end2 + 1)
        attrs[name] = data[end2 + 5 : end2 + 5 + size]
        pos = end2 + 5 + size
    pos += 1
    channels, cpos, raw = [], 0, attrs["channels"]
    while raw[cpos] != 0:
        end = raw.index(b"\0", cpos)
        (ptype,) = struct.unpack_from("<i", raw, end + 1)
        channels.append((raw[cpos:end].decode(), ptype))
        cpos = end + 17
    compression = attrs["compression"][0]
    x0, y0, x1, y1 = struct.unpack("<iiii", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    lines = {0: 1, 2: 1, 3: 16}.get(compression)
    if lines is None:
        raise ValueError("%s: compression %d not supported" % (path, compression))
    nblocks = (h + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % nblocks, data, pos)
    out = {name: [0.0] * (w * h) for name, _ in channels}
    for off in offsets:
        y, size = struct.unpack_from("<ii", data, off)
        block = data[off + 8 : off + 8 + size]
        n = min(lines, y1 + 1 - y)
        raw_size = n * w * sum(2 if t == 1 else 4 for _, t in channels)
        if compression in (2, 3) and size < raw_size:
            t = bytearray(zlib.decompress(block))
            for i in range(1, len(t)):
                t[i] = (t[i - 1] + t[i] - 128) & 0xFF
            half = (len(t) + 1) // 2
            block = bytearray(len(t))
            block[0::2] = t[:half]
            block[1::2] = t[half:]
        p = 0
        for row in range(n):
            yy = y - y0 + row
            for name, ptype in channels:
                fmt = "<%d%s" % (w, "e" if ptype == 1 else "f")
                vals = struct.unpack_from(fmt, block, p)
                p += w * (2 if ptype == 1 else 4)
                out[name][yy * w : (yy + 1) * w] = vals
    return w, h, out


def write_exr_y(path, w, h, values):
    # export_aokit imports bpy at module level; the writer is small, so repeat it here.
    def attr(name, kind, payload):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(payload)) + payload

    box = struct.pack("<iiii", 0, 0, w - 1, h - 1)
    header = (
        struct.pack("<ii", 20000630, 2)
        + attr("channels", "chlist", b"Y\0" + struct.pack("<iB3xii", 2, 0, 1, 1) + b"\0")
        + attr("compression", "compression", b"\0")
        + attr("dataWindow", "box2i", box)
        + attr("displayWindow", "box2i", box)
        + attr("lineOrder", "lineOrder", b"\0")
        + attr("pixelAspectRatio", "float", struct.pack("<f", 1.0))
        + attr("screenWindowCenter", "v2f", struct.pack("<ff", 0.0, 0.0))
        + attr("screenWindowWidth", "float", struct.pack("<f", 1.0))
        + b"\0"
    )
    first = len(header) + 8 * h
    with open(path, "wb") as f:
        f.write(header)
        f.write(struct.pack("<%dQ" % h, *(first + y * (8 + 4 * w) for y in range(h))))
        for y in range(h):
            f.write(struct.pack("<ii", y, 4 * w))
            f.write(struct.pack("<%df" % w, *values[y * w : (y + 1) * w]))


def invert_rigid(m):
    r = [[m[c][r] for c in range(3)] for r in range(3)]  # transpose of the rotation
    t = [-sum(r[i][k] * m[k][3] for k in range(3)) for i in range(3)]
    return r, t


def run(cmd):
    print("+ " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True)


def main():
    args = sys.argv[1:]
    radius, spp = 0.5, 64
    if "--radius" in args:
        i = args.index("--radius")
        radius = float(args[i + 1])
        del args[i : i + 2]
    if "--spp" in args:
        i = args.index("--spp")
        spp = int(args[i + 1])
        del args[i : i + 2]
    aokit, obj, export, work = args
    cam = json.load(open(os.path.join(export, "camera.json")))
    w, h = cam["width"], cam["height"]
    ox, oy = cam.get("ndc_offset", [0.0, 0.0])
    # Pixel position of the view axis in the exported image (x right, y down).
    ax, ay = (ox + 1.0) / 2.0 * w, (1.0 - oy) / 2.0 * h
    if abs(ax - round(ax)) > 1e-3 or abs(ay - round(ay)) > 1e-3:
        sys.exit("check_export: the view axis (%g, %g) is not on a pixel corner" % (ax, ay))
    ax, ay = int(round(ax)), int(round(ay))
    wb, hb = 2 * max(ax, w - ax), 2 * max(ay, h - ay)
    cx, cy = wb // 2 - ax, hb // 2 - ay
    rot_t, eye = invert_rigid(cam["view_from_world"])  # rot_t[i] = world components of view axis i
    axis = lambda i: [rot_t[k][i] for k in range(3)]  # noqa: E731
    fwd, up = [-v for v in axis(2)], axis(1)
    target = [eye[k] + fwd[k] for k in range(3)]
    fmt = lambda v: ",".join(repr(x) for x in v)  # noqa: E731
    ref = os.path.join(work, "reference")
    cmd = [aokit, "reference", "--scene", obj, "--eye", fmt(eye), "--target", fmt(target), "--up", fmt(up),
           "--size", "%dx%d" % (wb, hb), "--radius", repr(radius), "--spp", str(spp),
           "--near", repr(cam["near"]), "--out", ref]
    if cam["projection"] == "perspective":
        t = math.tan(math.radians(cam["fov_y_deg"]) / 2.0) * hb / h
        cmd += ["--fov-y", repr(math.degrees(2.0 * math.atan(t)))]
    else:
        cmd += ["--ortho-height", repr(cam["ortho_height"] * hb / h), "--far", repr(cam["far"])]
    run(cmd)
    aodir = os.path.join(work, "ao")
    run([aokit, "ao", "--depth", os.path.join(export, "depth.exr"), "--normals", os.path.join(export, "normal.exr"),
         "--camera-json", os.path.join(export, "camera.json"), "--radius", repr(radius), "--out", aodir])

    # The baseline: `aokit ao` on the reference's own G-buffer (the larger frame), cropped alike.
    basedir = os.path.join(work, "ao-on-reference-passes")
    run([aokit, "ao", "--depth", os.path.join(ref, "depth.exr"), "--normals", os.path.join(ref, "normal.exr"),
         "--camera-json", os.path.join(ref, "camera.json"), "--radius", repr(radius), "--out", basedir])

    def crop(img):
        return [img[(y + cy) * wb + x + cx] for y in range(h) for x in range(w)]

    _, _, rdepth = read_exr(os.path.join(ref, "depth.exr"))
    _, _, rnorm = read_exr(os.path.join(ref, "normal.exr"))
    _, _, rao = read_exr(os.path.join(ref, "reference.exr"))
    rd = crop(rdepth["Z"])
    rn = [crop(rnorm[c]) for c in "RGB"]
    ra = crop(rao["Y"])
    _, _, ed = read_exr(os.path.join(export, "depth.exr"))
    _, _, en = read_exr(os.path.join(export, "normal.exr"))
    _, _, ea = read_exr(os.path.join(aodir, "ao.exr"))
    _, _, ba = read_exr(os.path.join(basedir, "ao.exr"))
    ed, ea, ba = ed["Z"], ea["Y"], crop(ba["Y"])
    en = [en[c] for c in "RGB"]
    write_exr_y(os.path.join(work, "reference-cropped.exr"), w, h, ra)

    both = [i for i in range(w * h) if ed[i] > 0.0 and rd[i] > 0.0]
    one = sum(1 for i in range(w * h) if (ed[i] > 0.0) != (rd[i] > 0.0))
    rel = sorted(abs(ed[i] - rd[i]) / rd[i] for i in both)
    off = sum(1 for r in rel if r > 1e-4)
    angles = sorted(
        math.degrees(math.acos(max(-1.0, min(1.0, sum(en[c][i] * rn[c][i] for c in range(3)))))) for i in both
    )
    sq = [(ea[i] - ra[i]) ** 2 for i in both]
    rmse = math.sqrt(sum(sq) / len(sq))
    bias = sum(ea[i] - ra[i] for i in both) / len(both)
    base_rmse = math.sqrt(sum((ba[i] - ra[i]) ** 2 for i in both) / len(both))
    vfw_ref = json.load(open(os.path.join(ref, "camera.json")))["view_from_world"]
    vfw_err = max(abs(vfw_ref[r][c] - cam["view_from_world"][r][c]) for r in range(3) for c in range(4))
    print(
        "check_export %s: %dx%d (reference %dx%d cropped at %d,%d), %d pixels both hit, %d hit in one only (%.3f%%)\n"
        "  depth: relative error median %.2e, max %.2e, %d pixels over 1e-4\n"
        "  normals: angle median %.4f deg, 99.9th percentile %.4f deg\n"
        "  view_from_world: largest difference from the reference's %.2e\n"
        "  AO (aokit ao, default method and preset, radius %g) vs reference (%d spp): RMSE %.4f, mean error %+.4f\n"
        "  AO of aokit ao on the reference's own passes, same pixels: RMSE %.4f"
        % (cam["projection"], w, h, wb, hb, cx, cy, len(both), one, 100.0 * one / (w * h), rel[len(rel) // 2],
           rel[-1], off, angles[len(angles) // 2], angles[int(0.999 * (len(angles) - 1))], vfw_err, radius, spp,
           rmse, bias, base_rmse),
        flush=True,
    )
    failures = []
    if len(both) < 0.5 * w * h:
        failures.append("fewer than half the pixels hit")
    if one > 0.005 * w * h:
        failures.append("%d pixels hit in one image only" % one)
    if off > 0.001 * len(both) or rel[-1] > 1e-2:
        failures.append("depth disagrees")
    if angles[int(0.999 * (len(angles) - 1))] > 1.0:
        failures.append("normals disagree")
    if vfw_err > 1e-5:
        failures.append("view_from_world disagrees")
    if rmse > 0.15:
        failures.append("AO RMSE %.4f over 0.15" % rmse)
    if rmse > base_rmse + 0.02:
        failures.append("AO RMSE %.4f, over the reference passes' %.4f + 0.02" % (rmse, base_rmse))
    if failures:
        sys.exit("check_export: FAILED: " + "; ".join(failures))


if __name__ == "__main__":
    main()
