#!/usr/bin/env bash
# Splits the error of the horizon and slice methods at `high` three ways, as docs/notes/methods-investigations.md's
# "Where GTAO's error against HBAO comes from" and "Where VBAO's error against GTAO comes from"
# tables do:
#
#   high         the preset, one frame;
#   expectation  the preset's mean over the noise: 48 slices or directions, each with the
#                preset's steps and its own rotation and jitter, average what many frames would;
#   converged    many slices or directions and steps, the estimator without its sampling.
#
# Prints one markdown table per method (RMSE against the 512-ray references of
# bench/quality.sh, cached). A few minutes on 2 cores.
#
#   bash bench/error-split.sh [METHODS]    # METHODS: comma-separated, default gtao,hbao,vbao
set -euo pipefail
cd "$(dirname "$0")/.."
methods=${1:-gtao,hbao,vbao}
out=target/error-split
views=(--view room --view stairs --view thin
    --view scenes/sponza.obj@atrium --view scenes/sponza.obj@arcade
    --view scenes/sponza.obj@gallery --view scenes/sponza.obj@floor)

# The settings of each stage, per method. Converged GTAO drops what the presets tune against
# its sampling (the thickness heuristic, the radius multiplier, the power); converged HBAO
# runs at the true radius without angle bias; VBAO keeps its preset's thickness, which is the
# estimator's own model.
stage_settings() { # stage_settings METHOD STAGE
    case "$1:$2" in
        *:high) ;;
        gtao:expectation) echo "--set gtao.slice_count=48" ;;
        hbao:expectation) echo "--set hbao.direction_count=48" ;;
        vbao:expectation) echo "--set vbao.slice_count=48" ;;
        gtao:converged) echo "--set gtao.slice_count=32 --set gtao.steps_per_side=24 --set gtao.thickness=0 --set radius_multiplier=1 --set power=1" ;;
        hbao:converged) echo "--set hbao.direction_count=64 --set hbao.step_count=24 --set radius_multiplier=1 --set angle_bias=0" ;;
        vbao:converged) echo "--set vbao.slice_count=32 --set vbao.steps_per_side=24" ;;
        *) echo "error-split.sh: no stages for method $1" >&2; exit 2 ;;
    esac
}

cargo build --quiet --release -p aokit-cli
for method in ${methods//,/ }; do
    for stage in high expectation converged; do
        # shellcheck disable=SC2046 # the settings are separate words on purpose
        target/release/aokit compare "${views[@]}" --method "$method" --preset high \
            --size 480x270 --spp 512 --timing-frames 1 --set spatial.enabled=false \
            $(stage_settings "$method" "$stage") \
            --out "$out/$method-$stage" >/dev/null
    done
done

python3 - "$out" "$methods" <<'PY'
import json
import sys

out, methods = sys.argv[1], sys.argv[2].split(",")
stages = ["high", "expectation", "converged"]
for method in methods:
    rmse = {}
    for stage in stages:
        with open(f"{out}/{method}-{stage}/metrics.json") as f:
            for row in json.load(f)["results"]:
                rmse[(row["view"], stage)] = row["all"]["rmse"]
    views = list(dict.fromkeys(view for view, _ in rmse))
    print(f"\n`{method}` RMSE:\n")
    print("| view | " + " | ".join(stages) + " |")
    print("|---|" + "--:|" * len(stages))
    for view in views:
        print(f"| {view} | " + " | ".join(f"{rmse[(view, s)]:.4f}" for s in stages) + " |")
PY
