#!/usr/bin/env bash
# Fills fuzz/corpus/TARGET with the seeds: the small files committed under fuzz/seeds/TARGET
# (made by fuzz/make_seeds.py, the EXRs and room.json by `aokit render --scene room --size 8x6
# --gbuffer`), and the first lines of scenes/sponza.obj with its camera sidecar. The corpus
# grows as the fuzzer finds new paths; it is not committed.
#
#   bash fuzz/seed.sh               copy the seeds (existing corpus files are kept)
#   bash fuzz/seed.sh --regenerate  first remake fuzz/seeds (python3, and the aokit CLI for
#                                   the EXRs)
set -euo pipefail
cd "$(dirname "$0")"
if [ "${1:-}" = "--regenerate" ]; then
    python3 make_seeds.py seeds
    out=$(mktemp -d)
    (cd .. && cargo run --quiet -p aokit-cli -- render --scene room --size 8x6 --gbuffer --out "$out" >/dev/null)
    mkdir -p seeds/exr
    cp "$out/depth.exr" "$out/normal.exr" "$out/ao.exr" seeds/exr/
    cp "$out/camera.json" seeds/camera_json/room.json
    rm -rf "$out"
fi
for dir in seeds/*/; do
    target=$(basename "$dir")
    mkdir -p "corpus/$target"
    cp "$dir"* "corpus/$target/"
done
# A piece of Sponza (12 MB in all): its first vertices, and faces over them, then its sidecar.
if [ -f ../scenes/sponza.obj ]; then
    {
        grep -m 200 '^v ' ../scenes/sponza.obj
        awk '/^f / {
            ok = 1
            for (i = 2; i <= NF; i++) { split($i, p, "/"); if (p[1] < 1 || p[1] > 200) ok = 0 }
            if (ok) { print; if (++n == 100) exit }
        }' ../scenes/sponza.obj
        printf '\0'
        cat ../scenes/sponza-cameras.json
    } > corpus/obj/sponza-piece.obj
fi
for dir in corpus/*/; do
    echo "$(basename "$dir"): $(find "$dir" -type f | wc -l) files"
done
