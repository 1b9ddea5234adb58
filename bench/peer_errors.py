"""Error of aokit's GTAO `high` beside XeGTAO High's (docs/performance.md, "Side by side with
XeGTAO"): `aokit compare --peer` on the seven tuning views at 480x270 against the 512-ray
references, raw and denoised, aokit with its off-screen samples unoccluded (the default) and
with `offscreen_samples=clamp` (the texel XeGTAO's clamping sampler reads, at its height), and
with each of its spatial filters' kinds.

    python3 bench/peer_errors.py PEER [AOKIT]

PEER is an XeGTAO checkout or the SPIR-V `aokit peer compile` wrote (docs/peers.md); AOKIT the
binary, default target/release/aokit. Prints the markdown table: RMSE per view and the mean, in
bold where aokit's is at or below XeGTAO's in the same state (raw or denoised), and XeGTAO's
where it is at or below every aokit column beside it. About 5 minutes on 2 cores with the
references cached.
"""

import csv
import os
import subprocess
import sys
import tempfile

VIEWS = ["room", "stairs", "thin"] + [
    f"scenes/sponza.obj@{camera}" for camera in ("atrium", "arcade", "gallery", "floor")
]
RAW = ["--set", "spatial.enabled=false"]
CLAMP = ["--set", "offscreen_samples=clamp"]
# (column, the run's settings); each run also scores XeGTAO in the same state.
RUNS = [
    ("aokit raw", RAW),
    ("with `clamp`", RAW + CLAMP),
    ("aokit `bilateral`", ["--set", "spatial.enabled=true", "--set", "spatial.kind=bilateral"]),
    ("aokit `edges`", ["--set", "spatial.enabled=true", "--set", "spatial.kind=edges"]),
    ("with `clamp`", ["--set", "spatial.enabled=true", "--set", "spatial.kind=edges"] + CLAMP),
]


def compare(aokit, peer, settings, out):
    """RMSE by view of aokit's GTAO and of XeGTAO (through naga) in one compare run."""
    views = [arg for view in VIEWS for arg in ("--view", view)]
    subprocess.run(
        [aokit, "compare", *views, "--method", "gtao", "--preset", "high", "--peer",
         f"xegtao={peer}", "--set", "peer.shader=naga", *settings, "--size", "480x270",
         "--timing-frames", "0", "--out", out],
        check=True, stdout=subprocess.DEVNULL)
    rmse = {}
    with open(os.path.join(out, "metrics.csv")) as f:
        for row in csv.DictReader(f):
            rmse.setdefault(row["method"], {})[row["view"]] = float(row["rmse"])
    return rmse["gtao"], rmse["xegtao-naga"]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    peer = sys.argv[1]
    aokit = sys.argv[2] if len(sys.argv) == 3 else "target/release/aokit"
    columns, peers = [], {}
    with tempfile.TemporaryDirectory() as tmp:
        for i, (name, settings) in enumerate(RUNS):
            ours, theirs = compare(aokit, peer, settings, os.path.join(tmp, str(i)))
            columns.append((name, ours))
            peers["raw" if "spatial.enabled=false" in settings else "denoised"] = theirs
    views = list(columns[0][1])
    xe_raw, xe_denoised = ("XeGTAO raw", peers["raw"]), ("XeGTAO denoised", peers["denoised"])
    # The raw group, then the denoised one, each with XeGTAO last.
    groups = [columns[:2] + [xe_raw], columns[2:] + [xe_denoised]]

    def at(values, key):
        return values[key] if key else sum(values.values()) / len(values)

    def cells(group, key):
        ours = [at(values, key) for _, values in group[:-1]]
        theirs = at(group[-1][1], key)
        bold = [v <= theirs for v in ours] + [theirs <= min(ours)]
        return [f"**{v:.4f}**" if b else f"{v:.4f}" for v, b in zip(ours + [theirs], bold)]

    names = [name.strip() for group in groups for name, _ in group]
    print("| view | " + " | ".join(names) + " |")
    print("|---|" + "--:|" * len(names))
    for key in views + [None]:
        label = key.replace("sponza / ", "Sponza ").split(" / ")[0] if key else "mean"
        row = [cell for group in groups for cell in cells(group, key)]
        print(f"| {label} | " + " | ".join(row) + " |")

if __name__ == "__main__":
    main()
