"""Vortex-induced vibration (Cl; docs/model.md, "Vortex-induced vibration") on MoorDyn's own VIV deck
tests/Mooring/viv/viv.txt (tests/data/decks/public/viv): a 23.7 m riser of 24 mm diameter, Cl 0.7, in a uniform
0.2 m/s current. The deck loads, and its cross flow vibration locks in: a motion across the flow of
millimetres (MoorDyn: 4.3 mm RMS at mid-length) at a frequency inside the synchronisation band
(cF -+ dF) U / d = 0.83 .. 2.17 Hz, the fairlead tension oscillating at twice it; and, as MoorDyn, in the line's
seventh cross-flow mode at 1.04 Hz (MoorDyn's own test of this deck: the tension's period 1 / (2 x 1.04 Hz)
within 0.01 s), not in the sixth at 0.88 Hz (the mode depends on the direction the phases start spread in)."""

from pathlib import Path

import numpy as np

from ucable.fmu import CableFMU

DECK = Path(__file__).resolve().parents[1] / "data" / "decks" / "public" / "viv" / "viv.txt"
U, D, CF, DF = 0.2, 0.024, 0.18, 0.08
F_LOCK_IN = 1.04  # [Hz] MoorDyn on this deck and its own test's target


def _crossing_frequency(t, s):
    s = s - s.mean()
    z = np.where((s[:-1] < 0) & (s[1:] >= 0))[0]
    tz = t[z] - s[z] * (t[z + 1] - t[z]) / (s[z + 1] - s[z])
    return (len(tz) - 1) / (tz[-1] - tz[0])


def test_viv_deck_loads_and_locks_in_across_the_flow(fmu_file):
    c = CableFMU(fmu_file, parameters={"lineFile": str(DECK), "enableSeabed": True, "enableCompression": False},
                 logging_on=True)
    try:
        c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": -1.0})
        h, ts, ys, tens = 0.01, [], [], []
        for k in range(1500):  # 15 s as MoorDyn's own test (it checks from 10 s): locked in after about 4 s
            c.do_step(h, t=k * h)
            ts.append((k + 1) * h)
            ys.append(c.get("shape.y[11]"))  # mid-length
            tens.append(c.get("towTension"))
    finally:
        c.free()
    t, y, ten = np.array(ts), np.array(ys), np.array(tens)
    late = t > 4.0
    rms = np.sqrt(np.mean((y[late] - y[late].mean()) ** 2))
    assert 1e-3 < rms < 2e-2, rms  # millimetres, not the metres of a blow-up nor nothing
    f = _crossing_frequency(t[late], y[late])
    assert (CF - DF) * U / D < f < (CF + DF) * U / D, f
    # the tension sees the cross flow motion twice per period (the line stretches at both extremes)
    assert abs(_crossing_frequency(t[late], ten[late]) - 2 * f) < 0.25 * f
    # the mode MoorDyn locks in: the modes lie 0.17 Hz apart here (in still water 0.88, 1.05, 1.23 Hz)
    locked = t > 8.0
    f = _crossing_frequency(t[locked], y[locked])
    assert abs(f - F_LOCK_IN) < 0.05, f
    period = 1.0 / _crossing_frequency(t[locked], ten[locked])
    assert abs(period - 1.0 / (2.0 * F_LOCK_IN)) < 0.01, period
