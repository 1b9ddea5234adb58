#!/usr/bin/env bash
# Times builds against each other: the same `aokit bench --json` run with each binary in turn,
# for several rounds, so that drift of the machine (clocks, heat, neighbours) falls on every
# build alike. Each run's JSON goes to OUT/bBUILD-rROUND.json; then bench/ab_summary.py prints
# per configuration the wall time and every pass, each build's median over the rounds of its
# per-run median, and its ratio to the first build. The way optimisations are measured before
# they stay (docs/performance.md).
#
#   bash bench/ab.sh [-r ROUNDS] [-o OUT] AOKIT_A AOKIT_B [AOKIT_C ...] -- BENCH_OPTION...
#
# ROUNDS defaults to 3, OUT to target/ab. For example, a change to the temporal filter against
# the build before it, on a GPU:
#
#   bash bench/ab.sh target/ab/before target/release/aokit -- --scene scenes/sponza.obj \
#       --camera atrium --size 1920x1080 --compare \
#       "--set spatial.enabled=true --set temporal.enabled=true" \
#       "--set spatial.enabled=false --set temporal.enabled=true"
#
# On a software adapter only the wall times mean anything (docs/bench.md).
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=3
out=target/ab
while getopts "r:o:" option; do
    case $option in
        r) rounds=$OPTARG ;;
        o) out=$OPTARG ;;
        *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
builds=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do
    builds+=("$1")
    shift
done
if [ $# -eq 0 ] || [ ${#builds[@]} -lt 2 ]; then
    echo "usage: bash bench/ab.sh [-r ROUNDS] [-o OUT] AOKIT_A AOKIT_B ... -- BENCH_OPTION..." >&2
    exit 2
fi
shift
mkdir -p "$out"
rm -f "$out"/b*-r*.json
for round in $(seq "$rounds"); do
    for i in "${!builds[@]}"; do
        "${builds[$i]}" bench --json "$@" >"$out/b$i-r$round.json"
        echo "round $round: ${builds[$i]}" >&2
    done
done
python3 bench/ab_summary.py "$out" "${builds[@]}"
