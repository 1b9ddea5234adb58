#!/usr/bin/env bash
# Regenerates docs/images/noise/ and the error tables of docs/noise.md: the noise tiles and
# their spectra (crates/aokit/examples/noise_spectra.rs), and every noise kind under four
# methods against the ray-traced reference on three built-in views and Sponza's atrium: the raw
# AO of frame 0, the spatial filter alone on frame 0, and 12 frames of a still camera without
# filtering and with temporal accumulation (the last frame's error and the flicker between
# frames). The references are the ones bench/quality.sh caches; a run takes about 8 minutes
# on 2 cores.
#
#   bash bench/noise.sh
set -euo pipefail
cd "$(dirname "$0")/.."
kinds=(ign blue gtao bayer white hilbert-r2)
methods=(gtao vbao hbao ssao)
views=("room / front" "stairs / side" "thin / front" "sponza / atrium")
frames=12
out=target/noise
images=docs/images/noise
rm -rf "$out" "$images"
mkdir -p "$out"
cargo run --quiet --release --example noise_spectra -p aokit -- "$images"

# compare NAME KIND FLAGS...: every view and method with noise.kind=KIND into $out/KIND/NAME.
compare() {
    local name=$1 kind=$2
    shift 2
    cargo run --quiet --release -p aokit-cli -- compare \
        --view room --view stairs --view thin --view scenes/sponza.obj@atrium \
        --method "$(IFS=,; echo "${methods[*]}")" --preset high --timing-frames 0 \
        --set noise.kind="$kind" --set spatial.enabled=false "$@" --out "$out/$kind/$name" >/dev/null
}

# column QUANTITY KIND NAME COLUMN: appends kind,view,method,quantity,value to $out/scores.csv
# from the named column of $out/KIND/NAME/metrics.csv. A sequence's view name carries
# " (N frames, path)", quoted for its comma; it is dropped.
column() {
    sed 's/^"\(.*\) ([0-9]* frames, [a-z]*)",/\1,/' "$out/$2/$3/metrics.csv" |
        awk -F, -v quantity="$1" -v kind="$2" -v name="$4" '
            NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; if (!c) exit 1; next }
            { print kind "," $1 "," $2 "," quantity "," $c }' >> "$out/scores.csv"
}

for kind in "${kinds[@]}"; do
    compare raw "$kind"
    compare spatial "$kind" --set spatial.enabled=true
    compare still "$kind" --frames "$frames" --path still
    compare temporal "$kind" --frames "$frames" --path still --set temporal.enabled=true
    column raw "$kind" raw rmse
    column spatial "$kind" spatial rmse
    column still "$kind" still rmse
    column temporal "$kind" temporal rmse
    column flicker-raw "$kind" still flicker
    column flicker-temporal "$kind" temporal flicker
    cp "$out/$kind/raw/images/sponza-atrium-gtao-high.png" "$images/ao-$kind.png"
done
cp "$out/ign/raw/images/sponza-atrium-reference.png" "$images/ao-reference.png"

# Per method and kind the means over the views of the raw, spatially filtered and temporally
# accumulated RMSE and of the flicker; then per method the raw RMSE by view.
awk -F, -v kinds="${kinds[*]}" -v methods="${methods[*]}" -v frames="$frames" \
    -v views="$(IFS=,; echo "${views[*]}")" '
    { score[$1, $2, $3, $4] = $5 }
    function mean(kind, method, quantity,    s, l) {
        s = 0; for (l = 1; l <= nv; l++) s += score[kind, v[l], method, quantity]
        return s / nv
    }
    END {
        nk = split(kinds, k, " "); nm = split(methods, m, " "); nv = split(views, v, ",")
        printf "| method | noise | RMSE raw, frame 0 | spatial, frame 0 |"
        printf " raw, frame %d | temporal, frame %d |", frames - 1, frames - 1
        print " flicker raw | flicker temporal |"
        print "|:--|:--|--:|--:|--:|--:|--:|--:|"
        for (j = 1; j <= nm; j++)
            for (i = 1; i <= nk; i++)
                printf "| `%s` | `%s` | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", m[j], k[i], \
                    mean(k[i], m[j], "raw"), mean(k[i], m[j], "spatial"), \
                    mean(k[i], m[j], "still"), mean(k[i], m[j], "temporal"), \
                    mean(k[i], m[j], "flicker-raw"), mean(k[i], m[j], "flicker-temporal")
        for (j = 1; j <= nm; j++) {
            printf "\n#### `%s`, raw, frame 0\n\n| noise |", m[j]
            for (l = 1; l <= nv; l++) printf " %s |", v[l]; print ""
            printf "|:--|"; for (l = 1; l <= nv; l++) printf "--:|"; print ""
            for (i = 1; i <= nk; i++) {
                printf "| `%s` |", k[i]
                for (l = 1; l <= nv; l++) printf " %.4f |", score[k[i], v[l], m[j], "raw"]
                print ""
            }
        }
    }' "$out/scores.csv" > "$out/tables.md"

# Splice the tables between <!-- noise:rmse --> and <!-- /noise:rmse --> in docs/noise.md.
FILE="$out/tables.md" perl -0pi -e '
    open my $f, "<", $ENV{FILE} or die; local $/; my $body = <$f>;
    s/(<!-- noise:rmse -->\n).*?(<!-- \/noise:rmse -->)/$1\n$body\n$2/s
        or die "no marker noise:rmse\n"' docs/noise.md
echo "wrote $images/ and docs/noise.md's tables; full reports in $out/"
