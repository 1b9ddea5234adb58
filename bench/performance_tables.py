#!/usr/bin/env python3
"""Prints docs/performance.md's GPU tables from the JSON that bench/performance.sh and
bench/gpu-run.sh write.

    python3 bench/performance_tables.py DIR

DIR is either script's output directory. Prints, in the page's markdown, whichever of these
DIR holds: the side-by-side tables of gpu-run.sh (aokit against XeGTAO per view and size,
from side-by-side-SCENE-SIZE.json), the two "Every method and preset" tables (`room` and
Sponza's atrium, from SCENE-SIZE-RESOLUTION.json), the "Each pass" table (from
passes-sponza-atrium-SIZE.json), and one table for each set that performance.sh times on both
views and sizes (variants, depth-mips, sample-depth: NAME-SCENE-SIZE.json, each row's ratio to
the row it extends beside it): medians of the total and per-pass GPU time in milliseconds, to
3 decimals. Standard library only.
"""
import json
import sys
from pathlib import Path

SIZES = ["1920x1080", "3840x2160"]
SCENES = [("room", "`room` (camera `front`)"), ("sponza-atrium", "Sponza, camera `atrium`")]
SAMPLES = {"low": 4, "medium": 8, "high": 18, "ultra": 54}
# performance.sh's pass configurations, as the page labels them.
LABELS = {
    "": "(none: GTAO `high`)",
    "--set spatial.enabled=true": "`spatial.enabled=true`",
    "--set spatial.enabled=true --set spatial.kind=bilateral": "`spatial.kind=bilateral`",
    "--set spatial.enabled=true --set spatial.kind=edges": "`spatial.kind=edges`",
    "--set temporal.enabled=true": "`temporal.enabled=true`",
    "--set spatial.enabled=true --set temporal.enabled=true": "both filters",
    "--set spatial.enabled=true --set spatial.kind=guided": "`spatial.kind=guided`",
    "--set temporal.enabled=true --set temporal.filter_current=true":
        "temporal with `filter_current`",
    "--set resolution=half --set spatial.enabled=true --set temporal.enabled=true":
        "half, both filters",
    "--set resolution=half --set spatial.enabled=true --set temporal.enabled=true"
    " --set filter_resolution=full": "half, both filters at full resolution",
    "--set resolution=quarter --set spatial.enabled=true --set temporal.enabled=true":
        "quarter, both filters",
    "--set resolution=half --set downsample=checkerboard --set upsample=nearest-depth":
        "half, `checkerboard` + `nearest-depth`",
    "--set bent_normals=true": "`bent_normals=true`",
    "--set offscreen_samples=extend": "`offscreen_samples=extend`",
    "--set offscreen_samples=unoccluded": "`offscreen_samples=unoccluded`",
    "--guard-band 32": "a 32 px guard band (`--guard-band 32`)",
    "--set normals.encoding=oct16": "`normals.encoding=oct16` (decode pass)",
    "--set normals.source=depth-5tap": "`normals.source=depth-5tap`",
}
# Pipeline order; passes not listed here follow, in the order they first appear.
PASS_ORDER = ["linear_depth", "decode_normals", "normals_from_depth", "downsample", "gtao",
              "upsample", "spatial_filter_horizontal", "spatial_filter_vertical",
              "guided_filter_coefficients", "guided_filter_output", "temporal_filter"]


def load(path):
    with open(path) as f:
        return json.load(f)


def ms(x):
    return f"{x:.3f}"


def option(configuration, name):
    words = configuration.split()
    return words[words.index(name) + 1]


def method_tables(out):
    for scene, heading in SCENES:
        columns = [load(out / f"{scene}-{size}-{res}.json")
                   for size in SIZES for res in ("full", "half")]
        print(f"#### {heading}\n")
        print("| method | preset | samples | 1920x1080 full | half | 3840x2160 full | half |")
        print("|---|---|--:|--:|--:|--:|--:|")
        for row in zip(*columns):
            configuration = row[0]["configuration"]
            assert all(r["configuration"] == configuration for r in row), configuration
            preset = option(configuration, "--preset")
            method = f"`{option(configuration, '--method')}`"
            samples = SAMPLES[preset]
            if "hbao.variant=separable" in configuration:
                # Four fixed directions of `step_count` steps each.
                method += " separable"
                samples = 4 * row[0]["settings"]["hbao"]["step_count"]
            cells = [method, preset, str(samples)]
            cells += [ms(r["total_gpu_ms"]["median"]) for r in row]
            print("| " + " | ".join(cells) + " |")
        print()


def pass_table(out):
    runs = {size: load(out / f"passes-sponza-atrium-{size}.json") for size in SIZES}
    names = [p["name"] for size in SIZES for r in runs[size] for p in r["passes"]]
    order = [n for n in PASS_ORDER if n in names]
    order += [n for n in dict.fromkeys(names) if n not in order]
    print("| configuration | size | total | " + " | ".join(f"`{n}`" for n in order) + " |")
    print("|---|---|" + "--:|" * (1 + len(order)))
    for rows in zip(*(runs[size] for size in SIZES)):
        for size, r in zip(SIZES, rows):
            passes = {p["name"]: p["gpu_ms"]["median"] for p in r["passes"]}
            assert len(passes) == len(r["passes"]), "a pass ran twice"
            label = LABELS.get(r["configuration"], f"`{r['configuration']}`")
            cells = [label if size == SIZES[0] else "", size, ms(r["total_gpu_ms"]["median"])]
            cells += [ms(passes[n]) if n in passes else "" for n in order]
            print("| " + " | ".join(cells) + " |")


def base_row(configurations, i):
    """The row configuration i extends: the last earlier one whose options it starts with
    (`--method gtao --preset high` for `... --set depth_mips=fp32`), else the first."""
    words = configurations[i].split()
    for j in range(i - 1, -1, -1):
        if words[:len(configurations[j].split())] == configurations[j].split():
            return j
    return 0


def each_view_table(out, name):
    """The frame's median ms of each configuration on both views at both sizes, in brackets
    its ratio to the row it extends (base_row)."""
    views = [(scene, size) for scene, _ in SCENES for size in SIZES]
    runs = [load(out / f"{name}-{scene}-{size}.json") for scene, size in views]
    configurations = [r["configuration"] for r in runs[0]]
    print(f"`{name}`:\n")
    print("| configuration | " + " | ".join(f"{scene} {size}" for scene, size in views) + " |")
    print("|---|" + "--:|" * len(views))
    for i, configuration in enumerate(configurations):
        assert all(run[i]["configuration"] == configuration for run in runs), configuration
        base = base_row(configurations, i)
        cells = [f"`{configuration}`"]
        for run in runs:
            median = run[i]["total_gpu_ms"]["median"]
            cells.append(f"{ms(median)} ({median / run[base]['total_gpu_ms']['median']:.2f})")
        print("| " + " | ".join(cells) + " |")
    print()


def short_label(run):
    """A side-by-side configuration as the page names it: the peer's folder left out, and the
    way its shaders went (`xegtao-naga`, `xegtao-passthrough`) in its place."""
    words = run["configuration"].split()
    for i, word in enumerate(words):
        if word == "--peer":
            words[i + 1] = run["settings"]["method"]
    # bench marks a peer's run by its way to the GPU, which the method name now says.
    return " ".join(w for w in words if not (w.startswith("[") and w.endswith("]")))


def denoised(run):
    """Whether a run filters its AO: aokit's spatial filter, or the peer's denoiser."""
    settings = run["settings"]
    if "peer" in settings:
        return settings["denoise_passes"] > 0
    return settings["spatial"]["enabled"]


def side_by_side_table(out):
    """bench/gpu-run.sh's side-by-side runs: each configuration's frame and passes, and its
    ratio to XeGTAO through naga with the denoiser in the same state (on or off)."""
    for scene, heading in SCENES:
        for path in sorted(out.glob(f"side-by-side-{scene}-*.json")):
            size = path.stem.rsplit("-", 1)[1]
            runs = load(path)
            peers = {}
            for r in runs:
                if r["settings"]["method"] == "xegtao-naga":
                    peers.setdefault(denoised(r), r)
            print(f"#### {heading}, {size}\n")
            print("| configuration | frame ms | over XeGTAO | passes (ms) |")
            print("|---|--:|--:|---|")
            for r in runs:
                total = r["total_gpu_ms"]["median"]
                peer = peers.get(denoised(r))
                ratio = f"{total / peer['total_gpu_ms']['median']:.2f}" if peer else ""
                passes = ", ".join(f"`{p['name']}` {ms(p['gpu_ms']['median'])}"
                                   for p in r["passes"])
                label = f"`{short_label(r)}`"
                print(f"| {label} | {ms(total)} | {ratio} | {passes} |")
            print()


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    side_by_side_table(out)
    if (out / f"room-{SIZES[0]}-full.json").exists():
        method_tables(out)
    if (out / f"passes-sponza-atrium-{SIZES[0]}.json").exists():
        pass_table(out)
        print()
    for name in ("variants", "depth-mips", "sample-depth"):
        if (out / f"{name}-room-{SIZES[0]}.json").exists():
            each_view_table(out, name)


if __name__ == "__main__":
    main()
