#!/usr/bin/env bash
# Regenerates zeroset's icon, hicolor/SIZE/apps/zeroset.png, from zeroset-icon.surf with
# zeroset itself: each size is rendered on black and on white, and matte.py turns the pair
# into one picture with a transparent background (antialiased edges keep their coverage).
# Usage: data/icons/render-icons.sh [ZEROSET]   (default: build/src/app/zeroset)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
zeroset="${1:-$here/../../build/src/app/zeroset}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
for size in 16 24 32 48 64 128 256; do
  out="$here/hicolor/${size}x${size}/apps"
  mkdir -p "$out"
  for bg in 0 1; do
    "$zeroset" render "$here/zeroset-icon.surf" --size "${size}x${size}" \
      --set "background=[$bg,$bg,$bg]" -o "$tmp/$bg.png" >/dev/null
  done
  python3 "$here/matte.py" "$tmp/0.png" "$tmp/1.png" "$out/zeroset.png"
  echo "$out/zeroset.png"
done
