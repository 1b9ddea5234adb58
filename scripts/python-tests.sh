#!/usr/bin/env bash
# Builds the Python package (python/) into a fresh virtual environment and runs its pytest
# suite against the `aokit` CLI of the same build. A venv keeps pip off Debian's system Python,
# which refuses installs (PEP 668, "externally-managed-environment"); python3-venv is installed
# where the interpreter lacks ensurepip (Debian's python3 without python3-venv).
#
#   scripts/python-tests.sh            # dev profile: reuses `cargo test`'s target/debug
#   PYTHON=/usr/bin/python3 AOKIT_VENV=/tmp/venv scripts/python-tests.sh
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHON="${PYTHON:-python3}"
TARGET="${CARGO_TARGET_DIR:-$PWD/target}"
VENV="${AOKIT_VENV:-$TARGET/python-venv}"

as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}
if ! "$PYTHON" -c 'import ensurepip, venv' >/dev/null 2>&1; then
    echo "python-tests: $PYTHON cannot make a venv; installing python3-venv"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv python3-pip >/dev/null
fi
rm -rf "$VENV"
"$PYTHON" -m venv "$VENV"
"$VENV/bin/python" -m pip install --quiet --upgrade pip
"$VENV/bin/python" -m pip install --quiet "maturin>=1.9,<2" "pytest>=7" numpy mypy
# The wheel in the dev profile, from the build `cargo test` left (a release build of wgpu
# would double CI's time); `pip install ./python` builds the same package in release.
rm -rf "$TARGET/python-wheels"
"$VENV/bin/maturin" build --quiet --profile dev --manifest-path python/Cargo.toml \
    --interpreter "$VENV/bin/python" --out "$TARGET/python-wheels"
"$VENV/bin/python" -m pip install --quiet "$TARGET"/python-wheels/aokit-*.whl
# The package's annotations and the native module's stubs (aokit/_aokit.pyi) agree.
"$VENV/bin/mypy" --strict --no-incremental python/aokit
# The CLI the parity tests compare against; they fail rather than skip without it.
cargo build --quiet -p aokit-cli
export AOKIT_BIN="$TARGET/debug/aokit" AOKIT_REQUIRE_CLI=1
# From outside python/, so that `import aokit` is the installed wheel, not the source tree.
cd "$TARGET"
"$VENV/bin/python" -m pytest -q -p no:cacheprovider "$OLDPWD/python/tests"
