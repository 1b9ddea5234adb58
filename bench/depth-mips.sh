#!/usr/bin/env bash
# The error the depth MIP chain (`depth_mips`, docs/depth-mips.md) costs: RMSE against the
# reference of every method that reads it, at `high`, over the tuning views, with the chain
# off, at each precision and at several offsets. Prints docs/depth-mips.md's tables.
#
# The chain changes only samples at least 2^(offset + 1) pixels out, so it is measured at
# 960x540, where Sponza's radius spans far more pixels than at 480x270. The references (128
# rays per pixel) are cached; the first run traces them (a few minutes on 2 cores).
#
#   bash bench/depth-mips.sh [SIZE]    # default 960x540
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-960x540}
out=target/depth-mips
methods=gtao,vbao,hbao,hbao-plus,ssao,ssao-crytek
views=(--view room --view stairs --view thin
    --view scenes/sponza.obj@atrium --view scenes/sponza.obj@arcade
    --view scenes/sponza.obj@gallery --view scenes/sponza.obj@floor)
variants=(off fp32-3 fp16-3 fp32-2 fp32-1)

cargo build --quiet --release -p aokit-cli
for variant in "${variants[@]}"; do
    settings=()
    if [ "$variant" != off ]; then
        settings=(--set "depth_mips=${variant%-*}" --set "depth_mip_offset=${variant#*-}")
    fi
    target/release/aokit compare "${views[@]}" --method "$methods" --preset high \
        --size "$size" --spp 128 --timing-frames 1 --set spatial.enabled=false "${settings[@]}" \
        --out "$out/$variant" >/dev/null
done

python3 - "$out" "${variants[@]}" <<'PY'
import json
import sys

out, variants = sys.argv[1], sys.argv[2:]
rmse = {}
for variant in variants:
    with open(f"{out}/{variant}/metrics.json") as f:
        for row in json.load(f)["results"]:
            rmse[(row["view"], row["method"], variant)] = row["all"]["rmse"]
rows = list(dict.fromkeys((view, method) for view, method, _ in rmse))
labels = {"off": "off"} | {
    v: f"{v.split('-')[0]}, offset {v.split('-')[1]}" for v in variants if v != "off"
}
print("| view | method | " + " | ".join(labels[v] for v in variants) + " |")
print("|:--|:--|" + "--:|" * len(variants))
for view, method in rows:
    cells = " | ".join(f"{rmse[(view, method, v)]:.4f}" for v in variants)
    print(f"| {view} | {method} | {cells} |")


def mean(keep):
    return " | ".join(
        f"{sum(rmse[(vw, m, v)] for vw, m in rows if keep(vw, m)) / sum(1 for vw, m in rows if keep(vw, m)):.4f}"
        for v in variants
    )


print(f"| **mean of {len(rows)}** | | {mean(lambda vw, m: True)} |")
print(f"| mean without thin | | {mean(lambda vw, m: not vw.startswith('thin'))} |")
for method in dict.fromkeys(m for _, m in rows):
    print(f"| mean | {method} | {mean(lambda vw, m: m == method)} |")
PY
