#!/usr/bin/env bash
# The main job: install dependencies, build in Release, and show a surface.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/src/app/zeroset render examples/thesis/2-cayley-cubic.surf -o out/cayley-cubic.png
echo "open out/cayley-cubic.png to see the Cayley cubic; build/src/app/zeroset --help for more"
