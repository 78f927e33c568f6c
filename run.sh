#!/usr/bin/env bash
# The main job: install dependencies, build in Release, and show a surface.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/src/app/zeroset check "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)"
