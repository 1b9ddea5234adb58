#!/usr/bin/env bash
# Test the Blender exporter (tools/blender/export_aokit.py) against aokit's own reference:
# build a small scene in Blender, export it from a perspective camera (vertical sensor fit, lens
# shift) and an orthographic one (horizontal fit, shift), export the same triangles as OBJ,
# ray-trace `aokit reference` on the OBJ with the camera camera.json describes, and check that
# the depths agree where both hit and that `aokit ao` on the exported passes is within aokit's
# usual error of the reference (tools/blender/tests/check_export.py). Also checks the exporter's
# refusals. See docs/blender.md.
#
#   scripts/blender-test.sh            # uses $AOKIT, default target/release/aokit
#
# Skips (exit 0) when `blender` is not installed, unless AOKIT_REQUIRE_BLENDER=1.
set -euo pipefail
cd "$(dirname "$0")/.."
AOKIT=${AOKIT:-target/release/aokit}
BLENDER=${BLENDER:-blender}
if ! command -v "$BLENDER" >/dev/null 2>&1; then
    if [ "${AOKIT_REQUIRE_BLENDER:-0}" = 1 ]; then
        echo "blender-test: blender not found and AOKIT_REQUIRE_BLENDER=1" >&2
        exit 1
    fi
    echo "blender-test: SKIPPED: blender not found (apt-get install blender; AOKIT_REQUIRE_BLENDER=1 makes this an error)"
    exit 0
fi
if [ ! -x "$AOKIT" ]; then
    echo "blender-test: no aokit binary at $AOKIT (cargo build --release -p aokit-cli, or set AOKIT)" >&2
    exit 1
fi
AOKIT=$(cd "$(dirname "$AOKIT")" && pwd)/$(basename "$AOKIT")
WORK=${BLENDER_TEST_DIR:-$(mktemp -d)}
mkdir -p "$WORK"
echo "blender-test: $("$BLENDER" --version 2>/dev/null | head -n1), aokit $AOKIT, work $WORK"
EXPORT=tools/blender/export_aokit.py
blender_run() { "$BLENDER" -b --python-exit-code 1 "$@" >"$WORK/blender.log" 2>&1 || { cat "$WORK/blender.log"; return 1; }; }

blender_run --factory-startup -P tools/blender/tests/make_scene.py -- "$WORK/scene.blend" "$WORK/scene.obj"
# The third case: AUTO fit on a portrait image (the fit follows the longer side, the height, but
# with the sensor width), the persp camera shifted by whole pixels.
AUTO_PORTRAIT="import bpy; s = bpy.context.scene; s.render.resolution_x, s.render.resolution_y = 480, 640
c = bpy.data.objects['persp'].data; c.sensor_fit = 'AUTO'; c.sensor_width = 24.0; c.shift_x, c.shift_y = 0.05, -0.1"
for case in persp ortho auto-portrait; do
    rm -rf "$WORK/$case"
    case $case in
        auto-portrait) setup=(--python-expr "$AUTO_PORTRAIT") cam=persp ;;
        *) setup=() cam=$case ;;
    esac
    blender_run --factory-startup "$WORK/scene.blend" "${setup[@]}" -P "$EXPORT" -- --out "$WORK/$case" --camera "$cam"
    grep '^aokit export' "$WORK/blender.log"
    python3 tools/blender/tests/check_export.py "$AOKIT" "$WORK/scene.obj" "$WORK/$case" "$WORK/check-$case" \
        --radius 0.5 --spp 64
done

# Refusals: exit status 2 and a message naming the problem.
expect_refusal() {
    local want=$1
    shift
    set +e
    "$BLENDER" -b --factory-startup "$WORK/scene.blend" "$@" >"$WORK/refusal.log" 2>&1
    local rc=$?
    set -e
    if [ "$rc" != 2 ] || ! grep -q "$want" "$WORK/refusal.log"; then
        cat "$WORK/refusal.log"
        echo "blender-test: expected exit 2 and '$want', got exit $rc" >&2
        exit 1
    fi
    echo "blender-test: refused as expected: $(grep "$want" "$WORK/refusal.log" | head -n1)"
}
touch "$WORK/a-file"
expect_refusal "exists and is not a folder" -P "$EXPORT" -- --out "$WORK/a-file"
expect_refusal "is panoramic" --python-expr "import bpy; bpy.data.objects['persp'].data.type = 'PANO'" \
    -P "$EXPORT" -- --out "$WORK/pano"
expect_refusal "has no active camera" --python-expr "import bpy; bpy.context.scene.camera = None" \
    -P "$EXPORT" -- --out "$WORK/none"
expect_refusal "is a MESH, not a camera" -P "$EXPORT" -- --out "$WORK/mesh" --camera floor
echo "blender-test: OK"
