#!/usr/bin/env bash
# The installed zeroset, as a user gets it (ctest label "install"; tests/install/CMakeLists.txt).
#   install_test.sh setup      BUILD SOURCE PREFIX   cmake --install BUILD --prefix PREFIX
#   install_test.sh files      BUILD SOURCE PREFIX   every installed file is where it belongs
#   install_test.sh run        BUILD SOURCE PREFIX   the installed tree, moved to a new place,
#                              renders an installed example with SOURCE and BUILD out of reach
#   install_test.sh view       BUILD SOURCE PREFIX   the installed viewer cycles through the
#                              installed gallery (xvfb-run, xdotool), SOURCE out of reach
#   install_test.sh man        BUILD SOURCE PREFIX   man -l shows the page without warnings,
#                              and it names every option that --help names
#   install_test.sh desktop    BUILD SOURCE PREFIX   desktop entry, MIME type, thumbnailer
#   install_test.sh completion BUILD SOURCE PREFIX   bash completion of commands and values
# Exit status 77 means a tool the check needs is missing (ctest shows the test as skipped).
set -euo pipefail
what=$1 build=$2 source=$3 prefix=$4

fail() { echo "FAIL: $*" >&2; exit 1; }
skip() { echo "SKIP: $*" >&2; exit 77; }
need() { command -v "$1" >/dev/null || skip "$1 is not installed"; }

# Runs "$@" in a new mount namespace where SOURCE and BUILD are empty folders, with a bare
# environment, from a folder outside both: the program cannot read anything of them. Falls
# back to the bare environment alone where namespaces are not allowed (then the check
# below, that the program holds no path into them, is what remains).
out_of_reach() {
  local hide="mount -t tmpfs none '$source'"
  case "$build/" in "$source"/*) ;; *) hide+=" && mount -t tmpfs none '$build'" ;; esac
  local envs=(env -i PATH=/usr/bin:/bin HOME="$work" LANG=C.UTF-8)
  if unshare -m true 2>/dev/null; then
    unshare -m sh -c "$hide && cd '$work' && exec \"\$@\"" sh "${envs[@]}" "$@"
  elif unshare -rm true 2>/dev/null; then
    unshare -rm sh -c "$hide && cd '$work' && exec \"\$@\"" sh "${envs[@]}" "$@"
  else
    echo "note: no mount namespace here; running with a bare environment only" >&2
    (cd "$work" && "${envs[@]}" "$@")
  fi
}

# A copy of the installed tree somewhere else: the program must find its files relative to
# itself, not where it was installed.
moved_copy() {
  work=$(mktemp -d "${TMPDIR:-/tmp}/zeroset-installed.XXXXXX")
  trap 'rm -rf "$work"' EXIT
  case "$work/" in "$source"/* | "$build"/*) fail "temporary folder $work is inside the trees" ;; esac
  cp -a "$prefix" "$work/usr"
  bin="$work/usr/bin/zeroset" share="$work/usr/share"
}

is_png() { [[ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" == 89504e470d0a1a0a ]]; }

case $what in
setup)
  rm -rf "$prefix"
  cmake --install "$build" --prefix "$prefix" >"$prefix.log" || { cat "$prefix.log"; exit 1; }
  echo "installed into $prefix"
  ;;

files)
  for f in bin/zeroset \
           share/zeroset/examples/sphere.surf share/zeroset/examples/thesis/3-cuboid.surf \
           share/zeroset/examples/README.md share/doc/zeroset/README.md \
           share/doc/zeroset/docs/formula.md share/doc/zeroset/copyright \
           share/doc/zeroset/changelog.gz share/man/man1/zeroset.1.gz \
           share/bash-completion/completions/zeroset \
           share/applications/zeroset.desktop share/icons/hicolor/256x256/apps/zeroset.png \
           share/icons/hicolor/48x48/apps/zeroset.png share/mime/packages/zeroset.xml \
           share/thumbnailers/zeroset.thumbnailer; do
    [[ -e "$prefix/$f" ]] || fail "$f is not installed"
  done
  ls "$prefix"/share/zsh/*/_zeroset >/dev/null || fail "the zsh completion is not installed"
  [[ -x "$prefix/bin/zeroset" ]] || fail "bin/zeroset is not executable"
  [[ -e "$prefix/share/doc/zeroset/examples/sphere.surf" ]] ||
    fail "share/doc/zeroset/examples does not lead to the gallery"
  [[ ! -e "$prefix/share/zeroset/examples/render-all.sh" ]] || fail "render-all.sh is installed"
  ! find "$prefix" -name 'zeroset-docgen*' | grep -q . || fail "zeroset-docgen is installed"
  echo "all files in place"
  ;;

run)
  moved_copy
  # No path into the trees is compiled in (the gallery is found relative to the program).
  ! grep -qF "$source" "$bin" || fail "bin/zeroset holds the path $source"
  ! grep -qF "$build" "$bin" || fail "bin/zeroset holds the path $build"
  if out_of_reach test -e "$source/CMakeLists.txt"; then
    echo "note: the source tree is still visible; only the bare environment is checked"
  fi
  out_of_reach "$bin" --version | grep -q '^zeroset ' || fail "zeroset --version"
  out_of_reach "$bin" render "$share/zeroset/examples/thesis/3-cuboid.surf" \
    -o "$work/cuboid.png" --size 64x48
  is_png "$work/cuboid.png" || fail "no PNG from the installed zeroset render"
  out_of_reach "$bin" render "-x^2-y^2+z" -o "$work/minus.png" --size 32x24
  is_png "$work/minus.png" || fail "no PNG for a formula with a leading minus"
  echo "the installed zeroset renders with the source and build trees out of reach"
  ;;

view)
  need xvfb-run
  need xdotool
  moved_copy
  surfaces=$(find "$share/zeroset/examples" -name '*.surf' | wc -l)
  cat >"$work/drive.sh" <<DRIVE
"$bin" view --log >"$work/view.log" 2>&1 &
pid=\$!
for i in \$(seq 1 120); do grep -q '^ready' "$work/view.log" && break; sleep 0.5; done
window=\$(xdotool search --sync --onlyvisible --pid \$pid | head -1)
xdotool windowfocus --sync "\$window" mousemove --window "\$window" 400 300
xdotool key --delay 60 n
for i in \$(seq 1 60); do grep -q '^example 2 of' "$work/view.log" && break; sleep 0.5; done
kill \$pid
DRIVE
  out_of_reach xvfb-run -a -s "-screen 0 1024x768x24" sh "$work/drive.sh" || true
  grep -q "^example 2 of $surfaces: thesis/2-cayley-cubic" "$work/view.log" ||
    fail "the viewer did not cycle through the $surfaces installed examples: $(cat "$work/view.log")"
  echo "the installed viewer finds the installed gallery ($surfaces surfaces)"
  ;;

man)
  need man
  page="$prefix/share/man/man1/zeroset.1.gz"
  # As wide as it takes, so no option is hyphenated at a line's end.
  text=$(MANPAGER=cat MANWIDTH=1000 LC_ALL=C.UTF-8 man -l -P cat "$page")
  grep -q '^NAME' <<<"$text" || fail "man -l shows no NAME section"
  # groff's warnings, as lintian asks for them
  warnings=$(LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=80 man --warnings -E UTF-8 -l -Tutf8 -Z \
             "$page" 2>&1 >/dev/null)
  [[ -z "$warnings" ]] || fail "man reports: $warnings"
  # Every subcommand and every option that --help shows is on the page.
  flat=$(tr -s ' \n' ' ' <<<"$text")
  commands=$("$prefix/bin/zeroset" --help |
             awk '/^Subcommands:/ {on = 1; next} on && !NF {exit} on {print $1}')
  [[ -n "$commands" ]] || fail "no subcommands in zeroset --help"
  for c in $commands; do
    grep -qF "zeroset $c" <<<"$flat" || fail "the man page lacks zeroset $c"
    for opt in $("$prefix/bin/zeroset" "$c" --help | grep -oE '^ +-[-a-z,]+' | tr ',' ' '); do
      grep -qF -- "$opt" <<<"$flat" || fail "the man page lacks $c's option $opt"
    done
  done
  echo "the man page reads cleanly and names every command and option of --help"
  ;;

desktop)
  moved_copy
  if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate "$share/applications/zeroset.desktop"
  else
    echo "note: desktop-file-validate is not installed; the entry is checked by hand only"
  fi
  grep -q '^Exec=zeroset view %f$' "$share/applications/zeroset.desktop" || fail "desktop Exec"
  grep -q '^MimeType=application/x-zeroset-surf;$' "$share/applications/zeroset.desktop" ||
    fail "desktop MimeType"
  if command -v update-mime-database >/dev/null; then
    update-mime-database "$share/mime" >/dev/null
    grep -q '^application/x-zeroset-surf:\*\.surf$' "$share/mime/globs" ||
      fail "update-mime-database did not register *.surf"
  fi
  # The thumbnailer's own command line, with %i %o %s filled in as a file manager does.
  exec_line=$(sed -n 's/^Exec=//p' "$share/thumbnailers/zeroset.thumbnailer")
  exec_line=${exec_line//%i/$share/zeroset/examples/torus.surf}
  exec_line=${exec_line//%o/$work/thumb.png}
  exec_line=${exec_line//%s/128}
  read -r -a words <<<"$exec_line"
  [[ ${words[0]} == zeroset ]] || fail "the thumbnailer does not run zeroset"
  words[0]=$bin
  out_of_reach "${words[@]}"
  is_png "$work/thumb.png" || fail "the thumbnailer made no PNG"
  [[ "$(od -An -tu1 -j16 -N8 "$work/thumb.png" | tr -s ' ')" == " 0 0 0 128 0 0 0 128" ]] ||
    fail "the thumbnail is not 128x128"
  echo "desktop entry, MIME type and thumbnailer work"
  ;;

completion)
  need bash
  script="$prefix/share/bash-completion/completions/zeroset"
  complete_line() {  # the words; prints what completion offers for the last one
    bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _zeroset
             printf "%s\n" "${COMPREPLY[@]}"' sh "$script" "$@"
  }
  [[ "$(complete_line zeroset ren)" == render ]] || fail "zeroset ren<TAB>"
  [[ "$(complete_line zeroset render --back)" == --backend ]] || fail "--back<TAB>"
  [[ "$(complete_line zeroset render x --backend '' | sort | tr '\n' ' ')" == "egl osmesa " ]] ||
    fail "--backend <TAB>"
  [[ "$(complete_line zeroset view --set camera.e)" == camera.eye= ]] || fail "--set camera.e<TAB>"
  echo "bash completion offers commands, options and values"
  ;;

*) fail "unknown check $what" ;;
esac
