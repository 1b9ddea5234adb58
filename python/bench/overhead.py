"""Overhead of `Context.ao_batch` over the Rust pipeline on the same frames.

    python python/bench/overhead.py [--size 320x180] [--frames 8] [--repeats 5] [--rounds 5]
                                    [--release | --python-only]

Renders a G-buffer of the stairs with the `aokit` CLI ($AOKIT_BIN, else cargo's target
directory), makes FRAMES frames of it (shifted a pixel each), times `ao_batch` on them, and
times the Rust example `rust_batch` (python/bench/rust_batch.rs: `ExternalAo` with the passes
replaced each frame, as `ao_batch` runs it) on the same frames, each after a warm-up, in
ROUNDS alternating rounds of REPEATS batches. Prints the medians and the ratio of each round.
Both run the default settings (GTAO high) on the same adapter; build both in the same profile
(`maturin develop` and `cargo run` are dev builds with optimised dependencies, `--release` for
both otherwise). `--python-only` times `ao_batch` alone, to compare two builds of the package.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import aokit

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "python" / "tests"))
from conftest import _find_cli  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--release", action="store_true", help="run the Rust side in release")
    parser.add_argument("--python-only", action="store_true", help="time ao_batch alone")
    args = parser.parse_args()
    cli = _find_cli()
    if cli is None:
        sys.exit("no aokit binary: build it with `cargo build -p aokit-cli` or set AOKIT_BIN")
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        subprocess.run(
            [cli, "render", "--scene", "stairs", "--size", args.size, "--gbuffer", "--out", str(d / "g")],
            check=True,
            capture_output=True,
        )
        depth = aokit.read_depth(d / "g" / "depth.exr")
        normals = aokit.read_normals(d / "g" / "normal.exr")
        camera = aokit.Camera.from_json(d / "g" / "camera.json")
        depths = np.stack([np.roll(depth, i, axis=1) for i in range(args.frames)])
        normal_frames = np.stack([np.roll(normals, i, axis=1) for i in range(args.frames)])
        (d / "camera.json").write_text((d / "g" / "camera.json").read_text())
        for i in range(args.frames):
            np.save(d / f"depth_{i}.npy", depths[i])
            np.save(d / f"normal_{i}.npy", normal_frames[i])

        ctx = aokit.Context()
        ctx.ao_batch(depths, normal_frames, cameras=camera)
        cargo = ["cargo", "run", "--quiet", "-p", "aokit-python", "--example", "rust_batch"]
        if args.release:
            cargo.insert(2, "--release")
        rust = [*cargo, "--", str(d), str(args.frames), str(args.repeats)]
        if not args.python_only:
            subprocess.run(rust, check=True, capture_output=True, cwd=REPO)  # build it first
        # Rounds alternate the two sides, so that a busy spell of a shared machine falls on
        # both; the medians are reported.
        python_times, rust_times = [], []
        for _ in range(args.rounds):
            started = time.perf_counter()
            for _ in range(args.repeats):
                ctx.ao_batch(depths, normal_frames, cameras=camera)
            python_times.append((time.perf_counter() - started) * 1e3 / args.repeats)
            if not args.python_only:
                out = subprocess.run(rust, check=True, capture_output=True, text=True, cwd=REPO)
                rust_times.append(float(out.stdout.strip().splitlines()[-1]))
    print(f"adapter: {ctx.adapter}")
    print(
        f"{args.frames} frames of {args.size}, GTAO high, median of {args.rounds} rounds "
        f"of {args.repeats} batches"
    )
    python_ms = statistics.median(python_times)
    print(f"ao_batch (Python): {python_ms:.1f} ms per batch ({python_ms / args.frames:.2f} ms per frame)")
    print(f"ao_batch per round: {', '.join(f'{t:.1f}' for t in python_times)} ms per batch")
    if args.python_only:
        return
    rust_ms = statistics.median(rust_times)
    ratios = sorted(p / r for p, r in zip(python_times, rust_times))
    print(f"ExternalAo (Rust): {rust_ms:.1f} ms per batch ({rust_ms / args.frames:.2f} ms per frame)")
    print(f"ExternalAo per round: {', '.join(f'{t:.1f}' for t in rust_times)} ms per batch")
    print(f"ratio of the medians: {python_ms / rust_ms:.3f}")
    print(f"ratio per round: {', '.join(f'{r:.3f}' for r in ratios)}")


if __name__ == "__main__":
    main()
