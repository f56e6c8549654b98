"""Generated sections of the Markdown docs: the text between <!-- BEGIN name --> and <!-- END name -->,
rewritten by the script `name` that measured it."""

from __future__ import annotations

from pathlib import Path


def write_section(doc: Path, section: str, name: str) -> None:
    """Replace the text between the markers of `name` in doc (appended with them if absent)."""
    begin, end = f"<!-- BEGIN {name} -->", f"<!-- END {name} -->"
    text = doc.read_text() if doc.exists() else ""
    block = f"{begin}\n{section.rstrip()}\n{end}"
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        text = head + block + rest.split(end, 1)[1]
    else:
        text = text.rstrip() + "\n\n" + block + "\n"
    doc.write_text(text)
