"""What the bench scripts read of aokit's files: its EXR images and the reference cache that
`aokit compare` fills (crates/aokit-cli/src/cache.rs)."""

import os
import struct
import sys
import zlib

import numpy as np

def read_exr(path):
    """The channels of an EXR as aokit writes it: scanlines, f32, uncompressed or ZIP."""
    data = open(path, "rb").read()
    if struct.unpack_from("<I", data, 0)[0] != 20000630:
        sys.exit(f"{path} is not an EXR")
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        pos = end + 1
        end = data.index(b"\0", pos)
        pos = end + 1
        size = struct.unpack_from("<i", data, pos)[0]
        attrs[name] = data[pos + 4 : pos + 4 + size]
        pos += 4 + size
    pos += 1
    listed, channels, p = attrs["channels"], [], 0
    while listed[p] != 0:
        end = listed.index(b"\0", p)
        channels.append(listed[p:end].decode())
        p = end + 1 + 16
    x0, y0, x1, y1 = struct.unpack("<iiii", attrs["dataWindow"])
    width, height = x1 - x0 + 1, y1 - y0 + 1
    compression = attrs["compression"][0]
    if compression not in (0, 2, 3):
        sys.exit(f"{path}: EXR compression {compression} is not read here")
    lines = 16 if compression == 3 else 1
    chunks = (height + lines - 1) // lines
    offsets = struct.unpack_from(f"<{chunks}Q", data, pos)
    out = {name: np.zeros((height, width), np.float32) for name in channels}
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        raw = data[offset + 8 : offset + 8 + size]
        rows = min(lines, y1 + 1 - y)
        if compression != 0 and size < rows * width * 4 * len(channels):
            # ZIP: deflate, then undo the byte predictor and the split into two halves.
            a = np.frombuffer(zlib.decompress(raw), np.uint8).astype(np.int64)
            a = (np.cumsum(np.concatenate([a[:1], a[1:] - 128])) & 0xFF).astype(np.uint8)
            half = (len(a) + 1) // 2
            b = np.empty_like(a)
            b[0::2], b[1::2] = a[:half], a[half:]
            raw = b.tobytes()
        block = np.frombuffer(raw, "<f4").reshape(rows, len(channels), width)
        for i, name in enumerate(channels):
            out[name][y - y0 : y - y0 + rows] = block[:, i]
    return out


def cache_dir():
    """Where `aokit compare` caches references: $AOKIT_CACHE, else $XDG_CACHE_HOME/aokit, else
    ~/.cache/aokit, as the CLI looks."""
    return os.environ.get("AOKIT_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "aokit"
    )
