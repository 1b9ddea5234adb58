#!/usr/bin/env bash
# Regenerates docs/composite.md's multi-bounce pictures: the plot of GTAO's fit against the closed
# form (docs/images/multi-bounce.svg) and the room's lit.png with each form
# (docs/images/multi-bounce/room-lit-{none,gtao,closed-form}.png).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo run --quiet -p aokit --example multi_bounce_plot -- docs/images/multi-bounce.svg
cargo build --quiet --release -p aokit-cli
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p docs/images/multi-bounce
for form in none gtao closed-form; do
    target/release/aokit render --scene room --size 640x360 --multi-bounce "$form" \
        --out "$tmp/$form" >/dev/null
    cp "$tmp/$form/lit.png" "docs/images/multi-bounce/room-lit-$form.png"
done
echo "wrote docs/images/multi-bounce.svg and docs/images/multi-bounce/room-lit-*.png"
