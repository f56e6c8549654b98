"""Golden results: a few short scenes whose every output is stored exactly (as hex floats).

Refactors that must not change the numbers (the variable schema, the compiled line description,
a one-section line described by the scalar parameters; for the Vessel partner FMU, its optional
wave motion left off) are checked against these files bit for bit by tests/python/test_golden.py.
Regenerate only when a change of the numbers is intended:

    PYTHONPATH=python .venv/bin/python -m studies.cases.golden --write
"""

from __future__ import annotations

import argparse
import json
import math

from ucable.fmu import CableFMU
from ucable.paths import REPO_ROOT
from ucable.units import KNOT

GOLDEN_DIR = REPO_ROOT / "tests" / "data" / "golden"

# name -> (parameters, function t -> tow inputs, step, n steps)
SCENES = {
    "hopland_ramp": dict(
        parameters={"nElements": 10},
        tow=lambda t: _ramp(t, 1.1 * KNOT, 2.4 * KNOT, 2.0, 10.0),
        step=0.5, steps=40),
    "anchored_chain_seabed": dict(
        parameters={"nElements": 12, "length": 400.0, "diameter": 0.14, "massPerLength": 180.0,
                    "EA": 1.5e9, "axialDamping": 1.5e7, "EI": 0.0, "enableBending": False,
                    "bottomEnd": 1, "anchor.x": 330.0, "anchor.y": 0.0, "anchor.z": -150.0,
                    "enableSeabed": True, "waterDepth": 150.0, "seabedStiffness": 1e6,
                    "seabedFriction": 0.3, "enableCompression": False,
                    "initialDirection.x": 0.8, "initialDirection.z": -0.6},
        tow=lambda t: _surge(t, 4.0, 20.0),
        step=0.25, steps=40),
    "towed_body_torsion": dict(
        parameters={"nElements": 8, "bottomEnd": 2, "body.mass": 400.0, "body.volume": 0.1,
                    "body.addedMass": 100.0, "body.CdA": 0.5, "enableTorsion": True,
                    "torqueMode": 1, "topEnd": 1, "topTangent.x": 0.2, "topTangent.z": -1.0},
        tow=lambda t: dict(_ramp(t, 1.0, 1.5, 0.0, 5.0), torque=20.0 * min(t, 5.0)),
        step=0.5, steps=20),
}


# The Vessel partner FMU: name -> (parameters, function t -> tow force, step, n steps). A speed ramp and a
# turn under a tow force that changes with time (it yaws the vessel and loads the speed loop). Recorded
# with the heading loop a PD (its integral action, added later, off: headingIntegralBandwidth 0), which
# the PID must reproduce bit for bit with its integral pole at 0, and with the tow force held over a step
# (towForceTiming 0; the default, added later, extrapolates it from the last two inputs).
VESSEL_SCENES = {
    "vessel_ramp_turn": dict(
        parameters={"speed0": 1.1 * KNOT, "speed1": 2.4 * KNOT, "rampStart": 5.0, "rampDuration": 30.0,
                    "turnStart": 10.0, "turnRate": math.radians(1.5), "turnAngle": math.radians(45.0),
                    "headingIntegralBandwidth": 0.0, "towForceTiming": 0},
        force=lambda t: {"towForce.x": -4000.0 - 50.0 * t, "towForce.y": 1500.0 * math.sin(0.1 * t),
                         "towForce.z": -3000.0},
        step=0.5, steps=120),
}


def _ramp(t: float, v0: float, v1: float, t0: float, t1: float) -> dict:
    """Tow along +x at v0, ramped linearly to v1 between t0 and t1."""
    a = (v1 - v0) / (t1 - t0)
    if t <= t0:
        x, v, acc = v0 * t, v0, 0.0
    elif t <= t1:
        x, v, acc = v0 * t + 0.5 * a * (t - t0) ** 2, v0 + a * (t - t0), a
    else:
        x = v0 * t1 + 0.5 * a * (t1 - t0) ** 2 + v1 * (t - t1)
        v, acc = v1, 0.0
    return {"tow.x": x, "tow.vx": v, "_ax": acc}


def _surge(t: float, amplitude: float, period: float) -> dict:
    w = 2.0 * math.pi / period
    return {"tow.x": amplitude * math.sin(w * t), "tow.vx": amplitude * w * math.cos(w * t),
            "_ax": -amplitude * w * w * math.sin(w * t)}


def _output_names(cable: CableFMU) -> list:
    return [v.name for v in cable.model_description.modelVariables if v.causality == "output"]


def run_scene(name: str, fmu_path=None) -> dict:
    """Every output at every communication point: {name: [hex floats]} plus the times."""
    scene = SCENES[name]
    with CableFMU(fmu_path, parameters=scene["parameters"]) as cable:
        names = _output_names(cable)
        inputs = scene["tow"](0.0)
        ax = inputs.pop("_ax")
        cable.initialize(inputs=inputs)
        rows = [cable.get_reals(names)]
        times = [0.0]
        for n in range(scene["steps"]):
            t = n * scene["step"]
            inputs = scene["tow"](t)
            ax = inputs.pop("_ax")
            cable.set(inputs)
            cable.set_input_derivatives(["tow.vx"], 1, [ax])
            cable.do_step(scene["step"], t)
            rows.append(cable.get_reals(names))
            times.append(t + scene["step"])
    return {"time": [float(t).hex() for t in times],
            "outputs": {n: [float(r[i]).hex() for r in rows] for i, n in enumerate(names)}}


def run_vessel_scene(name: str, fmu_path=None, parameters: dict | None = None) -> dict:
    """Every output of the Vessel FMU at every communication point, as run_scene; `parameters` are set
    over the scene's own."""
    from ucable.system import partner_fmu
    scene = VESSEL_SCENES[name]
    with CableFMU(fmu_path or partner_fmu("Vessel"), parameters={**scene["parameters"], **(parameters or {})},
                  instance_name="vessel") as vessel:
        names = _output_names(vessel)
        vessel.initialize(0.0, scene["step"] * scene["steps"], inputs=scene["force"](0.0))
        rows, times = [vessel.get_reals(names)], [0.0]
        for n in range(scene["steps"]):
            t = n * scene["step"]
            vessel.set(scene["force"](t))
            vessel.do_step(scene["step"], t)
            rows.append(vessel.get_reals(names))
            times.append(t + scene["step"])
    return {"time": [float(t).hex() for t in times],
            "outputs": {n: [float(r[i]).hex() for r in rows] for i, n in enumerate(names)}}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="write tests/data/golden/*.json")
    parser.add_argument("--fmu", default=None)
    parser.add_argument("--vessel-fmu", default=None, help="the Vessel FMU (default: next to the cable's)")
    args = parser.parse_args(argv)
    runs = [(name, lambda name=name: run_scene(name, args.fmu)) for name in SCENES]
    runs += [(name, lambda name=name: run_vessel_scene(name, args.vessel_fmu)) for name in VESSEL_SCENES]
    for name, run in runs:
        result = run()
        if args.write:
            GOLDEN_DIR.mkdir(parents=True, exist_ok=True)
            (GOLDEN_DIR / f"{name}.json").write_text(json.dumps(result, indent=0) + "\n")
        print(f"{name}: {len(result['outputs'])} outputs x {len(result['time'])} points")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
