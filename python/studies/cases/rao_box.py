"""A generic RAO table of an 80 m vessel: a box barge with uncoupled single-degree-of-freedom responses
(scripts/rao_table writes it; the VesselRAO and Vessel FMUs ship it as resources/rao.csv).

This is an openly stated approximation, not the RAOs of any real ship. The hull is a box, L 80 m, B 18 m,
draught 5 m (7380 t), in deep water; the RAO reference point is midships on the centreline at the
waterline. Per wave frequency w (k = w^2 / g) and relative heading mu (the waves' direction of travel
relative to the bow), with E(.) the average of the wave's phase factor exp(i k.x) over the waterplane:

- heave, roll, pitch: a damped oscillator each, (C - w^2 (M + A) - i w B) X = C e, where the
  exciting "effective wave" e is the waterplane average of the elevation (heave), its first moment
  over the waterplane's inertia about x (roll: the mean transverse slope) and about y (pitch, with the
  sign of a bow-down rotation), attenuated by the pressure decay exp(-k T) at the keel. Long waves give
  X = e: the vessel follows the surface. Restoring: C33 = rho g L B, C44 = rho g V GM (GM 2 m),
  C55 = rho g B L^3 / 12 (the waterplane's inertia). Inertia: M = rho L B T, radii of gyration
  0.35 B (roll) and 0.25 L (pitch). Added mass: heave rho pi B^2 / 8 per metre (the low-frequency value
  of a half circle of diameter B), pitch the same strip added mass over the length (A33 L^2 / 12), roll
  20 % of the roll inertia. Damping: 40 % of critical in heave and pitch, 10 % in roll (radiation and
  viscous damping lumped into one linear ratio; a box has little pitch and heave resonance, the peaks
  stay near 1.4 times the exciting wave).
- surge, sway: the vessel moves with the water: the horizontal particle displacement of the wave,
  averaged over the draught ((1 - exp(-k T)) / (k T)) and over the waterplane, resolved on the body axes.
- yaw: the rigid rotation that best fits (least squares) that horizontal displacement field over the
  waterplane.

Couplings (sway-roll, surge-pitch), diffraction, the exact added mass and radiation damping of the hull,
and forward speed are left out. Good enough to drive a cable at a realistic tow-point motion; use the RAOs
of the actual vessel (from a diffraction code) for design.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from ucable.paths import REPO_ROOT
from ucable.units import GRAVITY as G, WATER_DENSITY as RHO

L, B, T = 80.0, 18.0, 5.0
GM = 2.0
ZETA = {"heave": 0.4, "roll": 0.1, "pitch": 0.4}
DEFAULT_OUT = REPO_ROOT / "fmu" / "partners" / "sea" / "rao.csv"
PERIODS = np.concatenate([np.arange(2.0, 25.0, 0.5), np.arange(25.0, 40.5, 1.0)])
HEADINGS = np.arange(0.0, 360.0, 15.0)
DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


def _mean_phase(q, a):
    """(1 / 2a) * integral over [-a, a] of exp(i q x) dx: sin(q a) / (q a)."""
    return np.sinc(q * a / math.pi)


def _first_moment(q, a):
    """Integral over [-a, a] of x exp(i q x) dx = 2 i (sin(qa) / q^2 - a cos(qa) / q)."""
    qa = q * a
    small = np.abs(qa) < 1e-4
    safe = np.where(small, 1.0, q)
    exact = 2.0 * (np.sin(qa) / safe**2 - a * np.cos(qa) / safe)
    return 1j * np.where(small, 2.0 / 3.0 * q * a**3 * (1.0 - qa**2 / 10.0), exact)


def oscillator(C, M, zeta, w):
    return C / (C - w**2 * M - 1j * w * 2.0 * zeta * math.sqrt(C * M))


def box_raos(period, heading_deg):
    """Complex RAOs (surge, sway, heave in m/m; roll, pitch, yaw in rad/m) at the given period [s] and
    relative heading [deg]; motion = Re[RAO a exp(-i w t)] for the wave a cos(w t) at the reference point."""
    w = 2.0 * math.pi / period
    k = w * w / G
    mu = math.radians(heading_deg)
    kx, ky = k * math.cos(mu), k * math.sin(mu)
    mass = RHO * L * B * T
    ex, ey = _mean_phase(kx, L / 2), _mean_phase(ky, B / 2)  # waterplane means of exp(i k x), exp(i k y)
    mx, my = _first_moment(kx, L / 2), _first_moment(ky, B / 2)  # first moments along x, y
    IL, IT = B * L**3 / 12.0, L * B**3 / 12.0  # waterplane inertias about y and x
    keel = math.exp(-k * T)
    heave_e = keel * ex * ey
    roll_e = keel * (L * ex) * my / IT
    pitch_e = -keel * mx * (B * ey) / IL
    a33 = RHO * math.pi * B**2 / 8.0 * L
    heave = oscillator(RHO * G * L * B, mass + a33, ZETA["heave"], w) * heave_e
    i44 = mass * (0.35 * B) ** 2
    roll = oscillator(RHO * G * L * B * T * GM, 1.2 * i44, ZETA["roll"], w) * roll_e
    i55 = mass * (0.25 * L) ** 2
    pitch = oscillator(RHO * G * IL, i55 + a33 * L**2 / 12.0, ZETA["pitch"], w) * pitch_e
    depth = (1.0 - keel) / (k * T)  # mean of exp(k z) over the draught
    horizontal = 1j * depth * ex * ey  # particle displacement per unit amplitude along the travel direction
    surge, sway = math.cos(mu) * horizontal, math.sin(mu) * horizontal
    # yaw: integral of (x v - y u) over the waterplane / integral of (x^2 + y^2)
    d = 1j * depth
    yaw = (math.sin(mu) * d * mx * (B * ey) - math.cos(mu) * d * (L * ex) * my) / (IL + IT)
    return np.array([surge, sway, heave, roll, pitch, yaw])


def table(periods=PERIODS, headings=HEADINGS):
    """Rows (period, heading, amplitude and phase lag [deg] of each DOF; rotations in deg/m)."""
    rows = []
    for p in periods:
        for h in headings:
            r = box_raos(float(p), float(h))
            r[3:] = np.degrees(1.0) * r[3:]
            row = [p, h]
            for z in r:
                amp = abs(z)
                row += [amp, math.degrees(math.atan2(z.imag, z.real)) if amp > 1e-12 else 0.0]
            rows.append(row)
    return np.array(rows)


HEADER = """# Displacement RAOs of a generic 80 m vessel: a box barge L 80 m, B 18 m, draught 5 m, deep water,
# with uncoupled heave, roll and pitch oscillators, surge and sway following the water (scripts/rao_table;
# the model and its assumptions: python/studies/cases/rao_box.py and docs/waves.md). An openly stated
# approximation for examples, not the RAOs of a real ship.
# Reference point: midships, centreline, waterline. Heading: the waves' direction of travel relative to the
# bow [deg] (0 following seas, 90 travelling to port, 180 head seas). Amplitudes: surge, sway, heave m/m;
# roll, pitch, yaw deg/m. Phases [deg]: lag of the motion behind the wave crest at the reference point.
# Positive roll lifts the port side, positive pitch lowers the bow.
"""


def write(path: Path, rows) -> None:
    cols = ["period", "heading"] + [f"{d}{q}" for d in DOFS for q in ("Amplitude", "Phase")]
    with open(path, "w") as f:
        f.write(HEADER)
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(f"{x:.10g}" for x in r) + "\n")


def read(path: Path):
    """The table as an (n, 14) array (comment lines and the column names skipped)."""
    lines = [line for line in Path(path).read_text().splitlines() if line.strip() and not line.startswith("#")]
    return np.loadtxt(lines[1:], delimiter=",", ndmin=2)


def interpolate(rows, period: float, heading: float):
    """The complex RAOs (rotations in rad/m; R = |R| e^(i lag)) of the table `rows` (as read) at a period [s]
    and relative heading [deg], as the partner FMUs state it: bilinear in period (held beyond the table's
    periods, an infinite period included) and, periodically over 360 deg, in heading."""
    periods, headings = np.unique(rows[:, 0]), np.unique(rows[:, 1])
    cells = {(r[0], r[1]): r for r in rows}

    def at(p, h):
        r = cells[(p, h)]
        amp = r[2::2] * np.where(np.arange(6) >= 3, math.pi / 180.0, 1.0)
        return amp * np.exp(1j * np.radians(r[3::2]))

    i = int(np.clip(np.searchsorted(periods, period) - 1, 0, len(periods) - 1))
    i1 = min(i + 1, len(periods) - 1)
    wp = 0.0 if i1 == i or period <= periods[0] else min(1.0, (period - periods[i]) / (periods[i1] - periods[i]))
    h = heading % 360.0
    j = np.searchsorted(headings, h, side="right") - 1
    h0, h1 = headings[j], headings[(j + 1) % len(headings)]
    wh = 0.0 if len(headings) == 1 else (h - h0) % 360.0 / ((h1 - h0) % 360.0)
    return ((1 - wp) * ((1 - wh) * at(periods[i], h0) + wh * at(periods[i], h1))
            + wp * ((1 - wh) * at(periods[i1], h0) + wh * at(periods[i1], h1)))


def fmu_with_table(fmu: Path, out: Path, text: str) -> Path:
    """A copy `out` of a partner FMU whose resources/rao.csv is `text`."""
    import zipfile
    with zipfile.ZipFile(fmu) as src, zipfile.ZipFile(out, "w") as dst:
        for item in src.infolist():
            dst.writestr(item, text.encode() if item.filename == "resources/rao.csv" else src.read(item.filename))
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="scripts/rao_table", description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--out", type=Path, default=DEFAULT_OUT, help="CSV to write")
    args = p.parse_args(sys.argv[1:] if argv is None else argv)
    rows = table()
    write(args.out, rows)
    print(f"wrote {args.out}: {len(PERIODS)} periods x {len(HEADINGS)} headings")
    return 0


if __name__ == "__main__":
    sys.exit(main())
