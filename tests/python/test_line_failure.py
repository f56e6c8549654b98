"""Line failure in a mooring system through the FMU (docs/line_failure.md): a deck's FAILURE section, the
failure.* parameters, a scene's [failure] table, the log message at the break and the state across it."""
from __future__ import annotations

import numpy as np
import pytest

from studies.comparisons import mooring_system as ms
from ucable.fmu import FMICallException
from ucable.scene import Scene
from ucable.scene_schema import SceneFileError

OC4 = ms.read_system_deck(ms.OC4)
FAILING = ms.DECKS / "oc4_failure.dat"  # OC4 with line 1 failing at its fairlead (point 4) at 3.3 s


def _parameters(**extra) -> dict:
    return ms.fmu_parameters(OC4, lineFileElements=10, **extra)


def _run(cable, steps: int, h: float = 0.5, start: int = 0) -> np.ndarray:
    out = []
    for k in range(start, start + steps):
        cable.do_step(h, t=k * h)
        out.append(cable.get_reals(["line[1].broken", "line[1].breakTime", "line[1].fairleadTension",
                                    "line[2].broken", "body[1].force.x", "body[1].force.y"]))
    return np.array(out)


def test_a_deck_failure_breaks_its_line_at_its_time_with_one_log_message(make_cable):
    c = make_cable(parameters=_parameters(lineFile=str(FAILING)), logging_on=True)
    c.initialize()
    before = c.get("line[1].fairleadTension")
    history = _run(c, 10)  # 5 s in steps of 0.5 s: the break at 3.3 s within the step from 3.0 s
    times = 0.5 * np.arange(1, 11)
    assert np.all(history[times < 3.3, 0] == 0.0) and np.all(history[times > 3.3, 0] == 1.0)
    assert np.all(history[times > 3.3, 1] == 3.3)
    assert np.all(history[:, 3] == 0.0)
    assert history[-1, 2] < 1e-3 * before  # a bare end carries no tension
    breaks = [m for _, _, m in c.messages if "line failure 1" in m]
    assert len(breaks) == 1, c.messages
    assert "t = 3.3 s: line 1 detached from point 4" in breaks[0]


def test_the_failure_parameters_break_a_line_by_tension_and_a_state_restores_across_it(make_cable):
    probe = make_cable(parameters=_parameters())
    probe.initialize()
    threshold = 1.05 * probe.get("line[2].fairleadTension")
    c = make_cable(parameters=_parameters(**{"failure.line": 2, "failure.tension": threshold}))
    c.initialize()

    def pulled(cable, steps, start=0):
        out = []
        for k in range(start, start + steps):
            t = 0.5 * k
            # towards +x, away from anchor 2 (at x = -837.6 m), from rest at 0.2 m/s2
            cable.set({"body[1].x": 0.1 * t * t, "body[1].vx": 0.2 * t})
            cable.do_step(0.5, t=t)
            out.append(cable.get_reals(["line[2].broken", "line[2].breakTime", "line[2].fairleadTension",
                                        "body[1].force.x"]))
        return np.array(out)

    pulled(c, 2)
    state = c.serialize_state(c.get_state())
    first = pulled(c, 16, start=2)
    assert first[-1, 0] == 1.0 and 1.0 < first[-1, 1] < 9.0, first
    fresh = make_cable(parameters=_parameters(**{"failure.line": 2, "failure.tension": threshold}))
    fresh.set_state(fresh.deserialize_state(state), time=1.0)
    assert pulled(fresh, 16, start=2).tobytes() == first.tobytes()


def _refusal(make_cable, parameters: dict) -> str:
    c = make_cable(parameters=parameters, logging_on=True)
    with pytest.raises(FMICallException):
        c.initialize(inputs={"tow.z": -70.0})
    return "\n".join(text for status, _, text in c.messages if status == "ERROR")


def test_a_failure_at_a_point_of_one_line_is_refused_at_the_start(make_cable):
    # one line breaks at its far end (tests/python/test_one_line_failure.py); it has no deck points
    log = _refusal(make_cable, {"lineFile": str(ms.DECKS / "chain.dat"), "failure.line": 1, "failure.point": 2,
                                "failure.time": 5.0})
    assert "failure.line = 1: failure.point = 2: one line has no deck points" in log, log


def test_an_anchor_lets_go_at_its_time(make_cable):
    # failure.point 1: line 1's anchor; its end there goes on bare, the line hangs from its fairlead
    c = make_cable(parameters=_parameters(**{"failure.line": 1, "failure.point": 1, "failure.time": 1.2}),
                   logging_on=True)
    c.initialize()
    before = c.get("line[1].anchorTension")
    history = []
    for k in range(4):
        c.do_step(0.5, t=0.5 * k)
        history.append(c.get_reals(["line[1].broken", "line[1].breakTime", "line[1].anchorTension",
                                    "line[1].fairleadTension"]))
    history = np.array(history)
    assert list(history[:, 0]) == [0.0, 0.0, 1.0, 1.0] and history[-1, 1] == 1.2
    assert history[-1, 2] < 1e-3 * before  # a bare end carries no tension
    assert history[-1, 3] > 1e4  # the line hangs from its fairlead
    assert any("line 1 detached from point 1" in m for _, _, m in c.messages), c.messages


def test_a_scene_failure_table_sets_the_failure_parameters_and_is_checked():
    base = {"duration": 2.0, "step": 0.5, "parameters": {"lineFile": str(ms.OC4)}, "body": {"start": [0] * 6}}
    scene = Scene.from_data({**base, "failure": {"line": 1, "time": 1.2}}, "s")
    assert scene.parameters["failure.line"] == 1 and scene.parameters["failure.time"] == 1.2
    assert scene.parameters["failure.point"] == 0 and scene.parameters["failure.tension"] == 0.0
    for bad, says in [({"line": 1}, "give a time"), ({"line": 0, "time": 1.0}, "[failure] line"),
                      ({"line": 1, "time": -1.0}, "must not be negative"), ({"line": 1, "time": 1, "end": 2}, "end")]:
        with pytest.raises(SceneFileError, match=says.replace("[", r"\[").replace("]", r"\]")):
            Scene.from_data({**base, "failure": bad}, "s")


def test_a_scene_failure_table_sets_a_break_along_the_line():
    base = {"duration": 2.0, "step": 0.5, "parameters": {"lineFile": str(ms.OC4)}, "body": {"start": [0] * 6}}
    scene = Scene.from_data({**base, "failure": {"line": 1, "time": 1.2, "position": 400.0}}, "s")
    assert scene.parameters["failure.position"] == 400.0 and scene.parameters["failure.point"] == 0
    for bad, says in [({"line": 1, "time": 1.0, "position": -1.0}, "must not be negative"),
                      ({"line": 1, "time": 1.0, "position": 400.0, "point": 4}, "[failure] position")]:
        with pytest.raises(SceneFileError, match=says.replace("[", r"\[").replace("]", r"\]")):
            Scene.from_data({**base, "failure": bad}, "s")


def test_a_scene_with_a_failure_records_when_its_line_broke(fmu_file):
    from ucable.scene import run_scene

    scene = {"duration": 2.0, "step": 0.5, "record_shape": False, "body": {"start": [0] * 6},
             "parameters": {**_parameters(), "lineFile": str(ms.OC4)}, "failure": {"line": 3, "time": 1.2}}
    result = run_scene(scene, fmu=fmu_file)
    assert list(result["line[3].broken"]) == [0.0, 0.0, 0.0, 1.0, 1.0]
    assert result["line[3].breakTime"][-1] == 1.2
    assert result["line[1].broken"][-1] == 0.0 and "line[4].broken" not in result.columns
