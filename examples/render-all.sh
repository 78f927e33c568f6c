#!/usr/bin/env bash
# Regenerates examples/images/*.png from every .surf under examples/ and prints the time
# each took. Usage: examples/render-all.sh [ZEROSET] [WIDTHxHEIGHT]
#   ZEROSET       the zeroset binary (default: build/src/app/zeroset or
#                 build-examples/src/app/zeroset, the first that can render)
#   WIDTHxHEIGHT  picture size (default 320x240: the pictures are committed, so they stay small)
# A scene in a subfolder gets the folder in its picture's name: thesis/3-cuboid.surf ->
# images/thesis-3-cuboid.png.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
zeroset="${1:-}"
if [[ -z "$zeroset" ]]; then
  for candidate in "$root/build/src/app/zeroset" "$root/build-examples/src/app/zeroset"; do
    # A stale build may predate the render command: take the first one that has it.
    if [[ -x "$candidate" ]] && "$candidate" render --help 2>&1 | grep -q -- --output; then
      zeroset="$candidate"; break
    fi
  done
fi
if [[ -z "$zeroset" || ! -x "$zeroset" ]]; then
  echo "render-all.sh: no zeroset binary; build it or pass its path" >&2
  exit 1
fi
size="${2:-320x240}"
mkdir -p "$here/images"
cd "$here"
find . -name '*.surf' | sed 's|^\./||' | sort | while read -r scene; do
  name="${scene%.surf}"
  name="${name//\//-}"
  "$zeroset" render "$scene" -o "images/$name.png" --size "$size"
done
