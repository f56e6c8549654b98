"""Pinned bodies and rods against MoorDyn v2 fed the same deck (docs/systems_mooring.md, "Pinned bodies"):
MoorDyn's own pinned-body deck (a rod on a CoupledPinned body in vacuum, its pin accelerated at 0.5 m/s2 along
y, MoorDyn's test of its pinned body), a rod pinned to a still coupled body released swinging, and that rod with
a line from its free end to an anchor, the body surging. The roll of the pinned body, the pin's load and the line's tensions are compared
over the run (RMS and largest difference).

    python -m studies.comparisons.pinned_bodies /path/to/pinnedBody.txt
"""

from __future__ import annotations

import math
import sys
import tempfile
from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU
from ..peers.moordyn import System

def deck(title: str, rod_type: str, rods: str, bodies: str = "", line_type: str = "rope 0.1 10.0 5e6 0 0 0 0 0 0",
         points: str = "1 Fixed 30 0 -5 0 0 0 0\n2 Fixed 30 0 -10 0 0 0 0", lines: str = "1 rope 1 2 5 1 -",
         options: str = "100 WtrDpth\n1025 WtrDnsty\n0 TmaxIC") -> str:
    """A MoorDyn deck of one line type, one rod type, the given rows (BODIES left out where none) and options;
    by default the line is the dummy MoorDyn's pinnedBody deck has, between two Fixed points."""
    body_table = ("---------------------- BODIES ----\n"
                  "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*\n"
                  "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n" + bodies + "\n") if bodies else ""
    return ("--- MoorDyn Input File ---\n" + title + "\n"
            "---------------------- LINE TYPES ----\n"
            "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n"
            "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n" + line_type + "\n"
            "---------------------- ROD TYPES ----\n"
            "TypeName Diam Mass/m Cd Ca CdEnd CaEnd\n"
            "(name) (m) (kg/m) (-) (-) (-) (-)\n" + rod_type + "\n" + body_table +
            "---------------------- RODS ----\n"
            "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n"
            "(#) (name) (#/key) (m) (m) (m) (m) (m) (m) (-) (-)\n" + rods + "\n"
            "---------------------- POINTS ----\n"
            "ID Type X Y Z Mass Volume CdA Ca\n"
            "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n" + points + "\n"
            "---------------------- LINES ----\n"
            "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n"
            "(#) (name) (#) (#) (m) (-) (-)\n" + lines + "\n"
            "---------------------- OPTIONS ----\n" + options + "\n"
            "------------------------- need this line ----\n")


def pinned_body_deck(d: float, mpl: float, Ca: float, z0: float, r0: float, sa: float, sb: float, rho: float) -> str:
    """A CoupledPinned body of no mass of its own at depth z0 with a rod (no drag) on its z axis from sa to sb,
    released from the roll r0 [deg] (TmaxIC 0), in water of density rho (MoorDyn's pinnedBody deck's kind)."""
    return deck("a rod on a pinned body", f"bar {d} {mpl:.12g} 0 {Ca} 0 0", f"1 bar Body1 0 0 {sa} 0 0 {sb} 10 -",
                bodies=f"1 CoupledPinned 0 0 {z0} {r0} 0 0 0 0 0 0 0 0", options=f"100 WtrDpth\n{rho} WtrDnsty\n0 TmaxIC")


ROD_TYPE = "bar 0.5 400 0 1.0 0 0"  # 8 m rods of 0.5 m, 400 kg/m, Ca 1, no drag
HOLDER = "1 Coupled 0 0 -10 0 0 0 0 0 0 0 0 0"


def pinned_rod_deck(kind: str, xb: float, zb: float, segs: int = 10, options: str = "") -> str:
    """A rod pinned at (2, 0, 0) on coupled body 1 (kind Body1Pinned) to (xb, 0, zb) in its frame, released
    from there (TmaxIC 0)."""
    return deck("a rod pinned to a coupled body", ROD_TYPE, f"1 bar {kind} 2 0 0 {xb:.12g} 0 {zb:.12g} {segs} -",
                bodies=HOLDER, options="100 WtrDpth\n1025 WtrDnsty\n0 TmaxIC" + options)


def pinned_rod_line_deck(xb: float, zb: float, segs: int, rod_segs: int, dtM: float) -> str:
    """The pinned rod with a chain from its end B to an anchor, each code from its own statics (TmaxIC 100)."""
    return deck("a rod pinned to a coupled body, a line from its free end to an anchor", ROD_TYPE,
                f"1 bar Body1Pinned 2 0 0 {xb:.12g} 0 {zb:.12g} {rod_segs} -", bodies=HOLDER,
                line_type="chain 0.1 30.0 1e8 -0.5 0 1.2 1.0 0.2 0.0", points="1 Fixed 40 0 -60 0 0 0 0",
                lines=f"1 chain 1 R1B 60 {segs} -",
                options=f"100 WtrDpth\n1025 WtrDnsty\n100 TmaxIC\n0.5 dtIC\n0.001 threshIC\n{dtM} dtM")


def _moordyn_end_tension(md, line, end: int) -> float:
    """MoorDyn's tension at a line end (0: A, 1: B), extrapolated from its two end segments' (its tensions
    are its segments', half a segment from the ends)."""
    api = md.api
    n = api.GetLineN(line)
    i0, i1 = (0, 1) if end == 0 else (n - 1, n - 2)
    t0 = np.linalg.norm(api.GetLineNodeTen(line, i0))
    t1 = np.linalg.norm(api.GetLineNodeTen(line, i1))
    return float(1.5 * t0 - 0.5 * t1)


def pinned_body(path: Path, t_end: float = 20.0, a: float = 0.5, h: float = 0.05, dt_md: float = 0.01) -> dict:
    """MoorDyn's pinnedBody deck, its pin accelerated along y from rest: the roll and the pin's load (y, z) of
    each code at the FMU's communication points."""
    n = int(round(t_end / h))
    sub = int(round(h / dt_md))
    with System(path) as md:
        x, v = [0.0, 0.0, -5.0, 0.0, 0.0, 0.0], [0.0] * 6
        md.init(x, v)
        body = md.api.GetBody(md.system, 1)
        ref = {"roll": [], "fy": [], "fz": []}
        t = 0.0
        for k in range(n):
            for j in range(sub):
                x[1], v[1] = 0.5 * a * t * t, a * t
                f = md.step(x, v, t, dt_md)
                t += dt_md
            ref["roll"].append(md.api.GetBodyState(body)[0][3])
            ref["fy"].append(f[1])
            ref["fz"].append(f[2])
    c = CableFMU(parameters={"lineFile": str(path)})
    out = {"roll": [], "fy": [], "fz": []}
    try:
        c.initialize(inputs={"body[1].z": -5.0})
        for k in range(n):
            t = k * h
            c.set({"body[1].y": 0.5 * a * t * t, "body[1].vy": a * t})
            c.do_step(h, t=t)
            out["roll"].append(c.get("body[1].pose.roll"))
            out["fy"].append(c.get("body[1].force.y"))
            out["fz"].append(c.get("body[1].force.z"))
    finally:
        c.free()
    return {k: (np.array(out[k]), np.array(ref[k])) for k in out}


def pinned_rod_line(tilt_deg: float = 10.0, t_end: float = 40.0, h: float = 0.05, segs: int = 40,
                    rod_segs: int = 20, elements: int = 20, surge: float = 1.0, period: float = 6.0,
                    md_calls: int = 5) -> dict:
    """The rod pinned to coupled body 1 with a chain from its free end to an anchor, each code from its own
    statics (MoorDyn's relaxation, TmaxIC; the FMU's Newton on the rod's rotation), body 1 then surging
    A (1 - cos 2 pi t / T): the chain's tension at the rod and at the anchor, and the pin's load on body 1
    (x, z), each code at the FMU's communication points (MoorDyn called md_calls times per step, its body
    moving linearly within each call)."""
    theta = math.radians(tilt_deg)
    dtM = 2e-4 * 40 / segs
    w = 2 * math.pi / period

    def motion(t):
        return surge * (1 - math.cos(w * t)), surge * w * math.sin(w * t), surge * w * w * math.cos(w * t)

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "pinned_rod_line.dat"
        path.write_text(pinned_rod_line_deck(2 + 8 * math.sin(theta), -8 * math.cos(theta), segs, rod_segs, dtM))
        n = int(round(t_end / h))
        with System(path) as md:
            x, v = [0.0, 0.0, -10.0, 0.0, 0.0, 0.0], [0.0] * 6
            md.init(x, v)
            line = md.api.GetLine(md.system, 1)
            ref = {"rod": [_moordyn_end_tension(md, line, 1)], "anchor": [_moordyn_end_tension(md, line, 0)],
                   "fx": [np.nan], "fz": [np.nan]}
            t, dt = 0.0, h / md_calls
            for k in range(n):
                for j in range(md_calls):
                    x[0], v[0], _ = motion(t)
                    f = md.step(x, v, t, dt)
                    t += dt
                ref["rod"].append(_moordyn_end_tension(md, line, 1))
                ref["anchor"].append(_moordyn_end_tension(md, line, 0))
                ref["fx"].append(f[0])
                ref["fz"].append(f[2])
        c = CableFMU(parameters={"lineFile": str(path), "lineFileElements": elements})
        out = {"rod": [], "anchor": [], "fx": [], "fz": []}

        def record():
            out["rod"].append(c.get("line[1].fairleadTension"))
            out["anchor"].append(c.get("line[1].anchorTension"))
            out["fx"].append(c.get("body[1].force.x"))
            out["fz"].append(c.get("body[1].force.z"))

        try:
            c.initialize(inputs={"body[1].z": -10.0})
            record()
            for k in range(n):
                x0, v0, a0 = motion(k * h)
                c.set({"body[1].x": x0, "body[1].vx": v0})
                c.set_input_derivatives(["body[1].vx"], 1, [a0])
                c.do_step(h, t=k * h)
                record()
        finally:
            c.free()
    return {k: (np.array(out[k]), np.array(ref[k])) for k in out}


def _period(t, x) -> float:
    crossings = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i]) for i in range(len(x) - 1)
                 if (x[i] < 0) != (x[i + 1] < 0)]
    return 2 * float(np.mean(np.diff(crossings)))


def pinned_rod_swing(tilt_deg: float = 5.0, t_end: float = 10.0, h: float = 0.05, rod_segs: int = 40) -> dict:
    """The rod (8 m, 0.5 m, 400 kg/m, Ca 1) pinned 2 m out on coupled body 1, the body held still, released
    tilted by tilt_deg in water (TmaxIC 0), no line on it: its swing's period in each code (MoorDyn's from
    the angle of its end nodes, the FMU's from the pin's load along x, which swings with it) and the pin's
    load on body 1 in each (MoorDyn's coupled body force: the rod's weight in water, no inertial part)."""
    theta = math.radians(tilt_deg)
    n = int(round(t_end / h))
    t = h * np.arange(1, n + 1)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "pinned_rod_swing.dat"
        path.write_text(pinned_rod_deck("Body1Pinned", 2 + 8 * math.sin(theta), -8 * math.cos(theta), rod_segs,
                                        "\n0.0002 dtM"))
        with System(path) as md:
            x, v = [0.0, 0.0, -10.0, 0.0, 0.0, 0.0], [0.0] * 6
            md.init(x, v)
            rod = md.api.GetRod(md.system, 1)
            angle, fx, fz = [], [], []
            for k in range(n):
                f = md.step(x, v, k * h, h)
                a = np.array(md.api.GetRodNodePos(rod, 0))
                b = np.array(md.api.GetRodNodePos(rod, md.api.GetRodN(rod)))
                angle.append(math.atan2(b[0] - a[0], a[2] - b[2]))
                fx.append(f[0])
                fz.append(f[2])
        c = CableFMU(parameters={"lineFile": str(path)})
        out = []
        try:
            c.initialize(inputs={"body[1].z": -10.0})
            for k in range(n):
                c.do_step(h, t=k * h)
                out.append((c.get("body[1].force.x"), c.get("body[1].force.z")))
        finally:
            c.free()
    out = np.array(out)
    return {"period": (_period(t, out[:, 0]), _period(t, np.array(angle))), "fx": (out[:, 0], np.array(fx)),
            "fz": (out[:, 1], np.array(fz))}


def differences(pair, scale=None) -> tuple:
    """RMS and largest difference of (fmu, moordyn) relative to `scale` (default: the mean |moordyn|)."""
    f, m = pair
    keep = np.isfinite(m)
    f, m = f[keep], m[keep]
    s = scale if scale is not None else float(np.mean(np.abs(m)))
    d = f - m
    return float(np.sqrt(np.mean(d * d)) / s), float(np.max(np.abs(d)) / s)


if __name__ == "__main__":
    r = pinned_body(Path(sys.argv[1]))
    amp = float(np.ptp(r["roll"][1]))
    print("pinnedBody: mean roll FMU %.5f MoorDyn %.5f (atan(-a/g) %.5f); swing FMU %.5f MoorDyn %.5f rad" % (
        np.mean(r["roll"][0]), np.mean(r["roll"][1]), math.atan(-0.5 / 9.80665), np.ptp(r["roll"][0]), amp))
    print("  roll RMS/largest difference of the swing: %.3g %.3g" % differences(r["roll"], amp))
    print("  pin load y RMS/largest of the mean |Fy|: %.3g %.3g; z of the mean: %.3g %.3g" % (
        *differences(r["fy"]), *differences(r["fz"])))
    w = pinned_rod_swing()
    print("pinned rod swinging, its pin still: period FMU %.4f s MoorDyn %.4f s; pin load along x: FMU swings by "
          "%.1f N, MoorDyn %.3g N; along z FMU mean %.1f N, MoorDyn %.1f N" % (
              *w["period"], np.ptp(w["fx"][0]), np.ptp(w["fx"][1]), np.mean(w["fz"][0]), np.mean(w["fz"][1])))
    q = pinned_rod_line()
    for k in q:
        print("pinned rod + chain %s: start FMU %.1f MoorDyn %.1f; mean FMU %.1f MoorDyn %.1f, swing %.1f, "
              "RMS %.3g largest %.3g of the mean" % (k, q[k][0][0], q[k][1][0], np.mean(q[k][0]), np.nanmean(q[k][1]),
                                                     np.ptp(q[k][1][1:]), *differences(q[k])))
