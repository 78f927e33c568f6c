#!/usr/bin/env bash
# Installs every Debian package zeroset needs to build, run and test. Idempotent: when all
# packages are present it only checks and returns (well under a second).
#   scripts/install-deps.sh          build + run + test dependencies
#   scripts/install-deps.sh --fuzz   also clang and its libFuzzer runtime
#   scripts/install-deps.sh --deb    also lintian, for scripts/build-deb.sh
#   scripts/install-deps.sh --web    also emscripten and chromium, for scripts/build-web.sh
#                                    and the browser tests
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config python3
  # GL: every Mesa package in ONE line, or apt upgrades part of Mesa and leaves the rest
  # at an older point release (docs/toolchain notes).
  libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
  libglfw3-dev libglm-dev glslang-dev glslang-tools python3-glad
  libpng-dev libjpeg-dev libimgui-dev libcli11-dev libtomlplusplus-dev libedit-dev
  libgtest-dev libgmock-dev libbenchmark-dev libmpfi-dev libmpfr-dev libgmp-dev
  xvfb xauth xdotool
  # the viewer's font (src/app/viewer/fonts.cpp); the printed page's serif italic
  fonts-dejavu-core fonts-dejavu-extra
  # the printed page (src/print): cairo draws it; poppler-utils reads it back in the tests
  libcairo2-dev poppler-utils
  # the mesh tests (tests/mesh): an independent check of the STL files
  admesh
  # the install tests (tests/install): man -l on the installed page
  man-db
  # the batch recipes of docs/batch.md (tests/app: shards run by GNU parallel)
  parallel
  # the translations (po/, docs/languages.md): xgettext, msgmerge and msgfmt
  gettext
  # the layout check of .ci/run (scripts/check-format.sh)
  clang-format
  # the surf command's tests (tests/surfscript): surf 1.0.6 to compare with, and Singular,
  # whose plot, plot_jupyter and surfer run zeroset through build/compat
  surf-alggeo-nox singular
)
for option in "$@"; do
  case $option in
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    --deb) packages+=(lintian) ;;
    --web)
      packages+=(emscripten chromium)
      # Node.js and npm run the browser tests; Debian's where the machine has none of its own.
      command -v node >/dev/null || packages+=(nodejs)
      command -v npm >/dev/null || packages+=(npm)
      ;;
    *) echo "install-deps.sh: unknown option $option" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "zeroset: installing ${#missing[@]} Debian packages: ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${packages[@]}"
