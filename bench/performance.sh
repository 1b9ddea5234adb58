#!/usr/bin/env bash
# Times every method at every preset with `aokit bench`, at full and half resolution, at
# 1920x1080 and 3840x2160, on `room` and Sponza's atrium: one interleaved `--compare` run per
# scene, size and resolution, each writing its JSON array to OUT/SCENE-SIZE-RESOLUTION.json.
# Then GTAO `high` on the atrium with the denoisers, lower resolutions, bent normals and the
# normal sources, one run per size, to OUT/passes-sponza-atrium-SIZE.json. Last, the separable
# HBAO and SAO, and the depth MIP chain (below).
# docs/performance.md's tables come from these files. Meant for a GPU: on a software adapter
# the per-pass times mean nothing (docs/bench.md).
#
#   bash bench/performance.sh [AOKIT] [OUT]
#
# AOKIT defaults to target/release/aokit (build it with `cargo build --release -p aokit-cli`),
# OUT to target/performance.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=bench-common.sh
source bench/bench-common.sh "$@"
configurations=()
for method in ssao-crytek ssao hbao hbao-plus gtao vbao sao ue4-ssao msvo; do
    for preset in low medium high ultra; do
        configurations+=("--method $method --preset $preset")
    done
done
for preset in low medium high ultra; do
    configurations+=("--method hbao --preset $preset --set hbao.variant=separable")
done
for scene in "${scenes[@]}"; do
    set_view "$scene"
    for size in "${sizes[@]}"; do
        for resolution in full half; do
            bench_json "$scene-$size-$resolution" "${view[@]}" --size "$size" \
                --set resolution="$resolution" -- "${configurations[@]}"
        done
    done
done
passes=(
    ""
    "--set spatial.enabled=true"
    "--set spatial.enabled=true --set spatial.kind=bilateral"
    "--set temporal.enabled=true"
    "--set spatial.enabled=true --set temporal.enabled=true"
    "--set spatial.enabled=true --set spatial.kind=guided"
    "--set temporal.enabled=true --set temporal.filter_current=true"
    "--set resolution=half --set spatial.enabled=true --set temporal.enabled=true"
    "--set resolution=half --set spatial.enabled=true --set temporal.enabled=true --set filter_resolution=full"
    "--set resolution=quarter --set spatial.enabled=true --set temporal.enabled=true"
    "--set resolution=half --set downsample=checkerboard --set upsample=nearest-depth"
    "--set bent_normals=true"
    "--set normals.encoding=oct16"
    "--set normals.source=depth-5tap"
)
set_view sponza-atrium
for size in "${sizes[@]}"; do
    bench_json "passes-sponza-atrium-$size" "${view[@]}" --size "$size" --method gtao \
        --preset high -- "${passes[@]}"
done
# The separable HBAO against the per-pixel one at the same samples (four directions), the
# passes of SAO, UE4's SSAO and MSVO (the depth chain, and MSVO's per level), and VBAO with its
# occluders measured from the back faces (the back_faces prepass), to
# OUT/variants-SCENE-SIZE.json.
variants=(
    "--method hbao --preset high --set hbao.direction_count=4"
    "--method hbao --preset high --set hbao.variant=separable"
    "--method hbao --preset high --set hbao.direction_count=4 --set resolution=half"
    "--method hbao --preset high --set hbao.variant=separable --set resolution=half"
    "--method sao --preset high"
    "--method ue4-ssao --preset high"
    "--method msvo --preset high"
    "--method vbao --preset high"
    "--method vbao --preset high --set vbao.back_faces=true"
)
bench_each_view variants "${variants[@]}"
# The depth MIP chain (docs/depth-mips.md): each reading method at `high` with it off, at both
# precisions and at two offsets, to OUT/depth-mips-SCENE-SIZE.json.
depth_mips=()
for method in gtao vbao hbao ssao; do
    depth_mips+=(
        "--method $method --preset high"
        "--method $method --preset high --set depth_mips=fp32"
        "--method $method --preset high --set depth_mips=fp16"
        "--method $method --preset high --set depth_mips=fp16 --set depth_mip_offset=2"
    )
done
bench_each_view depth-mips "${depth_mips[@]}"
# How the slice methods' samples read depth (docs/methods.md#sample-depth): the default nearest
# texel against the interpolated read, to OUT/sample-depth-SCENE-SIZE.json.
sample_depth=()
for configuration in "--method gtao --preset high" "--method gtao --preset ultra" \
    "--method vbao --preset high" "--method hbao --preset high" "--method hbao-plus --preset high" \
    "--method gtao --preset high --set resolution=half"; do
    sample_depth+=("$configuration" "$configuration --set sample_depth=interpolated")
done
bench_each_view sample-depth "${sample_depth[@]}"
