# Sourced by the scripts that write generated blocks into the pages (bench/quality.sh,
# bench/filtered-quality.sh, bench/heldout-quality.sh, scripts/settings-docs.sh).
#
# splice MARKER FILE: replace what lies between <!-- MARKER --> and <!-- /MARKER --> in whichever
# of docs/quality.md, docs/methods.md and docs/methods/*.md holds the marker with FILE, a blank
# line either side.
splice() {
    local page
    page=$(grep -l -F -- "<!-- $1 -->" docs/quality.md docs/methods.md docs/methods/*.md | head -n 1)
    [[ -n $page ]] || { echo "no marker $1" >&2; exit 1; }
    MARKER="$1" FILE="$2" perl -0pi -e '
        open my $f, "<", $ENV{FILE} or die; local $/; my $body = <$f>;
        s/(<!-- \Q$ENV{MARKER}\E -->\n).*?(<!-- \/\Q$ENV{MARKER}\E -->)/$1\n$body\n$2/s
            or die "no marker $ENV{MARKER}\n"' "$page"
}
