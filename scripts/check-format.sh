#!/usr/bin/env bash
# Fails when a C++ file of the project differs from what clang-format (.clang-format) makes
# of it, and names the files; `scripts/check-format.sh --fix` formats them instead. Every
# tracked source is checked (they were all formatted at once, so each change must keep it).
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format || true)
if [[ -z "$format" ]]; then
  echo "check-format: clang-format not found (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' \
                                  'bench/*.cpp' 'bench/*.hpp' 'fuzz/*.cpp' 'fuzz/*.hpp')
if [[ "${1:-}" == "--fix" ]]; then
  printf '%s\0' "${files[@]}" | xargs -0 -P "$(nproc)" -n 16 "$format" -i
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if ! "$format" --dry-run --Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if (( ${#bad[@]} )); then
  echo "check-format: ${#bad[@]} file(s) differ from clang-format's layout:" >&2
  printf '  %s\n' "${bad[@]}" >&2
  echo "run scripts/check-format.sh --fix, and commit the result" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files as clang-format lays them out"
