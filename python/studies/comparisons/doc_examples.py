"""Every runnable example of README.md and docs/*.md run literally as printed, as a new user runs it: the
`ucable` command lines of the shell blocks (each block's lines in order, in one empty directory), the
Python blocks, and the README's scene in TOML (run with `ucable run`, the way the README says a scene runs).
The text is taken out of the Markdown here, so the docs and the runs cannot drift apart. Each run must
complete; where an independent reference exists its answer is compared with it:

- the fmpy steady tow: the steady-tow ODE (ucable.steady_tow, scipy, no FMU) at the same speed;
- the chain mooring: MoorPy's elastic catenary with seabed of the same line at the first row (at rest);
- a scene run at its communication step: the same scene at 0.05 s (the step-size question);
- the README's winch scene: the steady-tow ODE with the body's weight as the end load at the final length.

    python -m studies.comparisons.doc_examples [--doc docs/first_contact.md] [--json FILE] [--light]

Computation here; markdown() formats (docs/first_contact.md, "The docs' examples as printed")."""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
FINE_STEP = 0.05  # [s] the reference run of a step-size question


@dataclass
class Example:
    doc: str    # README.md, docs/x.md
    line: int   # of the example in the doc (1-based)
    block: int  # the block's first line: the lines of a block run in order in one directory
    kind: str   # shell, python, scene
    text: str   # as printed

    @property
    def label(self) -> str:
        return f"{self.doc}:{self.line}"


def documents() -> list:
    return [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))


def examples(docs=None) -> list:
    """The runnable examples of the docs, in order: `ucable` lines of ```bash blocks and of indented blocks,
    ```python blocks, and ```toml blocks that are whole scenes (a title and a duration)."""
    out = []
    for path in docs or documents():
        lines = path.read_text().splitlines()
        name = str(path.relative_to(ROOT))
        i = 0
        while i < len(lines):
            fence = re.match(r"^```(\w*)\s*$", lines[i])
            if fence:
                language, start = fence.group(1), i + 1
                j = start
                while j < len(lines) and not lines[j].startswith("```"):
                    j += 1
                body = lines[start:j]
                if language == "bash":
                    out += [Example(name, start + k + 1, start + 1, "shell", text)
                            for k, text in enumerate(body) if text.startswith("ucable ") or text == "ucable"]
                elif language == "python":
                    out.append(Example(name, start + 1, start + 1, "python", "\n".join(body) + "\n"))
                elif language == "toml" and any(t.startswith("title") for t in body) and \
                        any(t.startswith("duration") for t in body):
                    out.append(Example(name, start + 1, start + 1, "scene", "\n".join(body) + "\n"))
                i = j + 1
                continue
            if lines[i].startswith("    ucable ") and (i == 0 or not lines[i - 1].strip()):
                out.append(Example(name, i + 1, i + 1, "shell", lines[i][4:]))
            i += 1
    return out


def is_light(ex: Example) -> bool:
    return ex.kind == "python" or ex.text.startswith(("ucable scenes", "ucable run chain.toml")) or \
        re.fullmatch(r"ucable system\s*(#.*)?", ex.text) is not None


# ------------------------------------------------------------------------------------------- running
def environment(fmu=None, bin_dir: Path | None = None) -> dict:
    """The user's environment: `ucable` on PATH (a clone without `pip install`: a shim that runs the package
    from python/), the FMU under test (UC_FMU) where given."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "python"))
    fmu = fmu or env.get("UC_FMU")
    if fmu:
        env["UC_FMU"] = str(Path(fmu).resolve())  # the examples run elsewhere
    if bin_dir is not None:
        shim = bin_dir / "ucable"
        shim.write_text(f"#!/bin/sh\nexec {sys.executable} -m ucable.cli \"$@\"\n")
        shim.chmod(0o755)
        env["PATH"] = f"{bin_dir}{os.pathsep}{env.get('PATH', '')}"
    return env


def run(ex: Example, cwd: Path, env: dict, timeout: float = 1800.0) -> dict:
    """The example as printed, in cwd: its exit code, output and CPU time."""
    t0 = time.time()
    if ex.kind == "shell":
        cmd = ["bash", "-c", ex.text]
    elif ex.kind == "python":
        cmd = [sys.executable, "-c", ex.text]
    else:  # a scene: written as printed and run as the README runs one
        (cwd / "scene.toml").write_text(ex.text)
        cmd = ["bash", "-c", "ucable run scene.toml --out scene"]
    p = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    return {"returncode": p.returncode, "stdout": p.stdout, "stderr": p.stderr, "wall": time.time() - t0}


def read_csv(path: Path) -> dict:
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0] for h in rows[0]]
    return {h: [float(r[k]) for r in rows[1:]] for k, h in enumerate(head)}


# ------------------------------------------------------------------------------------------- references
def fmpy_reference(out: str) -> dict | None:
    """The README's fmpy steady tow (2.4 kn, the default cable, free end) against the steady-tow ODE."""
    from ucable.steady_tow import solve_steady_tow

    m = re.search(r"tow tension (\d+) N, end depth ([\d.]+) m", out)
    if not m:
        return None
    ref = solve_steady_tow(2.4 * 1852 / 3600)
    T, depth = float(m.group(1)), float(m.group(2))
    return {"reference": "steady-tow ODE", "set": "tow.x/vx/ax at 2.4 kn, 60 s",
            "answer": f"towTension {T:.0f} N, end depth {depth:.1f} m",
            "expected": f"{ref.top_tension:.0f} N, {ref.end_depth:.1f} m",
            "difference": f"{100 * (T / ref.top_tension - 1):+.2f} % / {depth - ref.end_depth:+.2f} m",
            "worst": max(abs(T / ref.top_tension - 1), abs(depth - ref.end_depth) / 300.0)}


def scene_parameters(path: Path) -> dict:
    import tomllib

    return tomllib.loads(path.read_text())


def chain_reference(scene: Path, result: Path) -> dict:
    """The chain mooring at rest (the first row) against MoorPy's elastic catenary with a frictionless seabed."""
    from moorpy.Catenary import catenary

    s = scene_parameters(scene)
    p = s["parameters"]
    tow = s["tow"]["start"]
    d, rho, g = p["diameter"], 1025.0, 9.80665
    w = (p["massPerLength"] - rho * math.pi * d * d / 4) * g
    XF, ZF = abs(tow[0] - p["anchor.x"]), tow[2] - p["anchor.z"]
    fAH, fAV, fBH, fBV, _ = catenary(XF, ZF, p["length"], p["EA"], w, CB=0.0)
    top, anchor = math.hypot(fBH, fBV), math.hypot(fAH, fAV)
    r = read_csv(result)
    T, E = r["towTension"][0], r["endTension"][0]
    return {"reference": "MoorPy catenary", "set": "the scene chain_mooring as shipped",
            "answer": f"fairlead {T / 1e3:.2f} kN, anchor {E / 1e3:.2f} kN",
            "expected": f"{top / 1e3:.2f} kN, {anchor / 1e3:.2f} kN",
            "difference": f"{100 * (T / top - 1):+.3f} % / {100 * (E / anchor - 1):+.3f} %",
            "worst": max(abs(T / top - 1), abs(E / anchor - 1))}


def step_reference(scene: Path, result: Path, env: dict, cwd: Path) -> dict:
    """A scene's tow tension at its communication step against the same scene at FINE_STEP."""
    text = re.sub(r"^step\s*=.*$", f"step = {FINE_STEP}", scene.read_text(), count=1, flags=re.M)
    fine_scene = cwd / "fine.toml"
    fine_scene.write_text(text)
    p = subprocess.run(["bash", "-c", "ucable run fine.toml --out fine"], cwd=cwd, env=env, capture_output=True,
                       text=True, timeout=3600)
    if p.returncode != 0:
        return {"reference": f"{FINE_STEP} s run", "difference": f"the fine run failed: {p.stderr[-300:]}",
                "worst": None}
    coarse, fine = read_csv(result), read_csv(cwd / "fine" / "result.csv")
    at = {round(t, 9): v for t, v in zip(fine["time"], fine["towTension"])}
    pairs = [(v, at[round(t, 9)]) for t, v in zip(coarse["time"], coarse["towTension"]) if round(t, 9) in at]
    span = max(f for _, f in pairs) - min(f for _, f in pairs)
    worst = max(abs(c - f) for c, f in pairs)
    tension = max(abs(f) for _, f in pairs)
    step = scene_parameters(scene)["step"]
    return {"reference": f"the scene at {FINE_STEP} s", "set": f"step = {step} s",
            "answer": f"towTension {min(c for c, _ in pairs):.0f}-{max(c for c, _ in pairs):.0f} N",
            "expected": f"{min(f for _, f in pairs):.0f}-{max(f for _, f in pairs):.0f} N",
            "difference": f"largest {worst:.1f} N: {100 * worst / tension:.2f} % of the tension, "
                          f"{100 * worst / max(span, 1e-9):.1f} % of its range",
            "worst": worst / tension}


def winch_reference(scene: Path, result: Path) -> dict:
    """The README's winch scene at its end (the body paid out to its final length, held 210 s) against the
    steady-tow ODE of that length with the body's weight in water as the end load."""
    from ucable.steady_tow import CableProperties, body_end_load, solve_steady_tow

    s = scene_parameters(scene)
    p = s["parameters"]
    r = read_csv(result)
    length = r["unstretchedLength"][-1]
    V = s["tow"]["speed_kn"] * 1852 / 3600
    ref = solve_steady_tow(V, CableProperties(length=length),
                           end_load=body_end_load(V, p.get("body.mass", 0.0), p.get("body.volume", 0.0),
                                                  p.get("body.CdA", 0.0)))
    T = r["towTension"][-1]
    return {"reference": "steady-tow ODE", "set": f"length {p['length']:g} m paid out to {length:.1f} m, "
            f"body.mass {p.get('body.mass', 0):g} kg, {s['tow']['speed_kn']:g} kn",
            "answer": f"towTension {T:.0f} N at {r['time'][-1]:g} s", "expected": f"{ref.top_tension:.0f} N",
            "difference": f"{100 * (T / ref.top_tension - 1):+.2f} %", "worst": abs(T / ref.top_tension - 1)}


def user_set(ex: Example) -> str:
    """What the user chose in the example: a command's arguments (without its comment), a scene's title."""
    if ex.kind == "shell":
        words = ex.text.split("#")[0].split()[2:]
        return " ".join(words).replace("|", "/")
    return ""


def sweep_runs(text: str, cwd: Path) -> dict:
    """A sweep's table against the runs its --vary options ask for (their product)."""
    expected = 1
    for values in re.findall(r"--vary \"?[^=\s]+=([^\s\"]+)", text):
        expected *= len(values.split(","))
    out = re.search(r"--out (\S+)", text)
    with open(cwd / out.group(1) / "results.csv", newline="") as f:
        rows = len(list(csv.reader(f))) - 1
    return {"reference": "the --vary product", "answer": f"{rows} runs in results.csv", "expected": f"{expected} runs",
            "difference": f"{rows - expected:+d} runs", "worst": abs(rows - expected)}


def final_answer(text: str, cwd: Path) -> dict:
    """A run's or system's last tow tension (no reference)."""
    out = re.search(r"--out (\S+)", text)
    path = cwd / out.group(1) / "result.csv" if out else None
    if path is None or not path.is_file():
        return {}
    r = read_csv(path)
    return {"answer": f"towTension {r['towTension'][-1]:.0f} N at {r['time'][-1]:g} s"}


def check(ex: Example, out: dict, cwd: Path, env: dict, references: bool) -> dict:
    """What the example's answer is, against its reference where one exists."""
    if out["returncode"] != 0:
        return {}
    text = ex.text
    if text.startswith("ucable sweep"):
        return sweep_runs(text, cwd)
    if ex.kind == "python" and "simulate_fmu" in text and "tow tension" in text:
        return fmpy_reference(out["stdout"]) or {}
    if not references:
        return {}
    if text.startswith("ucable run chain.toml"):
        return chain_reference(cwd / "chain.toml", cwd / "chain" / "result.csv")
    if text.startswith("ucable run my.toml"):
        return step_reference(cwd / "my.toml", cwd / "d" / "result.csv", env, cwd)
    if ex.kind == "scene" and "[winch]" in text:
        return winch_reference(cwd / "scene.toml", cwd / "scene" / "result.csv")
    return final_answer(text, cwd)


def compute(fmu=None, light: bool = False, references: bool = True, progress=None) -> dict:
    """Every example (light: only those the CI test runs) as printed, each block in its own directory."""
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        bin_dir = tmp / "bin"
        bin_dir.mkdir()
        env = environment(fmu, bin_dir)
        dirs = {}
        for ex in examples():
            if light and not is_light(ex):
                continue
            if progress:
                progress(ex.label)
            cwd = dirs.setdefault((ex.doc, ex.block), tmp / f"run{len(dirs)}")
            cwd.mkdir(exist_ok=True)
            out = run(ex, cwd, env)
            r = {**asdict(ex), "set": user_set(ex), "returncode": out["returncode"], "wall": out["wall"],
                 "error": out["stderr"].strip().splitlines()[-1] if out["returncode"] and out["stderr"].strip() else "",
                 **check(ex, out, cwd, env, references)}
            r["verdict"] = ("fails" if out["returncode"] else "no reference" if r.get("worst") is None
                            else "ok" if r["worst"] <= 0.01 else "off by more than 1 %")
            results.append(r)
    return {"examples": results}


# ------------------------------------------------------------------------------------------- report
def markdown(data: dict) -> str:
    rows = data["examples"]
    failed = [r for r in rows if r["verdict"] == "fails"]
    off = [r for r in rows if r["verdict"] == "off by more than 1 %"]
    out = [f"{len(rows)} examples of README.md and docs/*.md run as printed: **{len(failed)}** fail, "
           f"**{len(off)}** more than 1 % from their reference.", "",
           "| example | as printed | user set | answer | reference | difference | verdict | wall [s] |",
           "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        shown = r["text"].strip().splitlines()[0] if r["kind"] != "scene" else "(the scene in TOML) " + \
            r["text"].strip().splitlines()[0]
        shown = shown.replace("|", "\\|")
        if r["kind"] == "python":
            shown = "(Python) " + shown
        answer = r.get("answer", "") if not r["returncode"] else f"exit {r['returncode']}: {r['error'][:120]}"
        ref = r.get("reference", "")
        if r.get("expected"):
            ref += f": {r['expected']}"
        out.append(f"| `{r['doc']}:{r['line']}` | `{shown[:110]}` | {r.get('set', '')} | {answer.replace('|', '/')} | "
                   f"{ref} | {r.get('difference', '')} | {r['verdict']} | {r['wall']:.1f} |")
    return "\n".join(out)


def main(argv=None) -> int:  # pragma: no cover
    from ..doc_section import add_report_options

    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_report_options(ap, "doc_examples", "UC_FMU, else the package's or the build's")
    ap.add_argument("--light", action="store_true", help="only the examples the CI test runs")
    ap.add_argument("--no-references", action="store_true", help="run the examples without the reference runs")
    args = ap.parse_args(argv)
    data = compute(args.fmu, args.light, not args.no_references,
                   progress=lambda label: print(label, file=sys.stderr, flush=True))
    text = markdown(data)
    if args.json:
        args.json.write_text(json.dumps(data, indent=1))
    if args.doc:
        from ..doc_section import write_section
        write_section(args.doc, text, "doc_examples")
    print(text)
    return 1 if any(r["verdict"] != "ok" and r["verdict"] != "no reference" for r in data["examples"]) else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
