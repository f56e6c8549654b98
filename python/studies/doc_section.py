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


def add_report_options(parser, name: str, fmu_default: str = "the build's") -> None:
    """--fmu, --doc (the section `name` of a Markdown file) and --json of a script that writes a generated section."""
    parser.add_argument("--fmu", type=Path, default=None, help=f"the FMU (default: {fmu_default})")
    parser.add_argument("--doc", type=Path, help="write the section into this Markdown file (between "
                        f"<!-- BEGIN {name} --> and <!-- END {name} -->)")
    parser.add_argument("--json", type=Path, help="also write the numbers as JSON")


def write_json(path: Path, data) -> None:
    """The numbers of a report as JSON, arrays as lists."""
    import json

    path.write_text(json.dumps(data, indent=1, default=lambda x: x.tolist() if hasattr(x, "tolist") else str(x)))


def publish(text: str, name: str, doc: Path | None = None, json_path: Path | None = None, data=None) -> None:
    """A report's outputs: its numbers as JSON (arrays as lists) to json_path, its section `name` into doc, the
    text to stdout."""
    if json_path:
        write_json(json_path, data)
    if doc:
        write_section(doc, text, name)
    print(text)


def bench_main(argv, name: str, description: str, quick_help: str, compute, markdown) -> int:
    """The command line of a scripts/<name> benchmark that prints a table: --quick, --fmu, --doc (the section `name`
    of a Markdown file); compute(fmu, quick=...) measures, markdown(data) writes the table."""
    import argparse

    from ucable.paths import fmu_path

    p = argparse.ArgumentParser(prog=f"scripts/{name}", description=description)
    p.add_argument("--quick", action="store_true", help=quick_help)
    p.add_argument("--fmu", type=Path, default=None)
    p.add_argument("--doc", type=Path, default=None,
                   help=f"also write the table into this Markdown file (between its {name} markers)")
    args = p.parse_args(argv)
    table = markdown(compute(args.fmu or fmu_path(), quick=args.quick))
    print(table)
    if args.doc:
        write_section(args.doc, table, name)
    return 0
