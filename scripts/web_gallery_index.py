#!/usr/bin/env python3
"""Writes the web page's gallery index (JSON, to stdout) from the examples/ folder: every
.surf file under it as {name, title, summary, formula, image}, thesis surfaces first, then the rest by
name; name is the path without .surf ("thesis/2-cayley-cubic"), summary the file's first
comment line, title its part before " — ", image the picture in examples/images that README.md shows for it."""
import json
import pathlib
import sys
import tomllib

from gallery_texts import summary_and_title

examples = pathlib.Path(sys.argv[1])
entries = []
for path in sorted(examples.glob("thesis/*.surf")) + sorted(examples.glob("*.surf")):
    name = path.relative_to(examples).with_suffix("").as_posix()
    text = path.read_text(encoding="utf-8")
    summary, title = summary_and_title(text, name)
    image = name.replace("/", "-") + ".png"
    if not (examples / "images" / image).exists():
        sys.exit(f"web_gallery_index.py: {path} has no picture examples/images/{image}")
    entries.append({"name": name, "title": title, "summary": summary, "formula": tomllib.loads(text)["formula"],
                    "image": image})
json.dump(entries, sys.stdout, ensure_ascii=False, indent=1)
sys.stdout.write("\n")
