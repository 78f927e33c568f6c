#!/usr/bin/env python3
"""Writes zeroset's man page and its bash completion from the program's own --help.

usage: make-manpage.py ZEROSET_BINARY OUT_MAN_PAGE OUT_BASH_COMPLETION

The man page (section 1) holds the command's help and one section per subcommand, so it
cannot drift from --help: it is regenerated whenever the binary is rebuilt.
"""
import re
import subprocess
import sys


def helptext(binary, *args):
    out = subprocess.run([binary, *args, "--help"], capture_output=True, text=True, check=True)
    return out.stdout.replace(binary, "zeroset")  # CLI11 prints the path it was run as


def subcommands(top):
    names, inside = [], False
    for line in top.splitlines():
        if line.strip() == "Subcommands:":
            inside = True
            continue
        if inside:
            m = re.match(r"\s+(\w+)\s", line)
            if m:
                names.append(m.group(1))
            elif line.strip() == "":
                break
    return names


def options(text):
    found = []
    for line in text.splitlines():
        m = re.match(r"\s+(-[\w-]+(?:,--?[\w-]+)*)", line)
        if m:
            found.extend(m.group(1).split(","))
    return found


def roff(text):
    lines = []
    for line in text.splitlines():
        line = line.replace("\\", "\\e")
        if line.startswith(".") or line.startswith("'"):
            line = "\\&" + line
        lines.append(line.replace("-", "\\-"))
    return "\n".join(lines)


def main():
    binary, man_out, completion_out = sys.argv[1:4]
    top = helptext(binary)
    subs = subcommands(top)
    version = subprocess.run([binary, "--version"], capture_output=True, text=True).stdout.strip()
    page = [
        '.TH ZEROSET 1 "" "%s" "User Commands"' % version,
        ".SH NAME",
        "zeroset \\- see implicit surfaces F(x,y,z) = 0, ray-traced",
        ".SH SYNOPSIS",
        ".B zeroset",
        "[\\fISUBCOMMAND\\fR] [\\fIOPTIONS\\fR] [\\fIFORMULA\\fR|\\fISCENE.surf\\fR]",
        ".PP",
        "Without arguments, zeroset opens the formula prompt.",
        ".SH DESCRIPTION",
        ".nf",
        roff(top),
        ".fi",
    ]
    for sub in subs:
        page += [".SH %s" % ("ZEROSET " + sub.upper()), ".nf", roff(helptext(binary, sub)), ".fi"]
    page += [
        ".SH FILES",
        "Scene files end in .surf (TOML); the gallery is installed in",
        ".IR /usr/share/zeroset/examples .",
        ".SH SEE ALSO",
        "The documentation in",
        ".IR /usr/share/doc/zeroset .",
    ]
    with open(man_out, "w") as f:
        f.write("\n".join(page) + "\n")

    cases = []
    for sub in subs:
        opts = " ".join(sorted(set(options(helptext(binary, sub)))))
        cases.append('    %s) opts="%s" ;;' % (sub, opts))
    completion = """# bash completion for zeroset (generated from --help by scripts/make-manpage.py)
_zeroset() {
  local cur=${COMP_WORDS[COMP_CWORD]} sub=${COMP_WORDS[1]} opts
  if [[ $COMP_CWORD -eq 1 ]]; then
    COMPREPLY=($(compgen -W "%s --help --version" -- "$cur"))
    return
  fi
  case "$sub" in
%s
    *) opts="" ;;
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -X '!*.@(surf|png|pfm|csv|json)' -- "$cur") $(compgen -d -- "$cur"))
  fi
}
complete -F _zeroset zeroset
""" % (" ".join(subs), "\n".join(cases))
    with open(completion_out, "w") as f:
        f.write(completion)


if __name__ == "__main__":
    main()
