#!/usr/bin/env bash
# Writes what the settings' declarations generate into the docs: docs/settings.md and, on each
# method's page docs/methods/METHOD.md, the table of its own keys between <!-- settings:METHOD -->
# and <!-- /settings:METHOD -->. A test (crates/aokit-cli/tests/cli/settings.rs) fails where
# either differs from the declarations.
#
#   bash scripts/settings-docs.sh [AOKIT]     (AOKIT defaults to a debug build of aokit-cli)
set -euo pipefail
cd "$(dirname "$0")/.."
aokit=${1:-}
if [[ -z $aokit ]]; then
    cargo build --quiet -p aokit-cli
    aokit=target/debug/aokit
fi
# shellcheck source=splice.sh
source scripts/splice.sh
"$aokit" settings --markdown > docs/settings.md
table=$(mktemp)
trap 'rm -f "$table"' EXIT
for page in docs/methods/*.md; do
    method=$(basename "$page" .md)
    "$aokit" settings --markdown --method "$method" > "$table"
    splice "settings:$method" "$table"
done
