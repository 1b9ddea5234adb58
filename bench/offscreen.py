"""Where the error lies: the border band, near depth discontinuities, elsewhere (docs/quality.md,
"Off-screen samples and silhouettes"). Runs `aokit compare` on a set of views for one method at
`high` with its default filtering plus any --set given, then splits each view's squared error
against the cached 512-ray reference (480x270) into three disjoint bands:

    border     surface pixels within 12 px of the image's edge;
    edges      the others within 2 px of a depth discontinuity (a background neighbour or a
               depth jump over 5%, as `aokit compare`'s `edges` column marks them);
    elsewhere  the rest.

    python3 bench/offscreen.py VIEWS METHOD [--set KEY=VALUE ...]    # VIEWS: tuning or held-out

Prints the RMSE of each band and of all surface pixels, per view, their mean over the views
(as docs/quality.md's tables take it) and over the set's pixels pooled, with each band's share
of the squared error. The AO is read back from compare's 8-bit PNGs: their rounding adds an RMSE of
about 0.001 in quadrature, which moves no figure here by more than 0.0001.
"""

import glob
import json
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

from aokit_files import cache_dir, read_exr

AOKIT = os.environ.get("AOKIT", "target/release/aokit")
SIZE = (480, 270)
BORDER = 12
EDGE_RELATIVE_DEPTH = 0.05
EDGE_RADIUS = 2
BANDS = ["border", "edges", "elsewhere", "all"]




def edge_mask(depth):
    """compare's depth_edge_mask: surface pixels within EDGE_RADIUS of a depth edge."""
    surface = np.isfinite(depth) & (depth > 0)
    edges = np.zeros_like(surface)
    for axis in (0, 1):
        a = depth.take(range(0, depth.shape[axis] - 1), axis)
        b = depth.take(range(1, depth.shape[axis]), axis)
        sa = surface.take(range(0, depth.shape[axis] - 1), axis)
        sb = surface.take(range(1, depth.shape[axis]), axis)
        with np.errstate(invalid="ignore"):
            jump = np.abs(a - b) > EDGE_RELATIVE_DEPTH * np.minimum(a, b)
        first = sa & (~sb | jump)
        second = sb & (~sa | jump)
        if axis == 0:
            edges[:-1] |= first
            edges[1:] |= second
        else:
            edges[:, :-1] |= first
            edges[:, 1:] |= second
    padded = np.pad(edges, EDGE_RADIUS)
    dilated = np.zeros_like(edges)
    for dy in range(2 * EDGE_RADIUS + 1):
        for dx in range(2 * EDGE_RADIUS + 1):
            dilated |= padded[dy : dy + edges.shape[0], dx : dx + edges.shape[1]]
    return dilated & surface, surface


def bands(depth):
    edges, surface = edge_mask(depth)
    border = np.zeros_like(surface)
    border[:BORDER] = border[-BORDER:] = True
    border[:, :BORDER] = border[:, -BORDER:] = True
    border &= surface
    edges &= ~border
    return {
        "border": border,
        "edges": edges,
        "elsewhere": surface & ~border & ~edges,
        "all": surface,
    }




def reference_dir(view):
    scene, camera = [part.strip() for part in view.split("/")]
    pattern = f"{cache_dir()}/references/{scene}-{camera}-{SIZE[0]}x{SIZE[1]}-r*-spp512-*"
    found = sorted(glob.glob(pattern))
    if len(found) != 1:
        sys.exit(f"offscreen.py: expected one cached reference at {pattern}, found {len(found)}")
    return found[0]


def slug(name):
    return re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-")


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("tuning", "held-out"):
        sys.exit(__doc__)
    views, method, extra = sys.argv[1], sys.argv[2], sys.argv[3:]
    with tempfile.TemporaryDirectory() as out:
        subprocess.run(
            [AOKIT, "compare", "--views", views, "--method", method, "--preset", "high",
             "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", "512", "--timing-frames", "1",
             *extra, "--out", out],
            check=True, stdout=subprocess.DEVNULL,
        )
        results = json.load(open(f"{out}/metrics.json"))["results"]
        pooled = {band: [0.0, 0] for band in BANDS}
        per_view = {band: [] for band in BANDS}
        print(f"`{method}` high {' '.join(extra)} on the {views} views, RMSE:\n")
        print("| view | " + " | ".join(BANDS) + " |")
        print("|---|" + "--:|" * len(BANDS))
        for row in results:
            reference = reference_dir(row["view"])
            truth = read_exr(f"{reference}/reference.exr")["Y"]
            masks = bands(read_exr(f"{reference}/depth.exr")["Z"])
            png = f"{out}/images/{slug(row['view'])}-{method}-high.png"
            ao = np.asarray(Image.open(png), np.float32) / 255.0
            squared = (ao - truth) ** 2
            cells = []
            for band in BANDS:
                errors = squared[masks[band]]
                pooled[band][0] += float(errors.sum())
                pooled[band][1] += errors.size
                if errors.size:
                    per_view[band].append(np.sqrt(errors.mean()))
                cells.append(f"{np.sqrt(errors.mean()):.4f}" if errors.size else "-")
            # The PNG's rounding against compare's own float score: a wrong file or mask shows.
            if abs(np.sqrt(squared[masks["all"]].mean()) - row["all"]["rmse"]) > 0.001:
                sys.exit(f"offscreen.py: {row['view']} does not score as compare scored it")
            print(f"| {row['view']} | " + " | ".join(cells) + " |")
        cells = [f"{np.mean(rmse):.4f}" for rmse in per_view.values()]
        print("| **mean** over the views | " + " | ".join(cells) + " |")
        total = pooled["all"][0]
        cells = [f"{np.sqrt(s / n):.4f} ({s / total:.0%})" for s, n in pooled.values()]
        print("| **pooled** (share of squared error) | " + " | ".join(cells) + " |")


main()
