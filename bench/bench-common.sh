# Sourced by performance.sh and kernel-costs.sh with their arguments ([AOKIT] [OUT]): the
# binary, the output directory, the two views and sizes they time, and the one way they run
# `aokit bench`.
aokit=${1:-target/release/aokit}
out=${2:-target/performance}
mkdir -p "$out"
scenes=(room sponza-atrium)
# AOKIT_BENCH_SIZES and AOKIT_BENCH_FRAMES ("TIMED WARMUP") shrink a run to try a script out on a
# software adapter before a GPU session spends its minutes on it.
read -r -a sizes <<<"${AOKIT_BENCH_SIZES:-1920x1080 3840x2160}"
read -r frames warmup <<<"${AOKIT_BENCH_FRAMES:-100 10}"

# The `aokit bench` options that show scene name $1, in `view`.
set_view() {
    case $1 in
        room) view=(--scene room) ;;
        sponza-atrium) view=(--scene scenes/sponza.obj --camera atrium) ;;
    esac
}

# bench_json NAME OPTION... -- CONFIGURATION...: one interleaved `--compare` run of the
# configurations, 100 timed frames after 10 (AOKIT_BENCH_FRAMES), its JSON array to
# OUT/NAME.json. The spatial filter is off unless a configuration turns it on, as it was by
# default when the published tables were measured: every configuration names its filters.
bench_json() {
    local name=$1 options=()
    shift
    while [ "$1" != -- ]; do
        options+=("$1")
        shift
    done
    shift
    "$aokit" bench --set spatial.enabled=false "${options[@]}" --timing-frames "$frames" --warmup "$warmup" --json --compare "$@" \
        >"$out/$name.json"
    echo "wrote $out/$name.json" >&2
}

# bench_each_view NAME CONFIGURATION...: bench_json on every scene at every size, to
# OUT/NAME-SCENE-SIZE.json.
bench_each_view() {
    local name=$1
    shift
    for scene in "${scenes[@]}"; do
        set_view "$scene"
        for size in "${sizes[@]}"; do
            bench_json "$name-$scene-$size" "${view[@]}" --size "$size" -- "$@"
        done
    done
}
