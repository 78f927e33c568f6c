#!/usr/bin/env bash
# Installs the build into a fresh prefix and uses it as a user would, from a directory
# outside the source tree with ZS_SOURCE_DIR unset: the installed zeroset renders an
# installed example, finds the installed gallery, and the installed man page reads.
# usage: install_test.sh CMAKE BUILD_DIR
set -euo pipefail
cmake_bin=$1 build=$2
prefix=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$prefix" "$work"' EXIT
"$cmake_bin" --install "$build" --prefix "$prefix" > /dev/null
cd "$work"
unset ZS_SOURCE_DIR
for f in bin/zeroset share/man/man1/zeroset.1.gz share/applications/zeroset.desktop \
         share/mime/packages/zeroset.xml share/thumbnailers/zeroset.thumbnailer \
         share/icons/hicolor/scalable/apps/zeroset.svg \
         share/bash-completion/completions/zeroset share/zeroset/examples/barth-sextic.surf \
         share/doc/zeroset/README.md share/doc/zeroset/surf-format.md; do
  [[ -e "$prefix/$f" ]] || { echo "not installed: $f"; exit 1; }
done
"$prefix/bin/zeroset" render "$prefix/share/zeroset/examples/thesis/2-cayley-cubic.surf" \
  -o cayley.png --size 120x90
[[ -s cayley.png ]] || { echo "no picture"; exit 1; }
# The thumbnailer's command line, as a file manager runs it (%i %o %s).
exec_line=$(sed -n 's/^Exec=//p' "$prefix/share/thumbnailers/zeroset.thumbnailer")
exec_line=${exec_line//%i/$prefix/share/zeroset/examples/sphere.surf}
exec_line=${exec_line//%o/thumb.png}
exec_line=${exec_line//%s/64}
PATH="$prefix/bin:$PATH" bash -c "$exec_line" > /dev/null
[[ -s thumb.png ]] || { echo "the thumbnailer wrote nothing"; exit 1; }
if command -v man > /dev/null; then
  page=$(MANWIDTH=100 man -l -P cat "$prefix/share/man/man1/zeroset.1.gz" 2> /dev/null)
  grep -q "ZEROSET RENDER" <<< "$page" || { echo "man page lacks the render section"; exit 1; }
  grep -q "ZEROSET SINGULAR" <<< "$page" || { echo "man page lacks the singular section"; exit 1; }
fi
echo "installed zeroset works from $prefix"
