#!/usr/bin/env python3
"""Ranks every method and preset by error against cost, for docs/quality.md's "Ranking: error
against cost" section (bench/ranking.sh runs it).

    python3 bench/ranking.py OUT AOKIT GPU_DATA

OUT holds `aokit compare --views tuning` and `--views held-out` at every preset
(OUT/tuning/metrics.csv, OUT/held-out/metrics.csv); AOKIT is the binary that scored them (its
`settings` command gives today's presets); GPU_DATA is a folder of bench/performance.sh and
bench/gpu-run.sh output (bench/data/h200-2026-11-27). The cost of a method at a preset is its
GPU time at 1920x1080 with the default filtering, the mean over `room` and Sponza's atrium:
the frame's time with the filter off (performance/SCENE-1920x1080-full.json) plus the edge
filter's pass (after-merge/side-by-side-SCENE-1920x1080.json), a pass over the AO texture
whose work does not depend on the method. Writes docs/images/ranking.svg and splices the table
between docs/quality.md's <!-- ranking --> markers. Standard library only.
"""
import csv
import json
import math
import re
import subprocess
import sys
from pathlib import Path

SCENES = [("room", "`room`"), ("sponza-atrium", "atrium")]
SIZE = "1920x1080"
SETS = ["held-out", "tuning"]
# Keys whose value in the GPU data may differ from today's without changing what was timed:
# the scene's radius, and the filters (the data's frames ran unfiltered; the edge filter's
# own pass is added).
UNTIMED = re.compile(r"^(radius|spatial\..*|temporal\..*)$")
# The settings group each method reads besides the shared keys (hbao-plus runs on hbao's).
GROUP = {"hbao-plus": "hbao"}
# Shared keys that are some methods' knob alone: every other method's preset carries the value
# of the method that owns it (AoSettings::preset), unread.
KNOBS = {"bias", "angle_bias"}
COLORS = {"ssao-crytek": "#7f7f7f", "ssao": "#bcbd22", "hbao": "#1f77b4",
          "hbao-plus": "#17becf", "gtao": "#d62728", "vbao": "#ff7f0e", "sao": "#8c564b",
          "ue4-ssao": "#e377c2", "msvo": "#2ca02c"}


def mean_rmse(path):
    """Each (method, preset)'s RMSE, the mean over the views of metrics.csv."""
    per = {}
    for row in csv.DictReader(open(path)):
        per.setdefault((row["method"], row["preset"]), []).append(float(row["rmse"]))
    return {key: sum(v) / len(v) for key, v in per.items()}


def runs(path):
    return {r["configuration"]: r for r in json.load(open(path))}


def flatten(settings, prefix=""):
    flat = {}
    for key, value in settings.items():
        if isinstance(value, dict):
            flat.update(flatten(value, f"{prefix}{key}."))
        else:
            flat[prefix + key] = value
    return flat


def today(aokit, method, preset):
    """`aokit settings --method M --preset P`'s value column, by key, and the default method
    and preset named in its footnote."""
    text = subprocess.run([aokit, "settings", "--method", method, "--preset", preset],
                          check=True, capture_output=True, text=True).stdout
    lines = text.splitlines()
    start, end = lines[0].index("value"), lines[0].index("range")
    values = {line.split()[0]: line[start:end].replace("*", "").strip()
              for line in lines[1:] if line and not line.startswith("*")}
    default = re.search(r"default \(`([^`]+)` at `([^`]+)`\)", text)
    if not default:
        sys.exit("ranking: `aokit settings` no longer names the default method and preset")
    return values, default.groups()


def same(timed, now):
    if isinstance(timed, bool):
        return str(timed).lower() == now
    if isinstance(timed, (int, float)):
        return math.isclose(float(timed), float(now), rel_tol=1e-6)
    return str(timed) == now


def knobs():
    """Each tuned method's knob, as `aokit tune`'s table names it; the methods it does not tune
    keep their published knobs."""
    rows = json.load(open("bench/data/tuning.json"))["results"]
    return {r["method"]: r["knob"] for r in rows}


KNOB_OF = knobs()


def drift(method, timed, now):
    """The settings `method` reads that were timed with another value than today's, as
    `key` timed (now): the shared keys (of the knobs, its own) and the method's own group."""
    group = GROUP.get(method, method).replace("-", "_") + "."
    own = KNOB_OF.get(method)
    return [f"`{k}` {v} (now {now[k]})" for k, v in sorted(flatten(timed).items())
            if ("." not in k or k.startswith(group)) and not UNTIMED.match(k)
            and (k not in KNOBS or k == own) and k in now and not same(v, now[k])]


def pareto(points):
    """The points no other is at most as dear as and more accurate than, cheapest first."""
    front, best = [], math.inf
    for p in sorted(points, key=lambda p: (p["cost"], p["held-out"])):
        if p["held-out"] < best:
            front.append(p)
            best = p["held-out"]
    return front


def pick(points, budget, cost):
    """The most accurate held-out point whose cost (a function of the point) is within budget."""
    return min((p for p in points if cost(p) <= budget + 1e-12), key=lambda p: p["held-out"])


def svg(points, front, default, budget, path):
    """The chart: held-out RMSE against the mean GPU time, both on log scales (the cheap
    presets crowd together on a linear one)."""
    width, height, left, right, top, bottom = 900, 560, 70, 150, 40, 55
    xlo, xhi, ylo, yhi = 0.09, 1.0, 0.05, 0.4
    if not all(xlo <= p["cost"] <= xhi and ylo <= p["held-out"] <= yhi for p in points):
        sys.exit("ranking: a point falls outside the chart's axes; widen them")
    x = lambda ms: left + (width - left - right) * math.log(ms / xlo) / math.log(xhi / xlo)
    y = lambda e: top + (height - top - bottom) * math.log(yhi / e) / math.log(yhi / ylo)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>']
    for ms in [0.1, 0.12, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0]:
        out.append(f'<line x1="{x(ms):.1f}" y1="{top}" x2="{x(ms):.1f}" y2="{height - bottom}" '
                   'stroke="#e4e4e4"/>')
        out.append(f'<text x="{x(ms):.1f}" y="{height - bottom + 16}" '
                   f'text-anchor="middle">{ms:g}</text>')
    for e in [0.05, 0.06, 0.07, 0.08, 0.1, 0.15, 0.2, 0.3, 0.4]:
        out.append(f'<line x1="{left}" y1="{y(e):.1f}" x2="{width - right}" y2="{y(e):.1f}" '
                   'stroke="#e4e4e4"/>')
        out.append(f'<text x="{left - 6}" y="{y(e) + 4:.1f}" text-anchor="end">{e:g}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 15}" text-anchor="middle">'
               f'GPU ms at {SIZE}, default filtering (H200, mean of room and Sponza atrium; log scale)'
               '</text>')
    out.append(f'<text transform="translate(18 {(top + height - bottom) / 2}) rotate(-90)" '
               'text-anchor="middle">held-out RMSE (mean of 10 views, log scale)</text>')
    out.append(f'<text x="{left}" y="24" font-size="14">Error against cost: every method at '
               'low, medium, high, ultra (L M H U)</text>')
    out.append(f'<line x1="{x(budget):.1f}" y1="{top}" x2="{x(budget):.1f}" '
               f'y2="{height - bottom}" stroke="#555" stroke-dasharray="4 3"/>')
    out.append(f'<text x="{x(budget) + 4:.1f}" y="{top + 12}" fill="#555">default preset\'s '
               'cost</text>')
    for method, color in COLORS.items():
        line = sorted((p for p in points if p["method"] == method), key=lambda p: p["cost"])
        coords = " ".join(f'{x(p["cost"]):.1f},{y(p["held-out"]):.1f}' for p in line)
        out.append(f'<polyline points="{coords}" fill="none" stroke="{color}" '
                   'stroke-opacity="0.5"/>')
        for p in line:
            out.append(f'<circle cx="{x(p["cost"]):.1f}" cy="{y(p["held-out"]):.1f}" r="4" '
                       f'fill="{color}"/>')
            out.append(f'<text x="{x(p["cost"]) + 5:.1f}" y="{y(p["held-out"]) - 5:.1f}" '
                       f'font-size="10" fill="{color}">{p["preset"][0].upper()}</text>')
    steps = []
    for a, b in zip(front, front[1:]):
        steps += [(a["cost"], a["held-out"]), (b["cost"], a["held-out"])]
    steps.append((front[-1]["cost"], front[-1]["held-out"]))
    coords = " ".join(f"{x(c):.1f},{y(e):.1f}" for c, e in steps)
    out.append(f'<polyline points="{coords}" fill="none" stroke="black" stroke-width="1.5"/>')
    for p in front:
        out.append(f'<circle cx="{x(p["cost"]):.1f}" cy="{y(p["held-out"]):.1f}" r="7" '
                   'fill="none" stroke="black" stroke-width="1.5"/>')
    out.append(f'<rect x="{x(default["cost"]) - 9:.1f}" y="{y(default["held-out"]) - 9:.1f}" '
               'width="18" height="18" fill="none" stroke="black" stroke-dasharray="2 2"/>')
    lx = width - right + 20
    for i, (method, color) in enumerate(COLORS.items()):
        ly = top + 10 + 18 * i
        out.append(f'<circle cx="{lx}" cy="{ly}" r="4" fill="{color}"/>')
        out.append(f'<text x="{lx + 10}" y="{ly + 4}">{method}</text>')
    ly = top + 10 + 18 * len(COLORS) + 10
    out.append(f'<circle cx="{lx}" cy="{ly}" r="7" fill="none" stroke="black"/>')
    out.append(f'<text x="{lx + 12}" y="{ly + 4}">Pareto front</text>')
    out.append(f'<rect x="{lx - 9}" y="{ly + 9}" width="18" height="18" fill="none" '
               'stroke="black" stroke-dasharray="2 2"/>')
    out.append(f'<text x="{lx + 12}" y="{ly + 22}">default</text>')
    out.append("</svg>")
    path.write_text("\n".join(out) + "\n")


def main():
    out, aokit, data = Path(sys.argv[1]), sys.argv[2], Path(sys.argv[3])
    rmse = {s: mean_rmse(out / s / "metrics.csv") for s in SETS}
    timed = {scene: runs(data / "performance" / f"{scene}-{SIZE}-full.json")
             for scene, _ in SCENES}
    filtered = "--method gtao --preset high --set spatial.enabled=true"
    edge = {}
    for scene, _ in SCENES:
        passes = runs(data / "after-merge" / f"side-by-side-{scene}-{SIZE}.json")[filtered]
        edge[scene] = next(p["gpu_ms"]["median"] for p in passes["passes"]
                           if p["name"] == "edge_filter")
    points = []
    for method, preset in rmse["held-out"]:
        configuration = f"--method {method} --preset {preset}"
        now, default_key = today(aokit, method, preset)
        p = {"method": method, "preset": preset,
             **{s: rmse[s][method, preset] for s in SETS},
             **{scene: timed[scene][configuration]["total_gpu_ms"]["median"] + edge[scene]
                for scene, _ in SCENES},
             "drift": drift(method, timed[SCENES[0][0]][configuration]["settings"], now)}
        p["cost"] = sum(p[scene] for scene, _ in SCENES) / len(SCENES)
        points.append(p)
    front = pareto(points)
    default = next(p for p in points if (p["method"], p["preset"]) == default_key)
    chosen = pick(points, default["cost"], lambda p: p["cost"])
    by_scene = {scene: pick(points, default[scene], lambda p, s=scene: p[s])
                for scene, _ in SCENES}
    svg(points, front, default, default["cost"], Path("docs/images/ranking.svg"))

    version = subprocess.run([aokit, "--version"], check=True, capture_output=True,
                             text=True).stdout.strip()
    name = lambda p: f"`{p['method']}` {p['preset']}"
    lines = [
        f"`bash bench/ranking.sh` ({version}): `aokit compare --method all --preset "
        "low,medium,high,ultra --size 480x270 --spp 512 --timing-frames 0` with `--views "
        "held-out` and `--views tuning` (RMSE, the mean over each set's views, with each "
        "preset's default filtering), against the H200 times of "
        f"[{data}](../{data}) at {SIZE}: the frame with the filter off "
        "(`performance/`, [performance.md](performance.md#every-method-and-preset)) plus the "
        "`edges` filter's pass, which does not depend on the method (`after-merge/`, "
        f"{', '.join(f'{edge[s]:.3f} ms on {label}' for s, label in SCENES)}). The cost is the "
        "mean of the two views; sorted by it.",
        "",
        "![Held-out RMSE against GPU time: one point per method and preset, the Pareto front "
        "circled, the default boxed](images/ranking.svg)",
        "",
        "| method | preset | GPU ms, " + " | ".join(label for _, label in SCENES)
        + " | mean | held-out RMSE | tuning RMSE | on the front |",
        "|---|---|" + "--:|" * (len(SCENES) + 3) + "---|",
    ]
    for p in sorted(points, key=lambda p: (p["cost"], p["held-out"])):
        mark = "**yes**" if p in front else ""
        cost = f"**{p['cost']:.3f}**" if p is default else f"{p['cost']:.3f}"
        times = " | ".join(f"{p[scene]:.3f}" for scene, _ in SCENES)
        lines.append(f"| `{p['method']}` | {p['preset']} | {times} | {cost} | "
                     f"{p['held-out']:.4f} | {p['tuning']:.4f} | {mark} |")
    lines += ["", f"The Pareto front, cheapest first: {', '.join(name(p) for p in front)}."]
    cheaper = [p for p in points if p["cost"] <= default["cost"] and p is not chosen]
    runner = min(cheaper, key=lambda p: p["held-out"])
    lines += [
        "",
        f"**The default method.** `AoSettings::default()` is {name(default)}, "
        f"{default['cost']:.3f} ms. Of the {len(cheaper) + 1} method and preset pairs that cost "
        f"no more, {name(chosen)} has the lowest held-out error ({chosen['held-out']:.4f}; "
        f"next {name(runner)}, {runner['held-out']:.4f} at {runner['cost']:.3f} ms). "
        + ("The measurement keeps the default method. "
           if chosen["method"] == default["method"]
           else f"**The measurement picks `{chosen['method']}`, not the default "
                f"`{default['method']}`.** ")
        + (("No pair at any cost is more accurate on the held-out views. "
            if chosen is min(points, key=lambda p: p["held-out"])
            else "A larger budget would pick "
            + name(min(points, key=lambda p: p["held-out"])) + ". "))
        + "On each view's time alone the pick is "
        + "; ".join(f"{name(by_scene[s])} ({label})" for s, label in SCENES) + ".",
    ]
    drifted = [p for p in points if p["drift"]]
    if drifted:
        lines += ["", "Presets retuned after the H200 run, timed with other values: "
                  + "; ".join(f"{name(p)}: {', '.join(p['drift'])}" for p in drifted) + "."]
    block = "\n".join(lines)
    page = Path("docs/quality.md")
    text, n = re.subn(r"(<!-- ranking -->\n).*?(<!-- /ranking -->)",
                      lambda m: f"{m[1]}\n{block}\n\n{m[2]}", page.read_text(), flags=re.S)
    if n != 1:
        sys.exit("ranking: no <!-- ranking --> markers in docs/quality.md")
    page.write_text(text)
    print("wrote docs/images/ranking.svg and the table between docs/quality.md's "
          "<!-- ranking --> markers")


if __name__ == "__main__":
    main()
