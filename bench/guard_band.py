"""Error in the border band against the guard band's size, and its cost (docs/quality.md,
"Guard band"). For each view, tuning and held-out, at 480x270, GTAO `high` with its default
filtering is rendered with guard bands of 0, 8, 16 and 32 px and of the kernel's radius in pixels (the
median over the border band's pixels of the AO radius projected at their depth, clamped to
`max_radius_px`), and scored against the 512-ray reference that `aokit compare` caches: RMSE
over the pixels showing a surface within 12 px of the image's edge, and over the whole image.
Issue 27's target is checked on the held-out views: at the kernel's radius, the border band's
RMSE at least a third lower than without a band. Then `aokit bench` times each band against
none, interleaved, on room, Sponza's atrium and a held-out view.

    python3 bench/guard_band.py [AOKIT]    # AOKIT: the binary, default target/release/aokit

Prints three markdown tables. The held-out scenes come from `bash scripts/fetch-scenes.sh`.
About 6 minutes on 2 cores with the references cached.
"""

import glob
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from aokit_files import cache_dir, read_exr

SIZE = (480, 270)
BORDER = 12
BANDS = [0, 8, 16, 32]
SETTINGS = ["--method", "gtao", "--preset", "high"]
TIMED = [("room", "front"), ("scenes/sponza.obj", "atrium"), ("scenes/oa_rpg3dm2.obj", "plaza")]


def view_set(name):
    """A view set as (scene, camera) pairs, read from the CLI's source so that the lists are
    declared once (crates/aokit-cli/src/view_sets.rs)."""
    path = os.path.join(os.path.dirname(__file__), "../crates/aokit-cli/src/view_sets.rs")
    source = open(path).read()
    block = re.search(rf"pub const {name}: \[&str; \d+\] = \[(.*?)\];", source, re.S)
    if block is None:
        sys.exit(f"no {name} list in view_sets.rs")
    return [(v.split("@") + [None])[:2] for v in re.findall(r'"([^"]+)"', block.group(1))]


def render(aokit, scene, camera, band, out):
    """Renders the view with a guard band of `band` px; returns its AO and the camera's name."""
    view = ["--scene", scene] + (["--camera", camera] if camera else [])
    said = run(aokit, "render", *view, *SETTINGS, "--size", f"{SIZE[0]}x{SIZE[1]}",
               "--guard-band", str(band), "--out", out)
    camera = re.search(r"from camera `([^`]+)`", said).group(1)
    return read_exr(f"{out}/ao.exr")["Y"], camera


def run(aokit, *args):
    return subprocess.run([aokit, *args], check=True, capture_output=True, text=True).stdout


def reference_dir(aokit, scene, camera, work):
    """The cached reference of the view at SIZE and 512 rays, traced by `aokit compare` if
    missing."""
    cache = cache_dir()
    stem = os.path.splitext(os.path.basename(scene))[0]
    pattern = f"{cache}/references/{stem}-{camera}-{SIZE[0]}x{SIZE[1]}-r*-spp512-seed0-none-*"
    if not glob.glob(pattern):
        run(aokit, "compare", "--view", f"{scene}@{camera}", *SETTINGS,
            "--size", f"{SIZE[0]}x{SIZE[1]}", "--spp", "512", "--timing-frames", "1",
            "--out", os.path.join(work, "compare"))
    found = sorted(glob.glob(pattern))
    if not found:
        sys.exit(f"no reference for {scene}@{camera} under {pattern}")
    return found[-1]


def radius_px(reference, border, settings):
    """The kernel's radius in pixels over the border band: the median of the radius projected
    at each pixel's depth, clamped to max_radius_px."""
    camera = json.load(open(f"{reference}/camera.json"))
    radius = json.load(open(f"{reference}/reference.json"))["radius"]
    depth = read_exr(f"{reference}/depth.exr")["Z"]
    per_unit = 0.5 * SIZE[1] / math.tan(math.radians(camera["fov_y_deg"]) / 2)
    world = radius * settings["radius_multiplier"]
    px = np.minimum(world * per_unit / depth[border], settings["max_radius_px"])
    return int(math.ceil(np.median(px)))


def print_border_table(title, rows):
    """Prints a view set's border-band table; returns the mean (border, whole) RMSE per band."""
    print(f"\n{title}: border band ({BORDER} px) RMSE / whole-image RMSE, GTAO high, "
          f"{SIZE[0]}x{SIZE[1]}:\n")
    heads = [f"{b} px" for b in BANDS] + ["kernel radius"]
    print("| view | kernel radius (px) | " + " | ".join(heads) + " | border change at the radius |")
    print("|---|---:|" + "---:|" * len(heads) + "---:|")
    means = np.zeros((len(heads), 2))
    for name, kernel, errors in rows:
        cells = [f"{b:.4f} / {w:.4f}" for b, w in errors]
        change = errors[-1][0] / errors[0][0] - 1
        print(f"| {name} | {kernel} | " + " | ".join(cells) + f" | {change:+.0%} |")
        means += np.array(errors) / len(rows)
    change = means[-1][0] / means[0][0] - 1
    cells = [f"{b:.4f} / {w:.4f}" for b, w in means]
    print("| **mean** | | " + " | ".join(cells) + f" | {change:+.1%} |")
    return means


def main():
    aokit = sys.argv[1] if len(sys.argv) > 1 else "target/release/aokit"
    work = tempfile.mkdtemp(prefix="guard-band-")
    y, x = np.mgrid[0 : SIZE[1], 0 : SIZE[0]]
    edge = np.minimum(np.minimum(x, SIZE[0] - 1 - x), np.minimum(y, SIZE[1] - 1 - y)) < BORDER
    settings = {}
    listed = run(aokit, "settings", *SETTINGS)
    for line in listed.splitlines():
        words = line.split()
        if len(words) >= 4 and words[0] in ("radius_multiplier", "max_radius_px"):
            # Columns: key, type, default, value the flags give.
            settings[words[0]] = float(words[3])
    kernel_bands, means = {}, {}
    for title, name in [("Tuning views", "TUNING"), ("Held-out views", "HELD_OUT")]:
        rows = []
        for scene, camera in view_set(name):
            label = f"{os.path.basename(scene)}@{camera or 'default'}"
            unbanded, camera = render(aokit, scene, camera, 0, os.path.join(work, f"{label}-0"))
            reference = reference_dir(aokit, scene, camera, work)
            truth = read_exr(f"{reference}/reference.exr")["Y"]
            surface = read_exr(f"{reference}/depth.exr")["Z"] > 0
            border = surface & edge
            kernel = radius_px(reference, border, settings)
            kernel_bands[f"{scene}@{camera}"] = kernel
            errors = []
            for band in BANDS + [kernel]:
                out = os.path.join(work, f"{label}-{band}")
                ao = unbanded if band == 0 else render(aokit, scene, camera, band, out)[0]
                rmse = lambda mask: float(np.sqrt(np.mean((ao[mask] - truth[mask]) ** 2)))
                errors.append((rmse(border), rmse(surface)))
            rows.append((f"{os.path.basename(scene)}@{camera}", kernel, errors))
        means[name] = print_border_table(title, rows)

    change = means["HELD_OUT"][-1][0] / means["HELD_OUT"][0][0] - 1
    verdict = "holds" if change <= -1 / 3 else "is missed"
    print(f"\nIssue 27's target: on the held-out views, a band of the kernel's radius lowers the "
          f"border band's RMSE by at least a third ({-change:.1%}: {verdict}).")

    print("\nCost: wall time of `aokit bench` with the band against none, interleaved:\n")
    print("| view | band (px) | extra pixels | wall-time ratio |")
    print("|---|---:|---:|---:|")
    for scene, camera in TIMED:
        kernel = kernel_bands[f"{scene}@{camera}"]
        bands = sorted(set(BANDS[1:] + [kernel]))
        configurations = [f"--guard-band {b}" for b in [0] + bands]
        report = json.loads(run(aokit, "bench", "--scene", scene, "--camera", camera, *SETTINGS,
                                "--size", f"{SIZE[0]}x{SIZE[1]}", "--timing-frames", "60",
                                "--warmup", "3", "--json", "--compare", *configurations))
        base = report[0]["wall_ms"]["median"]
        for band, entry in zip(bands, report[1:]):
            extra = (SIZE[0] + 2 * band) * (SIZE[1] + 2 * band) / (SIZE[0] * SIZE[1])
            ratio = entry["wall_ms"]["median"] / base
            name = f"{os.path.basename(scene)}@{camera}"
            print(f"| {name} | {band} | {extra:.2f}x | {ratio:.2f}x |")


if __name__ == "__main__":
    main()
