#!/usr/bin/env bash
# Regenerates the README's and docs/scenes.md's pictures (docs/images/*-ao.png, *-lit.png) with
# the default method and settings (GTAO `high`, spatial filter on): every built-in scene at 640x360 and every Sponza camera at
# 800x450.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --quiet --release -p aokit-cli
aokit=target/release/aokit
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
shot() { # shot NAME ARGS...
    local name=$1
    shift
    "$aokit" render "$@" --out "$tmp/$name" >/dev/null
    cp "$tmp/$name/ao.png" "docs/images/$name-ao.png"
    cp "$tmp/$name/lit.png" "docs/images/$name-lit.png"
}
for scene in room stairs thin open; do
    shot "$scene" --scene "$scene" --size 640x360
done
for camera in atrium arcade gallery floor; do
    shot "sponza-$camera" --scene scenes/sponza.obj --camera "$camera" --size 800x450
done
# The README's first picture: the atrium as the defaults render it (denoised), and lit without
# AO (intensity 0 leaves AO 1 everywhere) on the left half against lit with it on the right.
atrium=(--scene scenes/sponza.obj --camera atrium --size 800x450)
"$aokit" render "${atrium[@]}" --out "$tmp/denoised" >/dev/null
"$aokit" render "${atrium[@]}" --set intensity=0 --out "$tmp/no-ao" >/dev/null
cp "$tmp/denoised/ao.png" docs/images/sponza-atrium-ao-denoised.png
python3 bench/split_image.py "$tmp/no-ao/lit.png" "$tmp/denoised/lit.png" \
    docs/images/sponza-atrium-lit-split.png
echo "wrote docs/images/*-ao.png, *-lit.png, sponza-atrium-ao-denoised.png and -lit-split.png"
