#!/usr/bin/env bash
# Install dependencies, build, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
# The layout of every tracked C++ file is .clang-format's (scripts/check-format.sh --fix).
scripts/check-format.sh
scripts/build.sh
# The web page (docs/web.md): its site and wasm tests, and the browser tests' driver.
scripts/build-web.sh
npm ci --prefix tests/web --no-audit --no-fund --loglevel=error
# Every test has a TIMEOUT (tests/CMakeLists.txt); --timeout covers any added without one.
log=build/Testing/test-run.log
mkdir -p build/Testing
status=0
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 180 2>&1 | tee "$log" ||
  status=$?
# The ten slowest tests of this run: each should stay under 20 s.
echo "The ten slowest tests of this run (seconds):"
sed -n 's/^ *[0-9]*\/[0-9]* Test *#[0-9]*: \([^ ]*\) .* \([0-9.]*\) sec$/\2 \1/p' "$log" |
  sort -rn | awk 'NR <= 10 {printf "  %7.2f  %s\n", $1, $2}'
# A failing test's own output, last: what CI keeps of a run is its tail.
if [ "$status" -ne 0 ]; then
  awk '/Test *#[0-9]+: .*\*\*\*(Failed|Timeout|Exception)/ {keep = 1; n = 0; print "---- " $0; next}
       /^ *Start *[0-9]+:|Test *#[0-9]+:|^[0-9]+% tests passed/ {keep = 0}
       keep && n++ < 80' "$log"
fi
exit "$status"
