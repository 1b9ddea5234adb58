#!/usr/bin/env bash
# Regenerates the raw error tables and pictures of docs/quality.md, docs/methods.md and the
# method pages docs/methods/*.md, and their images: every method against the ray-traced
# reference on the built-in scenes and the four Sponza cameras, raw (`spatial.enabled=false`:
# these pages score the kernels, the presets without their denoiser). Each goes between its
# markers (scripts/splice.sh); the prose around them, which cites the numbers, is the pages'
# own and is read again by hand. Takes a few minutes on 2 cores (the references are cached;
# later runs only rerun the methods).
#
#   bash bench/quality.sh [METHODS]        # METHODS: comma-separated, default: all of them
#
# With METHODS the tables hold those methods alone: docs/quality.md's then lacks the others, so
# a run for the record names none.
set -euo pipefail
cd "$(dirname "$0")/.."
methods=${1:-all}
out=target/quality
rm -rf "$out"
compare() { # compare ARGS...: every view at every preset, at the tables' size and ray count
    cargo run --quiet --release -p aokit-cli -- compare \
        --view room --view stairs --view thin --view open \
        --view scenes/sponza.obj@atrium --view scenes/sponza.obj@arcade \
        --view scenes/sponza.obj@gallery --view scenes/sponza.obj@floor \
        --preset low,medium,high,ultra --size 480x270 --spp 512 --set spatial.enabled=false \
        "$@" >/dev/null
}
compare --method "$methods" --out "$out"

# shellcheck source=../scripts/splice.sh
source scripts/splice.sh
# docs/quality.md: the full tables, and the reference, GTAO and VBAO with their error maps for
# three views.
images=docs/images/quality
rm -rf "$images"
mkdir -p "$images"
shown=(stairs-side thin-front sponza-atrium)
for view in "${shown[@]}"; do
    cp "$out/images/$view-reference.png" "$images/"
    for method in gtao vbao; do
        cp "$out/images/$view-$method-high.png" "$out/images/$view-$method-high-error.png" "$images/"
    done
done
# The report's own title goes; its sections move one level down under the page's.
# Blank lines at either end go too: splice puts one either side.
tail -n +2 "$out/metrics.md" | sed 's/^## /### /' | sed '/./,$!d' \
    | sed -e :a -e '/^\n*$/{$d;N;ba' -e '}' >"$out/raw.md"
splice raw "$out/raw.md"
{
    echo "Error maps: blue = too dark (over-occludes), red = too bright, white = right, grey = no surface; saturated at +-0.25."
    for view in "${shown[@]}"; do
        echo
        echo "### $view"
        echo
        printf '| reference |'
        for f in "$images/$view"-*-high.png; do printf ' %s |' "$(basename "$f" .png | sed "s/^$view-//")"; done
        echo
        printf '|---|'
        for f in "$images/$view"-*-high.png; do printf -- '---|'; done
        echo
        printf '| ![](images/quality/%s-reference.png) |' "$view"
        for f in "$images/$view"-*-high.png; do printf ' ![](images/quality/%s) |' "$(basename "$f")"; done
        echo
        printf '| |'
        for f in "$images/$view"-*-high.png; do printf ' ![](images/quality/%s-error.png) |' "$(basename "$f" .png)"; done
        echo
    done
} >"$out/quality-pictures.md"
splice quality-pictures "$out/quality-pictures.md"

# docs/methods/METHOD.md: each method's error table at every preset, spliced between the page's
# markers; each method on every built-in scene and one Sponza camera (docs/images/methods/, shown
# by its page and, all together, by docs/methods.md between its markers).
pictures=docs/images/methods
rm -rf "$pictures"
mkdir -p "$pictures"
views=(room-front stairs-side thin-front open-above sponza-atrium)
method_list=$(grep '^## ' "$out/metrics-by-method.md" | cut -c4-)
{
    printf '| method |'
    for view in "${views[@]}"; do printf ' %s |' "$view"; done
    echo
    printf '|---|'
    for view in "${views[@]}"; do printf -- '---|'; done
    echo
    for method in $method_list; do
        printf '| `%s` |' "$method"
        for view in "${views[@]}"; do
            cp "$out/images/$view-$method-high.png" "$pictures/$view-$method.png"
            printf ' ![](images/methods/%s-%s.png) |' "$view" "$method"
        done
        echo
    done
} > "$out/pictures.md"
for method in $method_list; do
    awk -v m="## $method" '$0 == m {on = 1; next} /^## / {on = 0} on' \
        "$out/metrics-by-method.md" > "$out/errors-$method.md"
    splice "errors:$method" "$out/errors-$method.md"
done
splice pictures "$out/pictures.md"

variant() { # variant METHOD NAME IMAGES SUFFIX ARGS...: one more error table and pictures
    local method=$1 name=$2 images=$3 suffix=$4
    shift 4
    compare --method "$method" "$@" --out "$out/$name"
    awk -v m="## $method" '$0 == m {on = 1; next} /^## / {on = 0} on' \
        "$out/$name/metrics-by-method.md" > "$out/errors-$name.md"
    splice "errors:$name" "$out/errors-$name.md"
    mkdir -p "$images"
    for view in "${views[@]}"; do
        cp "$out/$name/images/$view-$method-high.png" "$images/$view$suffix.png"
    done
}
# docs/methods/hbao.md's separable HBAO: each variant with the same four directions and steps (the
# separable one reads no direction count), so both take 4 x step_count samples per pixel.
if [[ $methods == all || ,$methods, == *,hbao,* ]]; then
    for v in per-pixel separable; do
        variant hbao "hbao-$v" docs/images/separable-hbao "-$v" \
            --set hbao.variant=$v --set hbao.direction_count=4
    done
fi
# docs/methods/vbao.md's VBAO measuring its occluders from the back faces' depth: --set
# vbao.back_faces=true starts from its presets tuned with back faces.
if [[ $methods == all || ,$methods, == *,vbao,* ]]; then
    variant vbao vbao-back-faces docs/images/vbao-back-faces "" --set vbao.back_faces=true
fi
# docs/methods.md's sample depth: the slice methods with the interpolated read, beside their
# own tables (the default nearest read).
for method in gtao vbao hbao hbao-plus; do
    if [[ $methods == all || ,$methods, == *,$method,* ]]; then
        variant "$method" "$method-interpolated" docs/images/sample-depth "-$method-interpolated" \
            --set sample_depth=interpolated
    fi
done
echo "wrote the tables of docs/quality.md, docs/methods.md and docs/methods/*.md, $images/ and $pictures/"
