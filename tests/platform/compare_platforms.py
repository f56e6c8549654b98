#!/usr/bin/env python3
"""Runs the FMU's scenes with the linux64 and the win64 binaries (under wine64) and compares the results;
restores the states each platform saved on the other (docs/platforms.md).

Scenes whose physics uses only IEEE arithmetic and square roots (the Hopland tow, the winch) must give the
same bytes; scenes that call the C library's transcendental functions (waves, the catenary start of a
mooring) must agree within the integrator's error control. Every check prints one line; the exit code is 1
when any check fails, with the first disagreeing output, its time and both values. Used by ctest
(win64_results_match_linux64); standard library only.
"""
import argparse
import os
import shutil
import struct
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

MAGIC = b"UCDRIVE1"


def read_result(path):
    """(names, rows): the outputs' names and the raw bytes of each row (time + outputs)."""
    data = Path(path).read_bytes()
    if data[:8] != MAGIC:
        raise ValueError(f"{path}: not a driver result")
    n, names_size = struct.unpack_from("<II", data, 8)
    names = data[16:16 + names_size].decode().split("\0")[:-1]
    body = data[16 + names_size:]
    width = 8 * (n + 1)
    if len(names) != n or len(body) % width:
        raise ValueError(f"{path}: truncated")
    return names, [body[k:k + width] for k in range(0, len(body), width)]


# Outputs computed from the state by the C library's acos, asin and atan2 (src/line/outputs.cpp): glibc and
# MinGW-w64's runtime each return a result within 1 ulp of the exact value, so the two may differ by 2 ulps.
ANGLES = ("topDeclination", "topAzimuth", "anchorUplift")
ANGLE_ULPS = 2


def ulps_apart(x, y):
    a, b = (struct.unpack("<q", struct.pack("<d", v))[0] for v in (x, y))
    return abs(a - b) if (a < 0) == (b < 0) else abs(a) + abs(b)


class Exact:
    """Every output the same bytes, the angle outputs within ANGLE_ULPS."""
    def __init__(self):
        self.angle_ulps = 0

    def summary(self):
        return f"the same bytes (angles up to {self.angle_ulps} ulp apart)" if self.angle_ulps else "the same bytes"

    def __call__(self, name, x, y, row_a):
        if name in ANGLES:
            self.angle_ulps = max(self.angle_ulps, ulps_apart(x, y))
            return ulps_apart(x, y) <= ANGLE_ULPS
        return struct.pack("<d", x) == struct.pack("<d", y)


class WithinErrorControl:
    """Scenes whose physics calls the C library's exp, sin, cos, sinh, asinh (waves, the catenary start):
    both platforms solve the same equations within the integrator's error control, so forces agree to twice
    the tension tolerance (tensionTolerance x solver.tensionScale) and positions to twice positionTolerance
    (docs/error_control.md); the other outputs (curvatures, the solver's counters) are not compared."""
    FORCES = ("towForce.", "towTension", "endForce.", "endTension", "tension[", "minTension")
    POSITIONS = ("shape.", "endPosition.")

    def __init__(self, tension_tolerance, position_tolerance, names):
        self.tension, self.position = tension_tolerance, position_tolerance
        self.scale = names.index("solver.tensionScale") + 1
        self.worst = {}

    def __call__(self, name, x, y, row_a):
        if name.startswith(self.FORCES):
            bound = 2.0 * self.tension * row_a[self.scale]
        elif name.startswith(self.POSITIONS):
            bound = 2.0 * self.position
        else:
            return True
        share = abs(x - y) / bound
        self.worst[name] = max(self.worst.get(name, 0.0), share)
        return share <= 1.0

    def summary(self):
        if not self.worst:
            return "the same bytes"
        name = max(self.worst, key=self.worst.get)
        return f"within the error control (largest: {name} at {self.worst[name]:.1e} of its bound)"


def first_difference(a_path, b_path, checker_for, skip=0):
    """(None or a line that names the first disagreement, the checker): b's rows agree with a's rows from
    row `skip` on when checker(name, x, y, row of a) holds for every output and the times are the same
    bytes; checker_for(names) makes the checker."""
    names, a = read_result(a_path)
    names_b, b = read_result(b_path)
    agree = checker_for(names)
    if names != names_b:
        return "the outputs differ in name or order", agree
    a = a[skip:]
    if len(a) != len(b):
        return f"{len(a)} against {len(b)} communication points", agree
    for x, y in zip(a, b):
        if x == y:
            continue
        vx, vy = struct.unpack(f"<{len(x) // 8}d", x), struct.unpack(f"<{len(y) // 8}d", y)
        if x[:8] != y[:8]:
            return f"times {vx[0]!r} and {vy[0]!r}", agree
        for col in range(1, len(vx)):
            if not agree(names[col - 1], vx[col], vy[col], vx):
                return (f"first at t = {vx[0]!r}: {names[col - 1]} = {vx[col]!r} against {vy[col]!r} "
                        f"({len(a)} points)", agree)
    return None, agree


class Runner:
    def __init__(self, args):
        self.args = args
        self.work = Path(args.work).resolve()
        self.work.mkdir(parents=True, exist_ok=True)
        self.env = dict(os.environ, WINEPREFIX=str(self.work / "wine-prefix"), WINEDEBUG="-all",
                        WINEDLLOVERRIDES="mscoree,mshtml=")
        self.env.pop("DISPLAY", None)
        self.failures = 0

    def run(self, platform, scene, out, *extra, cwd=None, fmi3=False):
        a, prefix = self.args, "fmi3_" if fmi3 else ""
        driver, library = (getattr(a, f"{prefix}{platform}_{x}") for x in ("driver", "library"))
        command = [driver, library] if platform == "linux64" else [a.wine, driver, library]
        command += [scene, str(out), *map(str, extra)]
        started = time.monotonic()
        done = subprocess.run(command, cwd=cwd or self.work, env=self.env, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"{platform} {scene} failed ({done.returncode}): {' '.join(command)}\n{done.stderr}")
        return time.monotonic() - started

    def report(self, what, difference, seconds=None):
        timing = f" ({seconds:.1f} s)" if seconds is not None else ""
        if isinstance(difference, tuple):
            difference, checker = difference
            agreed = checker.summary()
        else:
            agreed = "the same bytes"
        if difference is None:
            print(f"{agreed}: {what}{timing}", flush=True)
        else:
            self.failures += 1
            print(f"DIFFERENT: {what}: {difference}", flush=True)


def exact(names):
    return Exact()


def compare_scene(r, scene, checker_for, linux=((), None), variants=(((), None),)):
    """Runs scene on linux64 once and on win64 for each (extra args, cwd) variant; each agrees with linux64."""
    result = r.work / f"{scene}.linux64.bin"
    r.run("linux64", scene, result, *linux[0], cwd=linux[1])
    for k, (extra, cwd) in enumerate(variants):
        win = r.work / f"{scene}.{k}.win64.bin"
        seconds = r.run("win64", scene, win, *extra, cwd=cwd)
        label = f"{scene} {' '.join(map(str, extra))}".strip()
        r.report(f"{label}, win64 against linux64", first_difference(result, win, checker_for), seconds)


def compare_states(r, scene, at, step, fmi3=False):
    """Both platforms save the state at `at`: the same bytes; each platform continues from the other's
    state as the uninterrupted linux64 run did."""
    label = f"{scene} (FMI 3.0)" if fmi3 else scene
    name = f"{scene}.fmi3" if fmi3 else scene
    states = {p: r.work / f"{name}.state.{p}" for p in ("linux64", "win64")}
    full = {p: r.work / f"{name}.saving.{p}.bin" for p in ("linux64", "win64")}
    for p in states:
        r.run(p, scene, full[p], "--save-at", at, states[p], fmi3=fmi3)
    if fmi3:
        r.report(f"{label}, win64 against linux64", first_difference(full["linux64"], full["win64"], exact))
    same = states["linux64"].read_bytes() == states["win64"].read_bytes()
    r.report(f"{label} state saved at t = {at:g} s ({states['linux64'].stat().st_size} bytes), win64 against "
             f"linux64", None if same else f"{states['win64'].stat().st_size} bytes on win64, different")
    skip = round(at / step) + 1  # the rows up to and including the saved point
    for p, other in (("win64", "linux64"), ("linux64", "win64")):
        cont = r.work / f"{name}.restored.{p}.bin"
        r.run(p, scene, cont, "--restore", at, states[other], fmi3=fmi3)
        r.report(f"{label} continued on {p} from the {other} state, against the uninterrupted linux64 run",
                 first_difference(full["linux64"], cont, exact, skip))


def default_start(model_description, name):
    for v in ET.parse(model_description).getroot().iter("ScalarVariable"):
        if v.get("name") == name:
            return float(next(iter(v)).get("start"))
    raise KeyError(name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name in ("linux64-driver", "linux64-library", "win64-driver", "win64-library", "fmi3-linux64-driver",
                 "fmi3-linux64-library", "fmi3-win64-driver", "fmi3-win64-library", "wine", "deck",
                 "model-description", "work"):
        parser.add_argument(f"--{name}", required=True)
    args = parser.parse_args()
    r = Runner(args)
    started = time.monotonic()
    tolerances = [default_start(args.model_description, n) for n in ("tensionTolerance", "positionTolerance")]

    def within_error_control(names):
        return WithinErrorControl(*tolerances, names)

    # The first wine start creates the prefix (its C: drive holds the deck for the URI and path variants).
    compare_scene(r, "hopland", exact)
    deck = Path(args.deck)
    decks = r.work / "decks"
    decks.mkdir(exist_ok=True)
    shutil.copy(deck, decks / deck.name)
    drive_c = r.work / "wine-prefix" / "drive_c" / "uc-decks"
    drive_c.mkdir(parents=True, exist_ok=True)
    shutil.copy(deck, drive_c / deck.name)
    relative = (("--line-file", deck.name), decks)                           # looked up in the working directory
    compare_scene(r, "mooring", within_error_control, linux=relative, variants=(
        relative,
        (("--line-file", f"file:///C:/uc-decks/{deck.name}"), None),        # a file: URI with a drive letter
        (("--line-file", f"C:\\uc-decks\\{deck.name}"), None),              # an absolute Windows path
    ))
    compare_scene(r, "waves", within_error_control)
    compare_scene(r, "winch", exact)
    compare_states(r, "hopland", 330.0, 0.5)
    compare_states(r, "winch", 30.0, 0.5)
    # The FMI 3.0 variant's binaries (no input derivatives there: compared with each other).
    compare_states(r, "hopland", 330.0, 0.5, fmi3=True)
    print(f"{'FAILED' if r.failures else 'passed'}: {r.failures} disagreements, {time.monotonic() - started:.1f} s")
    return 1 if r.failures else 0


if __name__ == "__main__":
    sys.exit(main())
