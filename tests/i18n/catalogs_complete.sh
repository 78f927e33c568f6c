#!/usr/bin/env bash
# Every text of the viewer and the web page is translated in every catalog: the extraction
# of scripts/update-po.sh, merged into each po/<code>.po in a scratch folder, must leave
# msgfmt --statistics with nothing untranslated or fuzzy, and the formats must check.
set -euo pipefail
root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ZS_PO_MERGE=0 "$root/scripts/update-po.sh" "$tmp" >/dev/null
status=0
for po in "$root"/po/*.po; do
  merged="$tmp/$(basename "$po")"
  msgmerge --quiet --no-fuzzy-matching -o "$merged" "$po" "$tmp/zeroset.pot"
  stats=$(msgfmt --statistics --check-format -o /dev/null "$merged" 2>&1) || { echo "$po: $stats"; status=1; continue; }
  echo "$(basename "$po"): $stats"
  if ! [[ "$stats" =~ ^[0-9]+\ translated\ messages?\.$ ]]; then
    echo "  untranslated or fuzzy in $po; run scripts/update-po.sh and translate:"
    msgattrib --untranslated --no-obsolete "$merged" | grep '^msgid' | head -20
    msgattrib --only-fuzzy --no-obsolete "$merged" | grep '^msgid' | head -20
    status=1
  fi
done
exit $status
