#!/usr/bin/env bash
# Installs what aokit needs on a fresh Debian or Ubuntu machine, and nothing that is already
# there: a Rust toolchain, and a Vulkan driver. Without a GPU driver that is Mesa's lavapipe
# software rasteriser (package mesa-vulkan-drivers), which runs everything, slowly.
set -euo pipefail

as_root() {
    if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

if ! command -v cargo >/dev/null 2>&1 && [ -x "$HOME/.cargo/bin/cargo" ]; then
    export PATH="$HOME/.cargo/bin:$PATH"
fi
if ! command -v cargo >/dev/null 2>&1; then
    echo "setup: installing Rust with rustup"
    curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal --component rustfmt,clippy
    export PATH="$HOME/.cargo/bin:$PATH"
fi

has_vulkan_driver() {
    local icd
    for icd in /usr/share/vulkan/icd.d/*.json /etc/vulkan/icd.d/*.json; do
        [ -e "$icd" ] && return 0
    done
    return 1
}
if ! has_vulkan_driver; then
    if command -v apt-get >/dev/null 2>&1; then
        echo "setup: no Vulkan driver found; installing mesa-vulkan-drivers (lavapipe)"
        as_root apt-get update -qq
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq mesa-vulkan-drivers >/dev/null
    else
        echo "setup: no Vulkan driver found and no apt-get; install your GPU's Vulkan driver" \
             "or Mesa's lavapipe (package mesa-vulkan-drivers or similar)" >&2
        exit 1
    fi
fi
echo "setup: ready ($(cargo --version))"
