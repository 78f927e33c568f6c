#!/usr/bin/env bash
# Collects every translatable text of the viewer and the web page into a template
# (build/po/zeroset.pot, or the folder given) and merges it into each po/<code>.po: new texts
# arrive untranslated, changed ones lose their translation, and texts no longer used become
# obsolete (#~). Then translate what msgfmt --statistics reports as untranslated. The test
# i18n.catalogs_complete runs the same extraction and fails while any text lacks a
# translation. docs/languages.md has the whole routine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/po}
merge=${ZS_PO_MERGE:-1}  # 0: only write the template (the test's use)
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root"
# C++: tr("..."), label("...") and N_("...") in the viewer, its gallery and the interaction
# stage, and the parser (its errors reach the viewer and the page as the person types).
xgettext --from-code=UTF-8 --language=C++ --keyword --keyword=tr --keyword=label --keyword=N_ \
  --add-location=file --sort-by-file -o "$tmp/cpp.pot" \
  src/app/viewer/*.cpp src/app/gallery.cpp src/interact/*.cpp src/parser/*.cpp \
  src/session/*.cpp
# The page's scripts: tr('...'), trf('...', values) and N_('...').
xgettext --from-code=UTF-8 --language=JavaScript --keyword --keyword=tr --keyword=trf --keyword=N_ \
  --add-location=file --sort-by-file -o "$tmp/js.pot" web/*.js
python3 scripts/i18n_extract.py "$root" > "$tmp/extra.pot"
msgcat --use-first --sort-by-file -o "$out/zeroset.pot" "$tmp/extra.pot" \
  $( [ -s "$tmp/cpp.pot" ] && echo "$tmp/cpp.pot" ) $( [ -s "$tmp/js.pot" ] && echo "$tmp/js.pot" )
if [ "$merge" = 1 ]; then
  for po in po/*.po; do
    msgmerge --quiet --update --backup=none --no-fuzzy-matching --no-wrap "$po" "$out/zeroset.pot"
    printf '%s: ' "$po"
    msgfmt --statistics --check-format -o /dev/null "$po"
  done
fi
