#!/usr/bin/env bash
# Regenerates docs/quality.md's "Raw and denoised" table: every method at its default preset
# (`high`) on the seven tuning views at 480x270, RMSE against the 512-ray references (cached by
# bench/quality.sh and bench/tuning.sh) with the spatial filter off, the kernel's raw estimate,
# and on, as the presets run it. Spliced between the page's <!-- filtered --> markers, which
# bench/quality.sh keeps. About 10 minutes on 2 cores.
#
#   bash bench/filtered-quality.sh [AOKIT]    # AOKIT: default target/release/aokit, built here
set -euo pipefail
cd "$(dirname "$0")/.."
aokit=${1:-target/release/aokit}
if [ $# -eq 0 ]; then
    cargo build --quiet --release -p aokit-cli
fi
out=target/filtered-quality
rm -rf "$out"
args=(compare --view room --view stairs --view thin
    --view scenes/sponza.obj@atrium --view scenes/sponza.obj@arcade
    --view scenes/sponza.obj@gallery --view scenes/sponza.obj@floor
    --method all --preset high --size 480x270 --spp 512 --timing-frames 0)
"$aokit" "${args[@]}" --set spatial.enabled=false --out "$out/raw" >/dev/null
"$aokit" "${args[@]}" --out "$out/filtered" >/dev/null
python3 - "$out" "$("$aokit" --version)" "${args[*]}" >"$out/table.md" <<'PY'
import csv
import sys

out, version, command = sys.argv[1:]
def read(name):
    rows = csv.DictReader(open(f"{out}/{name}/metrics.csv"))
    return {(r["method"], r["view"]): float(r["rmse"]) for r in rows}
raw, filtered = read("raw"), read("filtered")
methods = list(dict.fromkeys(m for m, _ in raw))
views = list(dict.fromkeys(v for _, v in raw))
print(f"`bash bench/filtered-quality.sh` ({version}): `aokit {command}`, with `--set "
      "spatial.enabled=false` (raw) and without (denoised, the default). RMSE raw -> denoised; "
      "the last column is the mean over the views.")
print()
print("| method | " + " | ".join(views) + " | mean |")
print("|---|" + "--:|" * (len(views) + 1))
for m in methods:
    cells = [f"{raw[m, v]:.4f} -> {filtered[m, v]:.4f}" for v in views]
    mean_raw = sum(raw[m, v] for v in views) / len(views)
    mean_filtered = sum(filtered[m, v] for v in views) / len(views)
    cells.append(f"{mean_raw:.4f} -> **{mean_filtered:.4f}** ({100 * (mean_filtered / mean_raw - 1):+.0f}%)")
    print(f"| `{m}` | " + " | ".join(cells) + " |")
PY
# shellcheck source=../scripts/splice.sh
source scripts/splice.sh
splice filtered "$out/table.md"
echo "wrote the table between docs/quality.md's <!-- filtered --> markers"
