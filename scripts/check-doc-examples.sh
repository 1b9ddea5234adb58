#!/usr/bin/env bash
# Fails when a public item of a published library crate has no example in its documentation:
# rustdoc's `missing_doc_code_examples` lint, which only a nightly toolchain has. Installs a
# minimal nightly with rustup when none is there. Its build goes to target/nightly-doc, apart
# from the stable builds.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! rustup toolchain list | grep -q '^nightly'; then
    rustup toolchain install nightly --profile minimal
fi
for crate in aokit aokit-scene aokit-reference aokit-eval; do
    CARGO_TARGET_DIR=target/nightly-doc cargo +nightly rustdoc --quiet -p "$crate" -- \
        -Z unstable-options -Zcrate-attr="feature(rustdoc_missing_doc_code_examples)" \
        -D rustdoc::missing-doc-code-examples
done
echo "check-doc-examples: every public item of the library crates has an example"
