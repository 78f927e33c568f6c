#!/usr/bin/env bash
# Builds the Debian package build/packages/zeroset_VERSION_ARCH.deb with CPack (the Release
# build of scripts/build.sh; cmake/Package.cmake says what goes in it), shows its control
# fields, and runs lintian on it. Install it with: sudo apt install ./build/packages/zeroset_*.deb
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --deb
scripts/build.sh
rm -f build/packages/zeroset_*.deb
(cd build && cpack -G DEB)
deb=$(ls build/packages/zeroset_*.deb)
dpkg-deb --field "$deb" Package Version Architecture Depends
echo "lintian:"
lintian --info --pedantic "$deb" || true  # an error is reported above; the .deb is kept
echo "built $deb; install it with: sudo apt install ./$deb"
