#!/usr/bin/env bash
# Regenerates the README's and docs/scenes.md's pictures (docs/images/*-ao.png, *-lit.png) with
# the default method and settings: every built-in scene at 640x360 and every Sponza camera at
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
echo "wrote docs/images/*-ao.png and *-lit.png"
