"""One line whose far end lets go (docs/line_failure.md, "One line"), as a user tries it: the README's tow recipe
through fmpy with a towed body and the failure.* parameters (the towline parts behind the ship), the log message and
the state across the break in a fresh instance."""
from __future__ import annotations

import math

import numpy as np

V = 2.4 * 1852 / 3600  # [m/s] the README's steady tow at 2.4 kn along +x
# a towed body at the far end (bottomEnd 2) that the line lets go of at 20.25 s (inside the step from 20 s)
TOWED = {"bottomEnd": 2, "body.mass": 400.0, "body.volume": 0.05, "body.CdA": 0.5, "failure.line": 1,
         "failure.time": 20.25}


def _recipe(fmu: str, stop: float, outputs: list, start_values: dict):
    """The README's fmpy recipe: every input 0 unless set, the tow point at V along +x, to `stop`."""
    from fmpy import read_model_description, simulate_fmu
    t = np.arange(0.0, stop + 0.5, 0.5)
    tow = {"tow.x": V * t, "tow.vx": V + 0 * t, "tow.ax": 0 * t}
    inputs = [v.name for v in read_model_description(fmu).modelVariables if v.causality == "input"]
    u = np.zeros(len(t), dtype=[("time", float)] + [(name, float) for name in inputs])
    u["time"] = t
    for name, values in tow.items():
        u[name] = values
    return simulate_fmu(fmu, stop_time=stop, output_interval=0.5, input=u, output=outputs, start_values=start_values)


def test_a_towline_parts_behind_the_ship_and_the_line_trails_with_a_bare_end(fmu_file):
    names = ["towTension", "endTension", "line[1].broken", "line[1].breakTime", "line[1].anchorTension",
             "endPosition.z"]
    res = _recipe(str(fmu_file), 60.0, names, TOWED)
    t = res["time"]
    before, after = t < 20.25, t > 20.25
    assert (res["line[1].broken"][before] == 0.0).all() and (res["line[1].broken"][after] == 1.0).all()
    assert (res["line[1].breakTime"][after] == 20.25).all(), "the break at failure.time exactly, inside the step"
    # tensionTolerance (its default, 1e-3) times the line's tension scale (about its tension at the start)
    tolerance = 1e-3 * res["towTension"][0]
    # the towed body pulled on the far end before; the bare end carries nothing after (to the integrator's error)
    assert res["line[1].anchorTension"][before][-1] > 100 * tolerance
    assert (res["line[1].anchorTension"][after] < tolerance).all(), res["line[1].anchorTension"][after]
    # the ship no longer tows the body: the tow tension falls by the body's pull on the line (its weight in water and
    # drag, the endTension before: 3443 N) once the release has reached the tow point (the axial wave crosses the 300 m
    # in 0.06 s, the line's bend at the body relaxes over a few tenths of a second): 3321 N at 21 s, the rest the
    # change of the line's own drag as it starts to rise
    pull = res["endTension"][before][-1]
    drop = res["towTension"][before][-1] - res["towTension"][t == 21.0][0]
    assert 0.8 * pull < drop < 1.2 * pull, (drop, pull)
    # the line without its body trails higher behind the ship: its end rises, the steady tow of a bare line (its critical
    # angle, where the normal drag balances the weight's normal part) is shallower than with a 400 kg body
    assert res["endPosition.z"][-1] > res["endPosition.z"][before][-1] + 1.0


def test_the_break_is_logged_and_a_state_restores_across_it_in_a_fresh_instance(make_cable):
    def run(cable, start, steps):
        out = []
        for k in range(start, start + steps):
            t = 0.5 * k
            cable.set({"tow.x": V * t, "tow.vx": V})
            cable.do_step(0.5, t=t)
            out.append(cable.get_reals(["towTension", "line[1].broken", "line[1].breakTime", "endPosition.x"]))
        return np.array(out)

    c = make_cable(parameters=TOWED, logging_on=True)
    c.initialize()
    run(c, 0, 36)  # to 18 s
    state = c.serialize_state(c.get_state())
    first = run(c, 36, 16)  # across the break, to 26 s
    assert first[-1, 1] == 1.0 and first[-1, 2] == 20.25
    breaks = [m for _, _, m in c.messages if "line failure 1" in m]
    assert len(breaks) == 1 and "t = 20.25 s: line 1's far end detached" in breaks[0], c.messages
    fresh = make_cable(parameters=TOWED)
    fresh.set_state(fresh.deserialize_state(state), time=18.0)
    assert run(fresh, 36, 16).tobytes() == first.tobytes()
    assert math.isfinite(first[-1, 3])
