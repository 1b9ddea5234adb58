#!/usr/bin/env bash
# Makes the held-out scenes (scenes/README.md): downloads Debian's openarena-081-maps package,
# takes three maps out of it and converts them to OBJ under scenes/ with scripts/bsp_to_obj.py.
# The maps are GPL-2+, so the repository holds only their camera sidecars; the OBJ files are
# made here and checked against the checksums the references and cameras were made for.
# Needs apt-get (run `apt-get update` once first), dpkg-deb and python3; about 40 MB download.
#
#   bash scripts/fetch-scenes.sh
set -euo pipefail
cd "$(dirname "$0")/.."
package=openarena-081-maps
version=0.8.5split-14
declare -A sha256=(
    [oa_minia]=1777ae5a94dcd00e2b544c15feb14f892d973ed3a0f9df367de6e4983abcc94b
    [oa_rpg3dm2]=104913092559a96d5f510c9684eabdb4b7d851c600be51714ced4d49361e6f35
    [islanddm]=e6a3a7db438a0514822841e84f5a7dafa0e0debc1648c707ddf1d376cf32c44e
)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work" # apt-get downloads as its own user where it can write
if ! (cd "$work" && apt-get download "$package=$version" >/dev/null); then
    echo "could not download $package $version with apt-get: run 'apt-get update' first" >&2
    exit 1
fi
dpkg-deb -x "$work"/"$package"_*.deb "$work/deb"
pk3="$work/deb/usr/share/games/openarena/baseoa/pak1-maps.pk3"
for map in "${!sha256[@]}"; do
    # A .pk3 is a zip archive.
    python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extract(sys.argv[2], sys.argv[3])' \
        "$pk3" "maps/$map.bsp" "$work"
    python3 scripts/bsp_to_obj.py "$work/maps/$map.bsp" "scenes/$map.obj" \
        --source "$package $version, maps/$map.bsp in pak1-maps.pk3"
    if ! echo "${sha256[$map]}  scenes/$map.obj" | sha256sum --check --quiet; then
        echo "scenes/$map.obj differs from the file its cameras and references were made for" >&2
        exit 1
    fi
done
