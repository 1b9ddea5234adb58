#!/usr/bin/env bash
# Regenerates bench/data/tuning.json and the table of docs/tuning.md: `aokit tune` over the tuning
# views (the built-in scenes and the four Sponza cameras) at 480x270 against 512-ray references
# (cached after the first run). The presets (each method's rows in
# crates/aokit/src/methods/<method>.rs) are this table: crates/aokit-cli/tests/cli/tune.rs fails
# until a changed table is copied there.
#
#   bash bench/tuning.sh                  # every method and preset, here
#   bash bench/tuning.sh METHOD PRESET    # one of them again, where a full run does not fit
#   bash bench/tuning.sh --into DIR       # every method and preset, the run alone, into DIR
#   bash bench/tuning.sh --from DIR       # install a run made with --into, here
#
# A full run took 21 minutes on 2 cores (lavapipe, 2026-11-28), a method at one preset one to
# three. --into runs the search elsewhere, e.g. on a lent GPU: it builds nothing (AOKIT names the binary, default
# target/release/aokit) and reads the references from AOKIT_CACHE, so that with the binary and
# a copy of the cache carried over, the GPU spends its time searching:
#
#   cargo build --release -p aokit-cli
#   aokit compare --views tuning --method gtao --preset high --spp 512 --timing-frames 0   # traces what is missing
#   cp -r ~/.cache/aokit target/tuning-cache
#   # on the GPU machine, carrying target/release/aokit and target/tuning-cache:
#   AOKIT_CACHE=target/tuning-cache bash bench/tuning.sh --into $OUT/tuning
#   # back here:
#   bash bench/tuning.sh --from OUT/tuning
#
# One method at one preset goes to bench/data/tuning-retuned/METHOD-PRESET.json, which stands in
# for the full run's row, and its table to the end of docs/tuning.md; a full run drops them.
set -euo pipefail
cd "$(dirname "$0")/.."
tune_args=(--size 480x270 --spp 512)

# The adapter a run's tune.json names.
adapter() {
    sed -n 's/.*"adapter": "\(.*\)",/\1/p' "$1/tune.json"
}

# Installs the full run in $1: bench/data/tuning.json, and docs/tuning.md's table; docs/tuning.md
# keeps its text, everything from the "## The table" heading on is replaced.
install() {
    cp "$1/tune.json" bench/data/tuning.json
    rm -rf bench/data/tuning-retuned
    local head
    head=$(sed '/^## The table/,$d' docs/tuning.md)
    {
        printf '%s\n\n## The table\n\n' "$head"
        echo "\`bash bench/tuning.sh\` on $(adapter "$1"), $(date -u -r "$1/tune.json" '+%Y-%m-%d %H:%M UTC'):"
        echo
        cat "$1/tune.md"
        printf '\n### Per view at `high`\n\n'
        echo "Filtered as the presets run; \`tune.json\` has every preset (\`python3 bench/tuning_views.py\`):"
        echo
        python3 bench/tuning_views.py "$1/tune.json"
    } >docs/tuning.md.new
    mv docs/tuning.md.new docs/tuning.md
    echo "wrote docs/tuning.md and bench/data/tuning.json"
}

case "${1:-}" in
--into)
    out=${2:?usage: bash bench/tuning.sh --into DIR}
    "${AOKIT:-target/release/aokit}" tune "${tune_args[@]}" --out "$out" >/dev/null
    echo "wrote $out/tune.json; install it with: bash bench/tuning.sh --from $out"
    ;;
--from)
    install "${2:?usage: bash bench/tuning.sh --from DIR}"
    ;;
"")
    out=target/tuning
    rm -rf "$out"
    cargo run --quiet --release -p aokit-cli -- tune "${tune_args[@]}" --out "$out" >/dev/null
    install "$out"
    ;;
*)
    method=$1
    preset=${2:?usage: bash bench/tuning.sh METHOD PRESET}
    out=target/tuning-$method-$preset
    rm -rf "$out"
    cargo run --quiet --release -p aokit-cli -- tune --method "$method" --preset "$preset" \
        "${tune_args[@]}" --out "$out" >/dev/null
    mkdir -p bench/data/tuning-retuned
    cp "$out/tune.json" "bench/data/tuning-retuned/$method-$preset.json"
    {
        if ! grep -q '^## Retuned since the table' docs/tuning.md; then
            printf '\n## Retuned since the table\n\n'
            echo "Presets searched again one at a time (\`bash bench/tuning.sh METHOD PRESET\`), each"
            echo "run's table as it printed; their rows stand in for the table's above."
        fi
        printf '\n### `%s` at `%s`\n\n' "$method" "$preset"
        echo "\`bash bench/tuning.sh $method $preset\` on $(adapter "$out"), $(date -u '+%Y-%m-%d %H:%M UTC'):"
        echo
        cat "$out/tune.md"
    } >>docs/tuning.md
    echo "wrote bench/data/tuning-retuned/$method-$preset.json and its table in docs/tuning.md"
    ;;
esac
