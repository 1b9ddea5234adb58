#!/usr/bin/env bash
# Regenerates bench/data/tuning.json and the table of docs/tuning.md: `aokit tune` over the built-in
# scenes and the four Sponza cameras at 480x270 against 512-ray references (cached after the
# first run; about 10 minutes on 2 cores for raw AO, more with the spatial filter the presets
# now run). The presets (each method's rows in crates/aokit/src/methods/<method>.rs) are this
# table: crates/aokit-cli/tests/cli/tune.rs fails until a changed table is copied there.
#
#   bash bench/tuning.sh                  # every method and preset
#   bash bench/tuning.sh METHOD PRESET    # one of them again, where a full run does not fit
#
# One method at one preset goes to bench/data/tuning-retuned/METHOD-PRESET.json, which stands in
# for the full run's row, and its table to the end of docs/tuning.md; a full run drops them.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -eq 2 ]; then
    out=target/tuning-$1-$2
    rm -rf "$out"
    cargo run --quiet --release -p aokit-cli -- tune --method "$1" --preset "$2" --size 480x270 \
        --spp 512 --out "$out" >/dev/null
    mkdir -p bench/data/tuning-retuned
    cp "$out/tune.json" "bench/data/tuning-retuned/$1-$2.json"
    {
        if ! grep -q '^## Retuned since the table' docs/tuning.md; then
            printf '\n## Retuned since the table\n\n'
            echo "Presets searched again one at a time (\`bash bench/tuning.sh METHOD PRESET\`), each"
            echo "run's table as it printed; their rows stand in for the table's above."
        fi
        printf '\n### `%s` at `%s`\n\n' "$1" "$2"
        echo "\`bash bench/tuning.sh $1 $2\` on $(sed -n 's/.*"adapter": "\(.*\)",/\1/p' "$out/tune.json"), $(date -u '+%Y-%m-%d %H:%M UTC'):"
        echo
        cat "$out/tune.md"
    } >> docs/tuning.md
    echo "wrote bench/data/tuning-retuned/$1-$2.json and its table in docs/tuning.md"
    exit 0
fi
out=target/tuning
rm -rf "$out"
cargo run --quiet --release -p aokit-cli -- tune --size 480x270 --spp 512 --out "$out" >/dev/null
cp "$out/tune.json" bench/data/tuning.json
rm -rf bench/data/tuning-retuned
# docs/tuning.md keeps its text; everything from the "## The table" heading on is replaced.
head=$(sed '/^## The table/,$d' docs/tuning.md)
{
    printf '%s\n\n## The table\n\n' "$head"
    echo "\`bash bench/tuning.sh\` on $(sed -n 's/.*"adapter": "\(.*\)",/\1/p' bench/data/tuning.json), $(date -u '+%Y-%m-%d %H:%M UTC'):"
    echo
    cat "$out/tune.md"
} > docs/tuning.md.new
mv docs/tuning.md.new docs/tuning.md
echo "wrote docs/tuning.md and bench/data/tuning.json"
