#!/usr/bin/env bash
# Fuzzes one reader of user input with libFuzzer for a while (fuzz/README.md):
#   scripts/fuzz.sh parser|codegen|surf|jsurf MINUTES
# Installs clang and its libFuzzer runtime (install-deps.sh --fuzz), configures the
# sanitized build in build-fuzz/ once, starts from the target's kept seed corpus
# (fuzz/corpus/), keeps what it learns in build-fuzz/corpus/TARGET, and writes any
# crashing input to build-fuzz/findings/TARGET/. Prints the executions and the findings;
# exits 1 when there are findings. JOBS=N runs N processes side by side (default 1).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { echo "usage: scripts/fuzz.sh parser|codegen|surf|jsurf MINUTES" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
target=$1
minutes=$2
[[ $minutes =~ ^[0-9]+$ && $minutes -gt 0 ]] || usage
case $target in
  parser | codegen) seeds=fuzz/corpus/codegen dict=(-dict=fuzz/formula.dict) ;;
  surf) seeds=fuzz/corpus/surf dict=() ;;
  jsurf) seeds=fuzz/corpus/jsurf dict=() ;;
  *) usage ;;
esac

scripts/install-deps.sh --fuzz
if [[ ! -f build-fuzz/build.ninja ]]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DZS_FUZZ=ON -DZS_BUILD_TESTS=OFF -DZS_BUILD_BENCH=OFF
fi
cmake --build build-fuzz --target "zs_${target}_fuzz"

work=$PWD/build-fuzz/corpus/$target
findings=$PWD/build-fuzz/findings/$target
log=$PWD/build-fuzz/fuzz-$target.log
mkdir -p "$work" "$findings"
before=$(find "$findings" -type f | wc -l)
jobs=${JOBS:-1}
fuzzer=$PWD/build-fuzz/fuzz/zs_${target}_fuzz
options=("${dict[@]/#-dict=/-dict=$PWD/}" -max_len=4096 -max_total_time=$((minutes * 60))
         -print_final_stats=1 -artifact_prefix="$findings/")
# libFuzzer adds what it finds to the FIRST corpus folder: the scratch one, not the seeds.
corpora=("$work" "$PWD/$seeds")
status=0
if [[ $jobs -gt 1 ]]; then
  # Independent processes sharing the corpus folder (-fork ran about half as many inputs a
  # second: each of its short jobs reloads the corpus). Each writes fuzz-JOB.log where it
  # starts, so they start in a folder of their own; the first process copies each job's log
  # into its own as the job ends.
  logs=$PWD/build-fuzz/logs-$target
  rm -rf "$logs"
  mkdir -p "$logs"
  (cd "$logs" && "$fuzzer" -jobs="$jobs" -workers="$jobs" "${options[@]}" "${corpora[@]}" \
     > "$log" 2>&1) || status=$?
else
  "$fuzzer" "${options[@]}" "${corpora[@]}" > "$log" 2>&1 || status=$?
fi
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | awk '{s += $1} END {print s + 0}')
found=$(( $(find "$findings" -type f | wc -l) - before ))
echo "$target: ${executions:-?} executions in $minutes min, $found new findings in $findings/ (log: $log)"
[[ $found -eq 0 && ($status -eq 0 || $jobs -gt 1) ]] || exit 1
