"""The docs' examples run as printed (docs/first_contact.md, "The docs' examples as printed"): the text is
taken out of README.md and docs/*.md by studies.comparisons.doc_examples, so a doc and its check cannot
drift apart. Light: the short examples run here (the scene listings, the fmpy steady tow against the
steady-tow ODE, the chain mooring against MoorPy's catenary); the long ones (sweeps, the systems, the
step-size runs) run in `bash scripts/first_contact_examples`, and every shell example parses here."""

import subprocess

import pytest

from studies.comparisons import doc_examples as de

# The fmpy steady tow: a straight line at the critical angle, which cubic elements hold exactly, so the
# FMU differs from the ODE by its solver tolerances (test_steady_tow.py: 0.5 %). The chain at rest: the
# FMU's statics check refuses a start more than 1 % from the elastic catenary, the "silently wrong" bound
# of docs/first_contact.md.
TOLERANCE = {"steady-tow ODE": 0.005, "MoorPy catenary": 0.01}


def test_the_docs_examples_are_found():
    found = {(e.doc, e.kind, e.text.split("#")[0].strip()) for e in de.examples()}
    for expected in [("README.md", "shell", "ucable run my.toml --out d"),
                     ("README.md", "shell", "ucable system towed_body --out sys"),
                     ("docs/for_mooring_users.md", "shell", "ucable run chain.toml --out chain"),
                     ("docs/cosimulation.md", "shell", "ucable system towed_body_explicit --master newton --out newton")]:
        assert expected in found, sorted(found)
    kinds = {e.kind for e in de.examples()}
    assert kinds == {"shell", "python", "scene"}, kinds


@pytest.mark.parametrize("example", [e for e in de.examples() if e.kind == "shell"], ids=lambda e: e.label)
def test_every_shell_example_is_a_command_line_as_printed(example):
    """Each parses as a shell line (a comment after `#`, not in parentheses: the cosimulation page's
    explicit-system line did not)."""
    out = subprocess.run(["bash", "-n", "-c", example.text], capture_output=True, text=True)
    assert out.returncode == 0, f"{example.label}: {example.text!r}: {out.stderr}"


def test_the_short_examples_run_as_printed_and_give_the_right_answer(fmu_file):
    data = de.compute(fmu_file, light=True)
    rows = data["examples"]
    assert {r["doc"] for r in rows} >= {"README.md", "docs/for_mooring_users.md"}
    for r in rows:
        assert r["returncode"] == 0, f"{r['doc']}:{r['line']} {r['text']!r}: {r['error']}"
    checked = {r["reference"]: r for r in rows if r.get("reference")}
    assert set(checked) == set(TOLERANCE), checked
    for name, r in checked.items():
        assert r["worst"] <= TOLERANCE[name], f"{r['doc']}:{r['line']}: {r['answer']} against {r['expected']}"
