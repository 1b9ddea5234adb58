#!/usr/bin/env bash
# Regenerates docs/quality.md's "Ranking: error against cost" section and its chart,
# docs/images/ranking.svg: every method at every preset, with its default filtering, scored at
# 480x270 against 512-ray references on the held-out views (`compare --views held-out`) and the
# tuning views (`--views tuning`), set against the H200 GPU times at 1920x1080 in
# bench/data/h200-2026-11-27 (bench/ranking.py says how the cost is made). Names the Pareto
# front and the most accurate held-out pair at the default preset's cost. The held-out scenes
# come from `bash scripts/fetch-scenes.sh`; with the references cached (bench/heldout-quality.sh
# traces them) the scoring takes a few minutes on 2 cores.
#
#   bash bench/ranking.sh [AOKIT]    # AOKIT: default target/release/aokit, built here
set -euo pipefail
cd "$(dirname "$0")/.."
aokit=${1:-target/release/aokit}
if [ $# -eq 0 ]; then
    cargo build --quiet --release -p aokit-cli
fi
out=target/ranking
rm -rf "$out"
for set in held-out tuning; do
    "$aokit" compare --method all --preset low,medium,high,ultra --size 480x270 --spp 512 \
        --timing-frames 0 --views "$set" --out "$out/$set" >/dev/null
done
python3 bench/ranking.py "$out" "$aokit" bench/data/h200-2026-11-27
