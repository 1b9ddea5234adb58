#!/usr/bin/env bash
# What the AO kernel's GPU time depends on: GTAO `high` (and HBAO `high` beside it) timed with
# `aokit bench` while one thing changes at a time: the screen radius clamp (how far samples
# reach, so how often they miss the texture cache), the split of the 18 samples into slices and
# steps, the step spacing, the noise kind and the slice normalisation. One interleaved
# `--compare` run per scene and size, each writing its JSON array to OUT/costs-SCENE-SIZE.json.
# docs/notes/performance-investigations.md's "What the kernel's time depends on" comes from
# these files. Meant for a GPU: on a software adapter the per-pass times mean nothing
# (docs/bench.md).
#
#   bash bench/kernel-costs.sh [AOKIT] [OUT]
#
# AOKIT defaults to target/release/aokit (build it with `cargo build --release -p aokit-cli`),
# OUT to target/performance.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=bench-common.sh
source bench/bench-common.sh "$@"
configurations=("--method gtao --preset high")
for px in 4 8 16 32 64 128; do
    configurations+=("--method gtao --preset high --set max_radius_px=$px")
done
configurations+=(
    "--method gtao --preset high --set gtao.slice_count=9 --set gtao.steps_per_side=1"
    "--method gtao --preset high --set gtao.slice_count=1 --set gtao.steps_per_side=9"
    "--method gtao --preset high --set step_power=2"
    "--method gtao --preset high --set gtao.normalize_slices=false"
    "--method gtao --preset high --set noise.kind=blue"
    "--method gtao --preset high --set noise.kind=bayer"
    "--method gtao --preset high --set noise.kind=white"
    "--method hbao --preset high"
    "--method hbao --preset high --set max_radius_px=16"
)
bench_each_view costs "${configurations[@]}"
