#!/usr/bin/env bash
# The run to make first whenever a GPU is lent (docs/performance.md): aokit's GTAO `high`, old
# and new kernel, raw and with each denoiser (and with the depth MIP chain), against XeGTAO High
# with and without its denoiser by naga and by passthrough SPIR-V, interleaved in one `aokit
# bench --compare` run per view and size: `room` and Sponza's atrium at 1920x1080 and
# 3840x2160. Then, time left, the per-pass set of bench/performance.sh, with the options whose
# cost only a GPU tells (docs/quality.md): `offscreen_samples=extend`,
# `offscreen_samples=unoccluded` (the default `clamp` should cost no more) and a 32 px guard
# band. Builds nothing: the GPU machine runs the release binary and the peer's SPIR-V
# compiled beforehand on a machine without a GPU:
#
#   cargo build --release -p aokit-cli
#   target/release/aokit peer compile xegtao=PATH/TO/XeGTAO --out target/peer/xegtao
#   bash bench/gpu-run.sh OUT [AOKIT] [PEER] [OLD]
#
# AOKIT defaults to target/release/aokit, PEER to target/peer/xegtao (without it the XeGTAO
# rows are left out). OLD, an earlier build (e.g. a release binary of the commit the last GPU
# run measured, kept as target/old/aokit), adds an A/B of the two builds' GTAO `high`, raw and
# with the default filter, at the first size (bench/ab.sh, three rounds): how much a change
# to the kernel measured only on a CPU moves it on the GPU. Every file goes to OUT: device.txt
# (adapter, driver, date), side-by-side-SCENE-SIZE.json, passes-sponza-atrium-SIZE.json,
# old-new-SCENE/summary.txt; then `python3 bench/performance_tables.py OUT` prints the tables.
# Takes about 3 minutes on an H100, 4 with OLD.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: bash bench/gpu-run.sh OUT [AOKIT] [PEER] [OLD]}
aokit=${2:-target/release/aokit}
peer=${3:-target/peer/xegtao}
old=${4:-}
# shellcheck source=bench-common.sh
source bench/bench-common.sh "$aokit" "$out"
{
    date -u +"date: %Y-%m-%d %H:%M UTC"
    "$aokit" --version
    if command -v nvidia-smi >/dev/null 2>&1; then
        nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
    fi
} >"$out/device.txt"
gtao="--method gtao --preset high"
thin_as_xegtao="--set depth_mips=fp32 --set depth_mip_offset=1.5 --set gtao.thickness=0.05"
configurations=(
    "$gtao --set slice_march=general"
    "$gtao"
    "$gtao --set slice_march=general --set spatial.enabled=true --set spatial.kind=bilateral"
    "$gtao --set spatial.enabled=true --set spatial.kind=bilateral"
    "$gtao --set spatial.enabled=true --set spatial.kind=edges"
    # The edges kind reading the AO and the depth from their two textures, as before the
    # kernel packed them into one (the default, the row above).
    "$gtao --set spatial.enabled=true --set spatial.kind=edges --set spatial.packed_input=false"
    "$gtao --set spatial.enabled=true --set spatial.kind=edges --set spatial.normal_power=0"
    # The normal weight by a log2 and an exp2, as before the power of two became squarings.
    "$gtao --set spatial.enabled=true --set spatial.kind=edges --set spatial.normal_power=16.0001"
    # What XeGTAO's way of seeing thin occluders thinner costs here: far samples from the depth
    # MIP chain, the settings under which GTAO `high` is below XeGTAO's error on every tuning
    # view (docs/performance.md, "Error").
    "$gtao --set spatial.enabled=true --set spatial.kind=edges $thin_as_xegtao"
    # Fewer samples at no more error than XeGTAO High's on most views (docs/performance.md).
    "--method gtao --preset medium --set spatial.enabled=true --set spatial.kind=edges"
)
# Each peer configuration runs twice where the driver takes the SPIR-V passed through: through
# naga and passed through (docs/peers.md). A driver that fails to compile it loses the device
# (NVIDIA 580 did), so a small run in a process of its own tries first; where it fails, the
# peer runs through naga alone and the reason goes to OUT/passthrough.txt.
if [ -d "$peer" ]; then
    shader=""
    if ! "$aokit" bench --scene room --size 64x64 --timing-frames 1 --warmup 0 --peer "xegtao=$peer" \
        --set peer.shader=passthrough >/dev/null 2>"$out/passthrough.txt"; then
        echo "gpu-run: XeGTAO passed through failed (see $out/passthrough.txt): naga only" >&2
        shader=" --set peer.shader=naga"
    else
        rm "$out/passthrough.txt"
    fi
    configurations+=(
        "--peer xegtao=$peer --preset high$shader"
        "--peer xegtao=$peer --preset high --set spatial.enabled=true$shader"
    )
else
    echo "gpu-run: no peer SPIR-V at $peer: timing aokit alone" >&2
fi
for scene in "${scenes[@]}"; do
    set_view "$scene"
    for size in "${sizes[@]}"; do
        bench_json "side-by-side-$scene-$size" "${view[@]}" --size "$size" \
            -- "${configurations[@]}"
    done
done
if [ -n "$old" ]; then
    for scene in "${scenes[@]}"; do
        set_view "$scene"
        mkdir -p "$out/old-new-$scene"
        bash bench/ab.sh -r 3 -o "$out/old-new-$scene" "$old" "$aokit" -- "${view[@]}" \
            --size "${sizes[0]}" --timing-frames "$frames" --warmup "$warmup" --compare \
            "$gtao --set spatial.enabled=false" "$gtao --set spatial.enabled=true" \
            >"$out/old-new-$scene/summary.txt"
        echo "wrote $out/old-new-$scene/summary.txt" >&2
    done
fi
passes=(
    ""
    "--set spatial.enabled=true --set spatial.kind=bilateral"
    "--set spatial.enabled=true --set spatial.kind=edges"
    "--set temporal.enabled=true"
    "--set spatial.enabled=true --set temporal.enabled=true"
    "--set resolution=half --set spatial.enabled=true --set temporal.enabled=true"
    "--set bent_normals=true"
    "--set offscreen_samples=extend"
    "--set offscreen_samples=unoccluded"
    "--guard-band 32"
)
set_view sponza-atrium
for size in "${sizes[@]}"; do
    bench_json "passes-sponza-atrium-$size" "${view[@]}" --size "$size" --method gtao \
        --preset high -- "${passes[@]}"
done
