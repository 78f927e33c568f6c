#!/usr/bin/env bash
# An independent check of the STL files zeroset writes: ADMesh (Debian's admesh) reads the
# file, matches the facets' edges exactly and reports what it had to repair. A closed,
# consistently oriented mesh needs no repair: no disconnected facets, no degenerate facets,
# no reversed facets or backwards edges, one part (or as many as given),
# and the volume ADMesh computes within 1% of the expected one.
#   admesh_check.sh ZEROSET OUT.stl PARTS VOLUME [zeroset mesh arguments...]
set -euo pipefail
zeroset=$1 out=$2 parts=$3 volume=$4
shift 4
"$zeroset" mesh "$@" -o "$out" -q
report=$(admesh "$out")
echo "$report" | sed -n '/Facet Status/,$p'
fail=0
expect() {  # expect LABEL VALUE: the "Final" (last) number on the line must equal VALUE
  local got
  got=$(echo "$report" | grep -E "^$1 *:" | head -1 | awk '{print $NF}')
  if [[ "$got" != "$2" ]]; then echo "FAIL: $1 is '$got', expected $2"; fail=1; fi
}
expect "Facets with 1 disconnected edge" 0
expect "Facets with 2 disconnected edges" 0
expect "Facets with 3 disconnected edges" 0
expect "Total disconnected facets" 0
expect "Degenerate facets" 0
expect "Edges fixed" 0
expect "Facets removed" 0
expect "Facets added" 0
expect "Facets reversed" 0
expect "Backwards edges" 0
# Not "Normals fixed": ADMesh recomputes each facet's normal in single precision and counts
# those that differ from the stored one by more than 0.001, which happens on thin facets
# however the normal was stored. Orientation is what "Facets reversed" and "Backwards edges"
# check.
got_parts=$(echo "$report" | grep -E "^Number of parts" | awk '{print $5}')
[[ "$got_parts" == "$parts" ]] || { echo "FAIL: $got_parts parts, expected $parts"; fail=1; }
got_volume=$(echo "$report" | grep -E "Volume" | awk '{print $NF}')
if ! awk -v g="$got_volume" -v e="$volume" 'BEGIN { d = g - e; if (d < 0) d = -d; exit !(d <= 0.01 * e) }'; then
  echo "FAIL: volume $got_volume, expected $volume within 1%"; fail=1
fi
exit $fail
