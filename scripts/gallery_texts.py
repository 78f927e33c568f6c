"""The gallery's texts of one example file, as the page shows them and the translators get
them: its summary (the first comment line, which the viewer shows too: see summaryLine in
src/scene/description.cpp) and its title (the summary's part before " — ")."""


def summary_and_title(text, name):
    first = text.splitlines()[0] if text else ""
    summary = first.lstrip("#").strip() if first.startswith("#") else ""
    title = summary.split(" \u2014 ")[0].split(" - ")[0] if summary else name
    return summary, title
