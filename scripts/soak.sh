#!/usr/bin/env bash
# The long soak (docs/reliability.md): the scene renderer and the AO pipeline for 10,000 frames
# while methods, presets, resolutions, filters, sizes (down to 1x1), masks, bent normals and
# lighting modes change at random, every frame checked for NaN and wgpu errors, and process
# memory and wgpu's live resource counts compared after the warm-up and at the end. It is
# crates/aokit-scene/tests/gpu/soak.rs, which CI runs for 48 frames, built in release.
#
#   scripts/soak.sh                  # 10,000 frames, seed 29
#   scripts/soak.sh 2000 7           # 2,000 frames, seed 7
#   AOKIT_SOAK_CONFIGS=16 scripts/soak.sh  # 16 configurations a cycle, as CI has
set -euo pipefail
cd "$(dirname "$0")/.."
export AOKIT_SOAK_FRAMES=${1:-10000}
export AOKIT_SOAK_SEED=${2:-29}
# 250 random configurations, each run 40 times; the first 250 frames are the warm-up.
export AOKIT_SOAK_CONFIGS=${AOKIT_SOAK_CONFIGS:-250}
exec cargo test --release -p aokit-scene --test gpu soak:: -- --nocapture
