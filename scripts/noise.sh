#!/usr/bin/env bash
# Regenerates docs/images/noise/ and the error tables of docs/noise.md: the noise tiles and
# their spectra (crates/aokit/examples/noise_spectra.rs), and every noise kind under four
# methods against the ray-traced reference on three built-in views and Sponza's atrium, with no
# filtering. The references are the ones scripts/quality.sh caches; a run takes a few minutes on
# 2 cores.
#
#   bash scripts/noise.sh
set -euo pipefail
cd "$(dirname "$0")/.."
kinds=(ign blue gtao bayer white hilbert-r2)
methods=(gtao vbao hbao ssao)
views=("room / front" "stairs / side" "thin / front" "sponza / atrium")
out=target/noise
images=docs/images/noise
rm -rf "$out" "$images"
mkdir -p "$out"
cargo run --quiet --release --example noise_spectra -p aokit -- "$images"
for kind in "${kinds[@]}"; do
    cargo run --quiet --release -p aokit-cli -- compare \
        --view room --view stairs --view thin --view scenes/sponza.obj@atrium \
        --methods "$(IFS=,; echo "${methods[*]}")" --presets high \
        --set noise.kind="$kind" --out "$out/$kind" >/dev/null
    # kind,view,method,rmse
    awk -F, -v kind="$kind" 'NR > 1 {print kind "," $1 "," $2 "," $8}' \
        "$out/$kind/metrics.csv" >> "$out/rmse.csv"
    cp "$out/$kind/images/sponza-atrium-gtao-high.png" "$images/ao-$kind.png"
done
cp "$out/ign/images/sponza-atrium-reference.png" "$images/ao-reference.png"

# The mean RMSE over the views per kind and method, then per method a table by view.
awk -F, -v kinds="${kinds[*]}" -v methods="${methods[*]}" -v views="$(IFS=,; echo "${views[*]}")" '
    { rmse[$1, $2, $3] = $4 }
    END {
        nk = split(kinds, k, " "); nm = split(methods, m, " "); nv = split(views, v, ",")
        printf "| noise |"; for (j = 1; j <= nm; j++) printf " `%s` |", m[j]; print ""
        printf "|:--|"; for (j = 1; j <= nm; j++) printf "--:|"; print ""
        for (i = 1; i <= nk; i++) {
            printf "| `%s` |", k[i]
            for (j = 1; j <= nm; j++) {
                s = 0; for (l = 1; l <= nv; l++) s += rmse[k[i], v[l], m[j]]
                printf " %.4f |", s / nv
            }
            print ""
        }
        for (j = 1; j <= nm; j++) {
            printf "\n#### `%s`\n\n| noise |", m[j]
            for (l = 1; l <= nv; l++) printf " %s |", v[l]; print ""
            printf "|:--|"; for (l = 1; l <= nv; l++) printf "--:|"; print ""
            for (i = 1; i <= nk; i++) {
                printf "| `%s` |", k[i]
                for (l = 1; l <= nv; l++) printf " %.4f |", rmse[k[i], v[l], m[j]]
                print ""
            }
        }
    }' "$out/rmse.csv" > "$out/tables.md"

# Splice the tables between <!-- noise:rmse --> and <!-- /noise:rmse --> in docs/noise.md.
FILE="$out/tables.md" perl -0pi -e '
    open my $f, "<", $ENV{FILE} or die; local $/; my $body = <$f>;
    s/(<!-- noise:rmse -->\n).*?(<!-- \/noise:rmse -->)/$1\n$body\n$2/s
        or die "no marker noise:rmse\n"' docs/noise.md
echo "wrote $images/ and docs/noise.md's tables; full reports in $out/"
