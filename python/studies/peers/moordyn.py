"""MoorDyn v2 (PyPI `moordyn`), the peer the studies run beside the FMU: the one place that creates,
initialises, steps, reads and closes a MoorDyn system.

MoorDyn writes its output files next to its input file and reads wave_frequencies.txt and
current_profile.txt next to it or in the working directory, so a System lives in a temporary
directory of its own; MoorDyn writes to the process's stdout and stderr directly, so it is silenced
(peers.quiet).

`moordyn` is imported where it is used, never when this module is: loaded after MoorPy or the FMU's
modules, MoorDyn 2.7's Create crashes at random on some decks (a segmentation fault), so `release`
runs it in a process of its own that loads nothing else (a self-contained script).
"""

from __future__ import annotations

import functools
import math
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from .quiet import Quiet


class System:
    """A MoorDyn system (moordyn.Create) in a temporary directory, closed at the end (a context manager).

    deck: an input file copied there, `also` the files MoorDyn reads next to it (current_profile.txt);
    or write(directory) writes the input file (and its companions) there and returns its path.
    chdir: the working directory is the temporary one while the system lives (MoorDyn reads some
    companions from there). init: (x, v) of the coupled points for moordyn.Init at the start.
    quiet: "all" silences MoorDyn's console from Create to Close, "setup" only Create, Init and
    Close (a caller's progress output stays visible)."""

    def __init__(self, deck: Path | None = None, *, also=(), write=None, chdir: bool = False, init=None,
                 quiet: str = "all"):
        self.deck, self.also, self.write, self.chdir, self.init_state = deck, tuple(also), write, chdir, init
        self.quiet = quiet

    def __enter__(self):
        import moordyn

        self.api = moordyn
        self._tmp = tempfile.TemporaryDirectory()
        tmp = Path(self._tmp.name)
        self._cwd = os.getcwd() if self.chdir else None
        self._quiet = None
        try:
            if self.write is not None:
                path = Path(self.write(tmp))
            else:
                for f in (self.deck, *self.also):
                    shutil.copy(f, tmp / Path(f).name)
                path = tmp / Path(self.deck).name
            if self.chdir:
                os.chdir(tmp)
            self._quiet = Quiet().__enter__()
            self.system = moordyn.Create(str(path))
            try:
                if self.init_state is not None:
                    self.init(*self.init_state)
            except BaseException:
                moordyn.Close(self.system)
                raise
            if self.quiet != "all":
                self._quiet.__exit__(None, None, None)
                self._quiet = None
        except BaseException:
            self._leave()
            raise
        self.step_raw = functools.partial(moordyn.Step, self.system)  # (x, v, t, h) -> forces, for hot loops
        return self

    def __exit__(self, *exc):
        try:
            if self._quiet is None:
                with Quiet():
                    self.api.Close(self.system)
            else:
                self.api.Close(self.system)
        finally:
            self._leave()

    def _leave(self):
        if self._quiet is not None:
            self._quiet.__exit__(None, None, None)
            self._quiet = None
        if self._cwd is not None:
            os.chdir(self._cwd)
        self._tmp.cleanup()

    # ------------------------------------------------------------------------- driving
    def init(self, x, v, no_ic: bool = False) -> None:
        """moordyn.Init at the coupled points' (x, v); no_ic: Init_NoIC (no initial-condition solve)."""
        if self._quiet is None:
            with Quiet():
                (self.api.Init_NoIC if no_ic else self.api.Init)(self.system, x, v)
        else:
            (self.api.Init_NoIC if no_ic else self.api.Init)(self.system, x, v)

    def step(self, x, v, t: float, h: float):
        """moordyn.Step from t by h (whole dtM steps), the coupled points moving linearly from (x, v):
        the forces on them at the end."""
        return self.api.Step(self.system, x, v, t, h)

    # ------------------------------------------------------------------------- reading
    def lines(self) -> int:
        return self.api.GetNumberLines(self.system)

    def line(self, k: int):
        """Line k (from 1)."""
        return self.api.GetLine(self.system, k)

    def segments(self, line) -> int:
        return self.api.GetLineN(line)

    def node_position(self, line, i: int) -> np.ndarray:
        return self.api.GetLineNodePos(line, i)

    def node_tension(self, line, i: int):
        """The tension vector of segment i (node 0 is end A): MoorDyn's tensions are its segments'."""
        return self.api.GetLineNodeTen(line, i)

    def point(self, k: int):
        """Point k (from 1)."""
        return self.api.GetPoint(self.system, k)

    def point_position(self, point):
        return self.api.GetPointPos(point)

    def wave_kinematics(self, x: float, y: float, z: float):
        """The water's velocity, acceleration and elevation at a point at MoorDyn's present time."""
        u, a, zeta, _ = self.api.GetWavesKin(self.api.GetWaves(self.system), x, y, z)
        return np.array(u), np.array(a), float(zeta)

    def tension_at(self, position) -> float:
        """|tension| of the end segment of the line end at `position` (an anchor)."""
        found = None
        for k in range(1, self.lines() + 1):
            line = self.line(k)
            n = self.segments(line)
            for node in (0, n):
                if np.allclose(self.node_position(line, node), position, atol=1e-6):
                    found = line, node
        return float(np.linalg.norm(self.node_tension(*found)))

    def end_b_tension(self, line) -> float:
        """The tension at a line's end B: MoorDyn's tensions are its segments', half a segment from the
        end node, so it is extrapolated linearly from the last two segments (node N - 1 has their mean)."""
        n = self.segments(line)
        return 2.0 * np.linalg.norm(self.node_tension(line, n)) - np.linalg.norm(self.node_tension(line, n - 1))

    def set_line_nodes(self, line, n_seg: int, shape) -> None:
        """Start the line at rest in the given shape (3, stations; station 0 at end B, the tow point).

        MoorDyn 2.7 has no API to set node positions and its initial-condition solver ignores
        currents; moordyn.Init_NoIC places a uniformly stretched straight line whose axial snap at the
        free end (~c eps = 0.3 m/s) excites a drag-damped mode with a 240 s time constant (measured:
        1.2 m end-position error after 300 s). So the node positions are written into MoorDyn's own
        serialized state (each internal node's coordinates replaced where they occur) and read back
        through moordyn.Deserialize; the result is checked with GetLineNodePos."""
        data = np.frombuffer(bytes(self.api.Serialize(self.system)), dtype=np.float64).copy()
        stations = np.linspace(0.0, 1.0, shape.shape[1])
        targets = {}
        for i in range(1, n_seg):
            u = 1.0 - i / n_seg  # MoorDyn node 0 is the free end (our s = L), node N the tow point
            q = np.array(self.node_position(line, i))
            new = np.array([np.interp(u, stations, shape[d]) for d in range(3)])
            hit = np.where((data[:-2] == q[0]) & (data[1:-1] == q[1]) & (data[2:] == q[2]))[0]
            if len(hit) == 0:
                raise RuntimeError("MoorDyn state layout not recognized (node position not found)")
            for j in hit:
                data[j:j + 3] = new
            targets[i] = new
        self.api.Deserialize(self.system, data.tobytes())
        for i, new in targets.items():
            got = np.array(self.node_position(line, i))
            if np.max(np.abs(got - new)) > 1e-9:
                raise RuntimeError(f"MoorDyn node {i} not set from the serialized state: {got} != {new}")


def drive(md: System, start, n: int, comm_step: float, calls: int, coupled, record, progress=None,
          whole_steps: bool = False) -> float:
    """Drive an initialised system from t = 0: the forces of its state at `start` = (x, v) (a step of
    1e-12 s: MoorDyn returns the forces of the state it ends in) to record(0, f), then n communication
    steps of comm_step, each `calls` calls of moordyn.Step by comm_step / calls with the coupled points
    at coupled(t) = (x, v) at the start of the call (MoorDyn moves them linearly from there); after
    step k record(k, f) and progress(k comm_step). The calls' start times add up their steps
    (whole_steps: one call a step, starting at k comm_step). Returns the CPU time of the n steps."""
    record(0, md.step(*start, 0.0, 1e-12))
    h = comm_step / calls
    cpu0 = time.process_time()
    t = 0.0
    for k in range(n):
        if whole_steps:
            x, v = coupled(k * comm_step)
            f = md.step(x, v, k * comm_step, comm_step)
        else:
            for _ in range(calls):
                x, v = coupled(t)
                f = md.step(x, v, t, h)
                t += h
        record(k + 1, f)
        if progress:
            progress((k + 1) * comm_step)
    return time.process_time() - cpu0


# ----------------------------------------------------------------------------- a process of its own
# The child's whole program: moordyn and numpy only, nothing of this package (the release runs crashed with a
# segmentation fault in the full test suite when the child ran this module with `-m`, which the
# self-contained script never did). Its input: a JSON file (see driven()); its output: an npz file.
_DRIVE_SCRIPT = r"""
import json, os, shutil, sys, tempfile, time
from pathlib import Path
import numpy as np
import moordyn

spec = json.loads(Path(sys.argv[1]).read_text())
h, calls, n, out = spec["h"], spec["calls"], spec["n"], spec["out"]
shift = np.load(spec["motion"]) if spec.get("motion") else np.zeros((2, n * calls))  # x offset, x velocity
times = np.arange(n + 1) * h
result = {"t": times, "cpu_init": 0.0, "cpu": 0.0, "error": "", "layout": "", "reached": 0.0}


def save():
    np.savez(out, **result)


with tempfile.TemporaryDirectory() as tmp:
    base = Path(spec["base"])
    shutil.copytree(base, Path(tmp) / base.name)
    deck = Path(tmp) / base.name / spec["deck"]
    if spec.get("text") is not None:
        deck.write_text(spec["text"])
    os.chdir(tmp)  # MoorDyn reads a SeafloorFile from the working directory, its wave files beside the deck
    system = moordyn.Create(str(deck))
    n_lines, n_points = moordyn.GetNumberLines(system), moordyn.GetNumberPoints(system)
    lines = [moordyn.GetLine(system, k) for k in range(1, n_lines + 1)]
    ends = [moordyn.GetLineN(ln) for ln in lines]
    # the coupled degrees of freedom in MoorDyn's order (bodies, rods, points) and which of them are x
    x0, xdof, layout = [], [], []
    for k in range(1, moordyn.GetNumberBodies(system) + 1):
        kind = moordyn.GetBodyType(moordyn.GetBody(system, k))
        if kind in (-1, 2):  # coupled: 6 values; coupled pinned: its position (3 read, 6 counted)
            r = list(moordyn.GetBodyState(moordyn.GetBody(system, k))[0])
            xdof.append(len(x0))
            x0 += r[:6] if kind == -1 else r[:3] + [0.0, 0.0, 0.0]
            layout.append(f"body {k}" + (" (pinned)" if kind == 2 else ""))
    for k in range(1, moordyn.GetNumberRods(system) + 1):
        if moordyn.GetRodType(moordyn.GetRod(system, k)) < 0:
            result["error"] = f"rod {k} is coupled: its motion is not driven here"
    for k in range(1, n_points + 1):
        if moordyn.GetPointType(moordyn.GetPoint(system, k)) == -1:
            xdof.append(len(x0))
            x0 += list(moordyn.GetPointPos(moordyn.GetPoint(system, k)))
            layout.append(f"point {k}")
    result["layout"] = ", ".join(layout)
    # each point's lines: (line, end) pairs, end 0 = A, 1 = B, as "p:l.e l.e;..."
    result["attached"] = ";".join(
        " ".join(f"{moordyn.GetLineID(ln)}.{e}" for ln, e in (moordyn.GetPointAttached(moordyn.GetPoint(system, k), i)
                                                          for i in range(moordyn.GetPointNAttached(moordyn.GetPoint(system, k)))))
        for k in range(1, n_points + 1))
    if not result["error"] and len(x0) != moordyn.NCoupledDOF(system):
        result["error"] = f"{moordyn.NCoupledDOF(system)} coupled values, {len(x0)} found"
    if result["error"]:
        save()
        sys.exit(0)
    points = spec.get("points", [])
    tension = np.full((2, n + 1, n_lines), np.nan)
    position = np.full((n + 1, len(points), 3), np.nan)

    def record(i):
        # MoorDyn's tensions are its segments', half a segment from the end node: extrapolated linearly
        # from the last two segments (the next node has their mean) to the end node
        for j, (ln, m) in enumerate(zip(lines, ends)):
            a = [np.linalg.norm(moordyn.GetLineNodeTen(ln, node)) for node in (0, min(1, m), max(m - 1, 0), m)]
            tension[0, i, j], tension[1, i, j] = 2.0 * a[0] - a[1], 2.0 * a[3] - a[2]
        for j, k in enumerate(points):
            position[i, j] = moordyn.GetPointPos(moordyn.GetPoint(system, k))

    def coupled(c):
        x = list(x0)
        for d in xdof:
            x[d] += float(shift[0][c]) if c >= 0 else 0.0
        v = [0.0] * len(x0)
        for d in xdof:
            v[d] = float(shift[1][c]) if c >= 0 else 0.0
        return x, v

    try:
        cpu0 = time.process_time()
        moordyn.Init(system, *coupled(-1))
        result["cpu_init"] = time.process_time() - cpu0
        moordyn.Step(system, *coupled(-1), 0.0, 1e-12)  # the forces of the state Init ends in
        record(0)
        cpu0 = time.process_time()
        sub = h / calls
        for k in range(n):
            for c in range(calls):
                moordyn.Step(system, *coupled(k * calls + c), times[k] + c * sub, sub)
            record(k + 1)
            if not np.all(np.isfinite(tension[:, k + 1])):
                raise FloatingPointError("its tensions are not finite")
            result["reached"] = times[k + 1]
        result["cpu"] = time.process_time() - cpu0
    except Exception as e:  # MoorDyn's failure is a result
        result["error"] = f"{type(e).__name__}: {e} (at t = {result['reached']:g} s)"
    result.update(tension=tension, position=position)
    moordyn.Close(system)
save()
"""


def driven(deck: Path, h: float, n: int, *, base: Path | None = None, text: str | None = None, calls: int = 1,
           shift=None, points=(), timeout: float | None = None) -> dict:
    """MoorDyn fed a deck in a process that loads nothing else (loaded after MoorPy or the FMU's modules,
    MoorDyn 2.7's Create crashes at random on some decks), n communication steps of h, each `calls` calls
    of moordyn.Step (MoorDyn substepping at dtM within a call, moving its coupled points linearly from the
    call's start).

    base: the folder copied beside it (default the deck's own; the working directory is its parent copy:
    MoorDyn reads a SeafloorFile from there, its wave and current files beside the deck); text: the deck's
    text replacing the copy's (a fileIC it names that is not there is left out: MoorDyn 2.7 fails then). Every coupled degree of freedom of x (bodies, points) moves by
    shift = (offset, velocity) along x, arrays of n calls values at the calls' starts (None: held at the deck's
    positions); timeout: the limit of its CPU time [s]. Returns t, tension (2, times, lines: each line's tension at end A and end B), position
    (times, points, 3) of the 1-based `points`, cpu_init (moordyn.Init: its initial-condition generation),
    cpu (the steps), layout (the coupled objects), attached (per point its "line.end" pairs, end 0 = A),
    error ("" or why MoorDyn stopped: the arrays hold NaN from there; a crash or the timeout is one too)."""
    import json
    import subprocess

    import re

    deck = Path(deck).resolve()
    base = Path(base).resolve() if base is not None else deck.parent
    ic = re.search(r"^\s*(\S+)\s+fileIC\b", text if text is not None else deck.read_text(errors="replace"),
                   flags=re.M | re.I)
    if ic and not any((d / ic.group(1)).is_file() for d in (deck.parent, base.parent)):
        # MoorDyn 2.7 logs that it cannot read a missing fileIC, then fails writing its first outputs: left out,
        # MoorDyn makes its initial conditions itself
        text = (text if text is not None else deck.read_text(errors="replace")).replace(ic.group(0), "", 1)
    with tempfile.TemporaryDirectory() as tmp:
        spec = {"deck": str(deck.relative_to(base)), "base": str(base), "text": text, "h": h, "n": int(n),
                "calls": int(calls), "points": list(points), "out": str(Path(tmp) / "moordyn.npz")}
        if shift is not None:
            np.save(Path(tmp) / "motion.npy", np.asarray(shift, float))
            spec["motion"] = str(Path(tmp) / "motion.npy")
        (Path(tmp) / "spec.json").write_text(json.dumps(spec))
        def limit():  # the CPU time of the child, not the wall clock: the machine may be shared
            import resource
            resource.setrlimit(resource.RLIMIT_CPU, (math.ceil(timeout), math.ceil(timeout) + 5))

        run = subprocess.run([sys.executable, "-c", _DRIVE_SCRIPT, str(Path(tmp) / "spec.json")],
                             capture_output=True, preexec_fn=limit if timeout else None)
        if not Path(spec["out"]).exists():
            import signal

            if run.returncode in (-signal.SIGXCPU, -signal.SIGKILL) and timeout:
                return {"error": f"not done within {timeout:g} s of CPU"}
            said = (run.stderr or run.stdout).decode(errors="replace").strip().splitlines()
            how = f"signal {-run.returncode}" if run.returncode < 0 else f"exit status {run.returncode}"
            return {"error": f"MoorDyn's process ended ({how})" + (f": {said[-1]}" if said else "")}
        with np.load(spec["out"]) as data:
            out = {k: data[k] for k in data.files}
    for k in ("cpu", "cpu_init", "reached"):
        out[k] = float(out[k])
    for k in ("error", "layout", "attached"):
        out[k] = str(out[k]) if k in out else ""
    return out


def release(deck: Path, point: int, n_lines: int, t_end: float, h: float) -> dict:
    """MoorDyn fed the deck, no coupled objects, one call per h (MoorDyn substepping at dtM), in a
    process that loads nothing else (driven): each line's tension at its end B and point `point`'s position at
    t = 0, h, 2 h, ... and the CPU time of the steps."""
    run = driven(deck, h, int(round(t_end / h)), points=[point])
    if run["error"]:
        raise RuntimeError(f"MoorDyn on {deck}: {run['error']}")
    return {"t": run["t"], "tension": run["tension"][1][:, :n_lines], "position": run["position"][:, 0],
            "cpu": run["cpu"]}
