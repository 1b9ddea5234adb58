#!/usr/bin/env bash
# Regenerates bench/data/tuning.json and the table of docs/tuning.md: `aokit tune` over the built-in
# scenes and the four Sponza cameras at 480x270 against 512-ray references (cached after the
# first run; about 10 minutes on 2 cores). The presets (crates/aokit/src/presets.rs) are this
# table: crates/aokit-cli/tests/cli/tune.rs fails until a changed table is copied there.
#
#   bash bench/tuning.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/tuning
rm -rf "$out"
cargo run --quiet --release -p aokit-cli -- tune --size 480x270 --spp 512 --out "$out" >/dev/null
cp "$out/tune.json" bench/data/tuning.json
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
