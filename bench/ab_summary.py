"""Summarises the runs of bench/ab.sh: per configuration, the wall time and each pass (and
with --compare the wall time over the first configuration's), each build's median over the
rounds of its per-run value, and its ratio to the first build.

    python3 bench/ab_summary.py OUT BUILD_A BUILD_B ...
"""
import glob
import json
import os
import statistics
import sys


def runs(out, build):
    """The bench results of one build, a list of configurations per round."""
    paths = sorted(glob.glob(os.path.join(out, f"b{build}-r*.json")))
    results = []
    for path in paths:
        with open(path) as file:
            data = json.load(file)
        results.append(data if isinstance(data, list) else [data])
    return results


def timings(configuration):
    """Name to median ms: the wall time, then each pass's GPU time; with --compare, also the
    run's ratio to its first configuration (of the total GPU time, or on a software adapter of
    the wall time), which drift of the machine between runs leaves alone."""
    times = {"wall": configuration["wall_ms"]["median"]}
    if "ratio_to_first" in configuration:
        basis = configuration["ratio_of"].removesuffix("_ms")
        times[f"{basis} / first config."] = configuration["ratio_to_first"]
    for p in configuration["passes"]:
        times[p["name"]] = p["gpu_ms"]["median"]
    return times


def main():
    out, builds = sys.argv[1], sys.argv[2:]
    per_build = [runs(out, b) for b in range(len(builds))]
    if not all(per_build):
        sys.exit(f"ab_summary: no runs of some build in {out}")
    for b, name in enumerate(builds):
        print(f"build {chr(ord('A') + b)}: {name} ({len(per_build[b])} rounds)")
    for c, configuration in enumerate(per_build[0][0]):
        label = configuration.get("configuration") or "(one configuration)"
        print(f"\n{label}")
        names = list(timings(configuration))
        header = "  ".join(f"{chr(ord('A') + b):>15}" for b in range(len(builds)))
        print(f"{'':28}{header}")
        for name in names:
            medians = []
            for rounds in per_build:
                values = [timings(r[c]).get(name) for r in rounds]
                values = [v for v in values if v is not None]
                medians.append(statistics.median(values) if values else None)
            cells = []
            for m in medians:
                if m is None or medians[0] is None:
                    cells.append(f"{'-':>15}")
                else:
                    cells.append(f"{m:8.4f} ({m / medians[0]:.3f})")
            print(f"{name:28}" + "  ".join(f"{cell:>15}" for cell in cells))


if __name__ == "__main__":
    main()
