#!/usr/bin/env python3
"""Writes, as a .pot fragment on stdout, the translatable texts that xgettext cannot find in
code: the web page's static texts (elements marked data-i18n, and the attributes named in
data-i18n-attrs), the gallery's texts (each example's first comment line, which the
viewer shows, and its title before " — ", which the page shows), and the words of the
scene's keys and choices (docs/surf-format.md's tables), which the page's settings show. Usage:
i18n_extract.py ROOT. scripts/update-po.sh runs it; docs/languages.md explains the marks."""
import html.parser
import pathlib
import re
import sys

from gallery_texts import summary_and_title

root = pathlib.Path(sys.argv[1])
messages = {}  # msgid -> list of "file:line" references, in order of first appearance


def add(text, where):
    text = " ".join(text.split())
    if text:
        messages.setdefault(text, []).append(where)


class Page(html.parser.HTMLParser):
    """Collects data-i18n texts and data-i18n-attrs attribute values of one HTML file."""

    def __init__(self, name):
        super().__init__(convert_charrefs=True)
        self.name = name
        self.open = []  # [tag, collected text] of the marked elements we are inside

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        where = f"{self.name}:{self.getpos()[0]}"
        for attr in (a.get("data-i18n-attrs") or "").split():
            add(a.get(attr, ""), where)
        if "data-i18n" in a:
            self.open.append([tag, "", where])

    def handle_data(self, data):
        if self.open:
            self.open[-1][1] += data

    def handle_endtag(self, tag):
        if self.open and self.open[-1][0] == tag:
            _, text, where = self.open.pop()
            add(text, where)


for page in sorted((root / "web").glob("*.html")):
    p = Page(page.relative_to(root).as_posix())
    p.feed(page.read_text(encoding="utf-8"))

# `| `camera.fov_y` | number | ...`: each word of the key ("fov y"), and the choices of a
# word key ("`"perspective"`, `"orthographic"`").
for number, row in enumerate((root / "docs" / "surf-format.md").read_text(encoding="utf-8").splitlines(), 1):
    m = re.match(r"\| `([a-z_.0-9]+)` \| (\w+) \| ([^|]*)\|", row)
    if not m:
        continue
    where = f"docs/surf-format.md:{number}"
    for word in m.group(1).split("."):
        add(word.replace("_", " "), where)
    if m.group(2) == "word":
        for choice in re.findall(r'`"([^"]+)"`', m.group(3)):
            add(choice, where)

examples = root / "examples"
for path in sorted(examples.glob("thesis/*.surf")) + sorted(examples.glob("*.surf")):
    summary, title = summary_and_title(path.read_text(encoding="utf-8"), "")
    where = f"{path.relative_to(root).as_posix()}:1"
    add(summary, where)
    add(title, where)


def quote(s):
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


print('msgid ""\nmsgstr ""\n"Content-Type: text/plain; charset=UTF-8\\n"\n')
for text, where in messages.items():
    print("#: " + " ".join(where))
    if "%" in text:
        print("#, no-c-format")
    print(f"msgid {quote(text)}\nmsgstr \"\"\n")
