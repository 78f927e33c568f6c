#!/usr/bin/env bash
# Builds the web page (docs/web.md): the core stages compiled to WebAssembly with Debian's
# emscripten, the page's assets from web/, the gallery of examples/; writes a static site to
# build-web/site/ that any static HTTP server can serve. Installs what it needs first, like
# install-deps.sh. Idempotent and quick when nothing changed.
#   scripts/build-web.sh            the site (and the wasm interval tests, run by test.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --web

# emcc's JavaScript optimizer loads Debian's node modules, whatever node is on the PATH.
export NODE_PATH=/usr/share/nodejs
emcmake cmake -S . -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release -DZS_BUILD_TESTS=ON >/dev/null
cmake --build build-web -j"$(nproc)"

site=build-web/site
rm -rf "$site"
mkdir -p "$site/examples/thesis" "$site/examples/images"
cp web/*.html web/*.js web/*.css "$site/"
cp build-web/src/web/zeroset.js build-web/src/web/zeroset.wasm "$site/"
cp examples/*.surf "$site/examples/"
cp examples/thesis/*.surf "$site/examples/thesis/"
cp examples/images/*.png "$site/examples/images/"
python3 scripts/web_gallery_index.py examples >"$site/examples/index.json"
echo "zeroset: web site in $site ($(du -sh "$site" | cut -f1)); serve it with any static server," \
     "e.g. python3 -m http.server -d $site"
