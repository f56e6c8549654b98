"""The storm scene with a break (scenes/oc4_storm_break.toml, docs/line_failure.md "A storm with a break"): its
[body.free] platform, the design cases a sweep runs (`--vary case=intact,damaged,transient`) and `ucable check`
of that sweep naming the governing line; a break at two communication steps (studies.comparisons.line_failure_steps)."""
from __future__ import annotations

import copy
import os
import subprocess
import sys

import numpy as np
import pytest

from studies.comparisons import line_failure_steps as steps
from ucable.free_body import FreeBody
from ucable.paths import REPO_ROOT
from ucable.scene import load_scene
from ucable.scene_schema import SceneFileError

SCENE = REPO_ROOT / "scenes" / "oc4_storm_break.toml"


def _data() -> dict:
    return copy.deepcopy(load_scene(SCENE).data)


def test_the_free_body_table_is_checked():
    from ucable.scene import Scene

    ok = _data()
    assert Scene.from_data(ok, "s").body["free"]["mass"] == pytest.approx(2.5473e7)
    for change, says in [(lambda d: d["body"]["free"].pop("mass"), "mass: missing"),
                         (lambda d: d["body"]["free"].update(damping=[1.0, 2.0]), "three numbers"),
                         (lambda d: d["body"]["free"].update(damping=[-1.0, 0.0, 0.0]), "must not be negative"),
                         (lambda d: d["body"].update(surge={"amplitude": 1.0, "period": 10.0}), "free degree"),
                         (lambda d: d["body"]["free"].update(stiffness=1.0), "unknown key")]:
        bad = _data()
        change(bad)
        with pytest.raises(SceneFileError, match=says):
            Scene.from_data(bad, "s")


def test_the_free_body_integrates_the_lines_load_exactly_for_a_constant_force():
    # a constant force: the trapezoidal rule is exact for v and x (no damping): x = F t^2 / (2 M)
    b = FreeBody(mass=2.0, inertia=4.0, load=(1.0, 0.0, 2.0))
    for _ in range(10):
        b.advance(0.1, np.zeros(3))
    assert b.q[0] == pytest.approx(0.25, rel=1e-12) and b.q[2] == pytest.approx(0.25, rel=1e-12)
    assert b.v[0] == pytest.approx(0.5, rel=1e-12)


def test_a_case_makes_the_scene_intact_damaged_or_as_written():
    s = load_scene(SCENE)
    assert "failure.line" not in s.with_overrides({"case": "intact"}).parameters
    damaged = s.with_overrides({"case": "damaged"}).parameters
    assert damaged["failure.line"] == 1 and damaged["failure.time"] == s.step
    assert s.with_overrides({"case": "transient"}).parameters["failure.time"] == 600.0
    with pytest.raises(SceneFileError, match="one of intact, damaged, transient"):
        s.with_overrides({"case": "broken"})
    with pytest.raises(SceneFileError, match="needs a .failure. table"):
        load_scene("oc4_platform").with_overrides({"case": "intact"})


def _cli(*args, cwd, fmu):
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT / "python"), "UC_FMU": str(fmu)}
    return subprocess.run([sys.executable, "-m", "ucable.cli", *args], env=env, capture_output=True, text=True,
                          cwd=cwd, timeout=900)


def test_a_sweep_over_the_cases_is_checked_case_by_case_and_names_the_governing_line(fmu_file, tmp_path):
    """The storm shortened (the break at 40 s, 60 s in all, the sea grown over 20 s), as a user runs it."""
    text = SCENE.read_text().replace("duration = 900.0", "duration = 60.0").replace("time = 600.0", "time = 40.0")
    text = text.replace('"waves.rampTime" = 60.0', '"waves.rampTime" = 20.0')
    (tmp_path / "storm.toml").write_text(text)
    (tmp_path / "oc4_semi.dat").write_text((REPO_ROOT / "scenes" / "oc4_semi.dat").read_text())
    r = _cli("sweep", "storm.toml", "--vary", "case=intact,damaged,transient", "--workers", "1", "--out", "s",
             cwd=tmp_path, fmu=fmu_file)
    assert r.returncode == 0, r.stderr
    c = _cli("check", "s/results.csv", cwd=tmp_path, fmu=fmu_file)
    assert c.returncode in (0, 3), c.stderr
    out = c.stdout
    for case in ("intact", "damaged", "transient"):
        assert f"{case}: run 1" in (tmp_path / "s" / "check.csv").read_text(), case
    rows = (tmp_path / "s" / "check.csv").read_text().splitlines()
    # line 1 is broken in the damaged and transient cases: it is checked intact only
    assert not any(r.startswith("1,") and ("damaged:" in r or "transient:" in r) for r in rows), rows
    # the windward lines 2 and 3 (symmetric about the load) govern, in the intact case (the break relieves them)
    assert "governing" in out.lower() or "governs" in out.lower(), out
    sentence = [line for line in out.splitlines() if "govern" in line.lower()][-1]
    assert ("line 2" in sentence or "line 3" in sentence) and "intact" in sentence, sentence


@pytest.mark.parametrize("lead, after, steps_", [
    pytest.param(600.0, 60.0, (0.1, 1.0), marks=pytest.mark.slow),
    pytest.param(60.0, 60.0, (0.1, 1.0), marks=pytest.mark.slow),   # 66 s of CPU
    pytest.param(30.0, 20.0, (0.1, 1.0))])                          # 31 s of CPU
def test_a_break_in_a_storm_is_the_same_at_a_fine_and_a_coarse_communication_step(fmu_file, lead, after, steps_):
    """By time: the same break time, exactly; by tension: within the tension tolerance's equivalent time; the
    other lines' peak over the transient after the break within 1 % (at the communication points both runs
    share). The CI variant: a lead-in of 30 s, 20 s after the break."""
    os.environ.setdefault("UC_FMU", str(fmu_file))
    c = steps.compare(lead, steps=steps_, after=after)
    assert c["time"]["break"] == [lead, lead]
    d = c["tension"]
    lo, hi = d["window"]  # where the tension is within the tolerance of the threshold
    assert all(lo <= t <= hi for t in d["break"]), steps.report(c)
    assert lead - steps.PROBE_MARGIN < d["break"][0] < lead + 3 * steps.PROBE_MARGIN, steps.report(c)
    for trigger in ("time", "tension"):
        fine, coarse = c[trigger]["peaks"]
        assert np.all(np.abs(coarse / fine - 1.0) < 0.01), steps.report(c)
