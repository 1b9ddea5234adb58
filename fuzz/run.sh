#!/usr/bin/env bash
# Runs every fuzz target for SECONDS each (default 60), one after another, on the seeds
# (fuzz/seed.sh) and the corpus earlier runs grew. Needs nightly Rust and cargo-fuzz
# (`cargo install cargo-fuzz`). A crash stops the script with the target's name; the input is
# in fuzz/artifacts/TARGET/ (`cargo +nightly fuzz run TARGET fuzz/artifacts/TARGET/crash-…`
# replays it).
#
#   bash fuzz/run.sh        a minute each
#   bash fuzz/run.sh 3600   an hour each
set -euo pipefail
seconds=${1:-60}
cd "$(dirname "$0")"
bash seed.sh >/dev/null
cargo +nightly fuzz build
for target in $(cargo +nightly fuzz list); do
    echo "== $target: ${seconds}s"
    # 2 GB of memory at most, and inputs of 64 KB at most: a loader must refuse a file that
    # claims more than it holds before it allocates, not after.
    cargo +nightly fuzz run "$target" "corpus/$target" -- \
        -max_total_time="$seconds" -rss_limit_mb=2048 -max_len=65536 -timeout=20 \
        -print_final_stats=1 2>&1 | grep -E '^(stat::|==|SUMMARY|Done|INFO: (A corpus|Loaded))|panicked|ERROR' \
        || { echo "$target: FAILED; see fuzz/artifacts/$target/"; exit 1; }
done
