"""System co-simulation: vessel FMU -> cable FMU -> towed-body FMU, each its own unit, described by an
OSP system structure file (systems/*/OspSystemStructure.xml) and run by one of two masters:

- fmpy: a Python loop over the FMUs (FMU2Slave), non-iterative, either Gauss-Seidel (the cable steps
  first, then the body and the vessel with the cable's new outputs) or Jacobi (every unit steps from
  the values of the last communication point, as libcosim's fixed-step algorithm). Optionally it passes
  the tow-point acceleration (the vessel's tow.a*) to the cable as the input derivative der(tow.v*).
- libcosim (libcosimpy): loads the same system file and runs its fixed-step algorithm (Jacobi).
- newton (ucable.newton): the reference iterating master for a body that integrates itself (the explicit
  coupling): the cable-body interface solved by Newton's method per step, both FMUs rolled back.

Couplings of the towed body (COUPLINGS):
  internal  the body inside the cable FMU (bottomEnd 2 with body.CdA): systems/towed_body_internal
  external  the cable FMU integrates the body's translation (bottomEnd 2, body.CdA = 0) and the TowedBody
            FMU supplies its hydrodynamic force with the velocity linearization (endLoad,
            endLoadVelocity, endLoadDamping): systems/towed_body
  explicit  the TowedBody FMU integrates its own translation from the cable force and the cable's far
            end follows it (bottomEnd 3): systems/towed_body_explicit; unstable above a critical step
  proxy     the TowedBody FMU integrates its own translation, the cable integrates a proxy with its inertia
            and returns the force that makes it follow (bottomEnd 4): systems/towed_body_proxy

Initialization follows libcosim: the units enter initialization mode with their start values, then the
connected values are transferred (outputs read in initialization mode, inputs set) as many times as
there are units, then every unit leaves initialization mode. The cable computes its steady state from
the inputs it has then (the body's drag at the tow velocity included).
"""

from __future__ import annotations

import math
import re
import tempfile
import time as timer
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field, replace
from pathlib import Path
from xml.sax.saxutils import escape as xml_escape

import numpy as np

from .fmu import CableFMU
from .paths import REPO_ROOT, fmu_path, systems_dir
from .units import GRAVITY, KNOT

SYSTEM_DIRS = {"internal": "towed_body_internal", "external": "towed_body", "explicit": "towed_body_explicit",
               "proxy": "towed_body_proxy"}
SELF_INTEGRATING = ("explicit", "proxy")  # the body FMU integrates its own translation
COUPLINGS = tuple(SYSTEM_DIRS)
MASTERS = ("fmpy", "libcosim", "newton")
ORDERINGS = ("gauss-seidel", "jacobi")
GAUSS_SEIDEL_ORDER = ("cable", "body", "vessel")  # the cable first, then the units that use its outputs
OSP_NS = "http://opensimulationplatform.com/MSMI/OSPSystemStructure"

# ------------------------------------------------------------------------------------ manoeuvres
# Vessel parameters of each manoeuvre (the Vessel FMU's speed and heading programme) and its default
# duration: accelerate and decelerate are the Hopland (1993) ramps (60 s, then 600 s), the turns start
# at t = 30 s at 1 deg/s, the stop orders zero speed in 5 s from t = 30 s.
_TURN = {"speed0": 2.4 * KNOT, "speed1": 2.4 * KNOT, "turnStart": 30.0, "turnRate": math.radians(1.0)}
# The Vessel FMU's towForceTiming: the tow force it is given is the cable's at the start of its step (it
# extrapolates it with the rate of the last two) or at the end of it (it interpolates from the one before).
TOW_FORCE_AT_STEP_START, TOW_FORCE_AT_STEP_END = 1, 2
MANOEUVRES = {
    "accelerate": ({"speed0": 1.1 * KNOT, "speed1": 2.4 * KNOT, "rampStart": 0.0, "rampDuration": 60.0}, 660.0),
    "decelerate": ({"speed0": 2.5 * KNOT, "speed1": 1.0 * KNOT, "rampStart": 0.0, "rampDuration": 60.0}, 660.0),
    "turn90": ({**_TURN, "turnAngle": math.radians(90.0)}, 300.0),
    "turn180": ({**_TURN, "turnAngle": math.radians(180.0)}, 400.0),
    "stop": ({"speed0": 2.4 * KNOT, "speed1": 0.0, "rampStart": 30.0, "rampDuration": 5.0}, 300.0),
    "circle": ({"speed0": 2.4 * KNOT, "speed1": 2.4 * KNOT, "turnStart": 30.0, "turnRate": math.radians(0.5),
                "turnAngle": 1e6}, 900.0),
}


@dataclass(frozen=True)
class Body:
    """The towed body. Unset values follow the default body (400 kg, 0.1 m3, 100 kg added mass, 0.3 m2
    drag area) scaled to the mass: the same density (4000 kg/m3), added mass a quarter of the mass,
    drag area with mass^(2/3)."""

    mass: float = 400.0
    added_mass: float | None = None
    volume: float | None = None
    cda: float | None = None
    cla: float = 0.0  # depressor lift area (TowedBody FMU only)

    def resolved(self) -> "Body":
        s = self.mass / 400.0
        return replace(self,
                       added_mass=100.0 * s if self.added_mass is None else self.added_mass,
                       volume=0.1 * s if self.volume is None else self.volume,
                       cda=0.3 * s ** (2.0 / 3.0) if self.cda is None else self.cda)


def unit_parameters(coupling: str, body: Body) -> dict:
    """Start values that the coupling and the body set in each unit (beyond the system file's)."""
    b = body.resolved()
    cable_body = {"body.mass": b.mass, "body.volume": b.volume, "body.addedMass": b.added_mass}
    partner = {"mass": b.mass, "addedMass": b.added_mass, "volume": b.volume, "CdA": b.cda, "CLA": b.cla}
    if coupling == "internal":
        if b.cla != 0.0:
            raise ValueError("a depressor lift (CLA) needs the TowedBody FMU: coupling external or explicit")
        return {"cable": {"bottomEnd": 2, **cable_body, "body.CdA": b.cda}}
    if coupling == "external":
        return {"cable": {"bottomEnd": 2, **cable_body, "body.CdA": 0.0}, "body": partner}
    if coupling == "explicit":
        return {"cable": {"bottomEnd": 3}, "body": {**partner, "integrateTranslation": True}}
    if coupling == "proxy":
        return {"cable": {"bottomEnd": 4, **cable_body}, "body": {**partner, "integrateTranslation": True}}
    raise ValueError(f"coupling must be one of {COUPLINGS}")


# ------------------------------------------------------------------------------------ system file
@dataclass
class Simulator:
    name: str
    source: Path
    initial: dict = field(default_factory=dict)  # variable -> value (bool, int or float)


@dataclass(frozen=True)
class Connection:
    source: str  # simulator
    output: str
    target: str
    input: str


@dataclass
class SystemStructure:
    path: Path
    step: float
    simulators: dict  # name -> Simulator
    connections: list

    @classmethod
    def parse(cls, path: Path) -> "SystemStructure":
        path = Path(path)
        root = ET.parse(path).getroot()
        ns = {"o": OSP_NS}
        step = float(root.findtext("o:BaseStepSize", namespaces=ns))
        sims = {}
        for s in root.iterfind("o:Simulators/o:Simulator", ns):
            initial = {}
            for iv in s.iterfind("o:InitialValues/o:InitialValue", ns):
                (v,) = list(iv)
                kind, text, name = v.tag.split("}")[1], v.get("value"), iv.get("variable")
                if kind == "String" and name == "lineFile" and text and not Path(text).is_absolute():
                    text = str((path.parent / text).resolve())  # a deck next to the system file
                initial[name] = (text if kind == "String" else text == "true" if kind == "Boolean" else
                                 int(text) if kind == "Integer" else float(text))
            sims[s.get("name")] = Simulator(s.get("name"), (path.parent / s.get("source")).resolve(), initial)
        conns = []
        for c in root.iterfind("o:Connections/o:VariableConnection", ns):
            a, b = c.iterfind("o:Variable", ns)
            conns.append(Connection(a.get("simulator"), a.get("name"), b.get("simulator"), b.get("name")))
        return cls(path, step, sims, conns)

    def write(self, path: Path, step: float, extra: dict) -> None:
        """A copy with absolute sources, another step and the extra start values {sim: {var: value}}
        (for libcosim, which reads only files)."""
        lines = ['<?xml version="1.0" encoding="utf-8"?>',
                 f'<OspSystemStructure xmlns="{OSP_NS}" version="0.1">',
                 "  <StartTime>0.0</StartTime>", f"  <BaseStepSize>{step!r}</BaseStepSize>",
                 "  <Algorithm>fixedStep</Algorithm>", "  <Simulators>"]
        for s in self.simulators.values():
            lines.append(f'    <Simulator name="{s.name}" source="{s.source}">')
            lines.append("      <InitialValues>")
            for var, value in {**s.initial, **extra.get(s.name, {})}.items():
                if isinstance(value, str):
                    tag, text = "String", xml_escape(value, {'"': "&quot;"})
                elif isinstance(value, bool):
                    tag, text = "Boolean", "true" if value else "false"
                elif isinstance(value, int):
                    tag, text = "Integer", str(value)
                else:
                    tag, text = "Real", repr(float(value))
                lines.append(f'        <InitialValue variable="{var}"><{tag} value="{text}"/></InitialValue>')
            lines += ["      </InitialValues>", "    </Simulator>"]
        lines += ["  </Simulators>", "  <Connections>"]
        for c in self.connections:
            lines.append(f'    <VariableConnection><Variable simulator="{c.source}" name="{c.output}"/>'
                         f'<Variable simulator="{c.target}" name="{c.input}"/></VariableConnection>')
        lines += ["  </Connections>", "</OspSystemStructure>", ""]
        Path(path).write_text("\n".join(lines))


def partner_fmu(name: str) -> Path:
    """<name>.fmu next to the cable FMU (build/ or the directory of $UC_FMU), else in build/."""
    for d in (fmu_path().parent, REPO_ROOT / "build"):
        if (d / f"{name}.fmu").is_file():
            return d / f"{name}.fmu"
    raise FileNotFoundError(f"{name}.fmu not found: build first: scripts/build")


def system_names() -> list[str]:
    """The shipped systems: the folders of systems/ that hold an OspSystemStructure.xml."""
    return sorted(p.parent.name for p in systems_dir().glob("*/OspSystemStructure.xml"))


def system_description(name: str) -> str:
    """A shipped system's description: the first sentence of its system file's leading comment."""
    text = (systems_dir() / name / "OspSystemStructure.xml").read_text()
    m = re.search(r"<!--(.*?)-->", text, re.S)
    if not m:
        return ""
    words = " ".join(m.group(1).split())
    return re.split(r":\s|\.\s|\.$", words, maxsplit=1)[0]


def load_named_system(name: str) -> SystemStructure:
    """A shipped system file by its folder's name, its FMUs resolved to the cable FMU in use and the
    partners next to it."""
    path = systems_dir() / name / "OspSystemStructure.xml"
    if not path.is_file():
        raise FileNotFoundError(f"no system {name!r}: the shipped systems are {', '.join(system_names())}")
    system = SystemStructure.parse(path)
    for s in system.simulators.values():
        s.source = fmu_path() if s.source.name == "UnderwaterCable.fmu" else partner_fmu(s.source.stem)
    return system


def load_system(coupling: str) -> SystemStructure:
    """The system file of a coupling (SYSTEM_DIRS)."""
    return load_named_system(SYSTEM_DIRS[coupling])


# ------------------------------------------------------------------------------------ results
RECORD = {
    "vessel": ["x", "y", "heading", "speed", "thrust", "tow.x", "tow.y", "tow.z", "waveElevation", "platform.x",
               "platform.y", "platform.z", "platform.roll", "platform.pitch", "platform.yaw"],
    "cable": ["towTension", "waveElevation", "towForce.x", "towForce.y", "towForce.z", "endTension", "endForce.x", "endForce.y",
              "endForce.z", "endPosition.x", "endPosition.y", "endPosition.z", "endVelocity.x", "endVelocity.y",
              "endVelocity.z", "bodyForceEstimate.x", "bodyForceEstimate.y", "bodyForceEstimate.z"],
    # a mooring system's cable FMU (systems/moored_platform): its lines and their load on the platform
    "mooring": ["line[1].fairleadTension", "line[2].fairleadTension", "line[3].fairleadTension",
                "body[1].force.x", "body[1].force.y", "body[1].force.z", "body[1].moment.x", "body[1].moment.y",
                "body[1].moment.z"],
    "body": ["position.x", "position.y", "position.z", "velocity.x", "velocity.y", "velocity.z", "force.x",
             "force.y", "force.z"],
}


@dataclass
class SystemResult:
    time: np.ndarray
    values: dict  # "unit.variable" -> (n,) array
    cpu: float
    coupling: str
    master: str
    ordering: str
    step: float
    stats: dict = field(default_factory=dict)  # the newton master's iteration counts (ucable.newton)

    def __getitem__(self, name):
        return self.values[name]

    @property
    def body_position(self) -> np.ndarray:
        """(n, 3) position of the towed body, Earth frame: the cable's far end, which carries the body
        (internal, external), or the body's own state (explicit, proxy: the body integrates itself)."""
        key = "body.position" if self.coupling in SELF_INTEGRATING else "cable.endPosition"
        return np.column_stack([self.values[f"{key}.{q}"] for q in "xyz"])

    def columns(self) -> dict:
        """The result table: time, towTension, body.x/y/z first, then every recorded output."""
        p = self.body_position
        cols = {"time": self.time, "towTension": self.values["cable.towTension"],
                "body.x": p[:, 0], "body.y": p[:, 1], "body.z": p[:, 2]}
        cols.update(self.values)
        return cols


# ------------------------------------------------------------------------------------ fmpy master
DIVERGED_FACTOR = 20.0  # a tow tension this many times the initial one ends a run: the coupling diverged


class Diverged(RuntimeError):
    """The co-simulation blew up (an unstable coupling), detected before an FMU failed."""


class _Unit:
    """One FMU of the system: the fmpy slave, its value references, and the vrs to record."""

    def __init__(self, sim: Simulator, instance_name: str):
        self.fmu = CableFMU(sim.source, instance_name=instance_name)
        self.name = sim.name
        self.vars = self.fmu.variables

    def vrs(self, names):
        return [self.vars[n].valueReference for n in names]

    def get(self, vrs):
        return self.fmu.slave.getReal(vrs)

    def set(self, vrs, values):
        if vrs:
            self.fmu.slave.setReal(vrs, values)


class FmpyMaster:
    """Non-iterative fmpy master over the units of a SystemStructure."""

    def __init__(self, system: SystemStructure, parameters: dict, ordering: str = "gauss-seidel",
                 input_derivatives: bool = True, t_end: float | None = None, tag: str = ""):
        if ordering not in ORDERINGS:
            raise ValueError(f"ordering must be one of {ORDERINGS}")
        self.system, self.ordering, self.t_end = system, ordering, t_end
        self.units = {n: _Unit(s, f"{n}{tag}") for n, s in system.simulators.items()}
        self.parameters = parameters
        # inputs of each unit: (target vrs, [(source unit, source vr)]) for one fmi2SetReal per unit
        self.inputs = {}
        for n in self.units:
            conns = [c for c in system.connections if c.target == n]
            self.inputs[n] = (self.units[n].vrs([c.input for c in conns]),
                              [(c.source, self.units[c.source].vars[c.output].valueReference) for c in conns])
        self.sourced = {n: sorted({vr for m in self.inputs for s, vr in self.inputs[m][1] if s == n})
                        for n in self.units}
        self.derivatives = []  # (target unit, target vrs, source unit, source vrs): der(input) = output
        if input_derivatives:
            pairs = [("vessel", "tow.a", "cable", "tow.v")]
            if any(c.target == "cable" and c.input.startswith("body[1].") for c in system.connections):
                # a platform driving a mooring system: its accelerations as der(body[1].v*, w*)
                pairs += [("vessel", "platform.a", "cable", "body[1].v"),
                          ("vessel", "platform.alpha", "cable", "body[1].w")]
            if "body" in self.units and any(c.input.startswith("end.") and c.target == "cable"
                                            for c in system.connections):
                pairs.append(("body", "acceleration.", "cable", "end.v"))
            for src, out, dst, inp in pairs:  # (a body without an acceleration output gives none)
                if src in self.units and dst in self.units and all(out + q in self.units[src].vars for q in "xyz"):
                    self.derivatives.append((dst, self.units[dst].vrs([inp + q for q in "xyz"]),
                                             src, self.units[src].vrs([out + q for q in "xyz"])))
        self.t = 0.0

    def _snapshot(self, units=None):
        """The connected outputs of the given units (default: all), one fmi2GetReal per unit."""
        snap = {}
        for n in (self.units if units is None else units):
            vrs = self.sourced[n]
            snap[n] = dict(zip(vrs, self.units[n].get(vrs))) if vrs else {}
        return snap

    def _transfer(self, target, snap=None):
        """Sets the inputs of the target unit from its sources' outputs: the snapshot given (Jacobi) or
        their current outputs (Gauss-Seidel)."""
        vrs, sources = self.inputs[target]
        if snap is None:
            snap = self._snapshot({s for s, _ in sources})
        self.units[target].set(vrs, [snap[s][vr] for s, vr in sources])

    def initialize(self):
        for n, u in self.units.items():
            s = self.system.simulators[n]
            u.fmu.slave.setupExperiment(startTime=0.0, stopTime=self.t_end)
            u.fmu.set({**s.initial, **self.parameters.get(n, {})})
            u.fmu.slave.enterInitializationMode()
        for _ in range(len(self.units)):
            snap = self._snapshot()
            for n in self.units:
                self._transfer(n, snap)
        for u in self.units.values():
            u.fmu.slave.exitInitializationMode()
        self.t = 0.0

    def _set_derivatives(self, target):
        for dst, dvrs, src, svrs in self.derivatives:
            if dst == target:
                self.units[dst].fmu.slave.setRealInputDerivatives(dvrs, [1] * len(dvrs), self.units[src].get(svrs))

    def advance(self, h: float, t: float):
        if self.ordering == "jacobi":
            snap = self._snapshot()
            for n in self.units:
                self._transfer(n, snap)
                self._set_derivatives(n)
            for u in self.units.values():
                u.fmu.slave.doStep(t, h)
        else:
            order = [n for n in GAUSS_SEIDEL_ORDER if n in self.units] + \
                    [n for n in self.units if n not in GAUSS_SEIDEL_ORDER]
            for n in order:
                self._transfer(n)
                self._set_derivatives(n)
                self.units[n].fmu.slave.doStep(t, h)
        self.t = t + h

    def free(self):
        for u in self.units.values():
            u.fmu.free()


def _recorded(unit: str, variables, mooring: bool = False) -> list:
    """The variables of RECORD[unit] that the unit has (a vessel without an autopilot has no thrust), with
    a mooring system's lines and body load for the cable FMU of a mooring system."""
    names = RECORD.get(unit, []) + (RECORD["mooring"] if mooring and unit == "cable" else [])
    return [v for v in names if v in variables]


def _mooring(system: SystemStructure) -> bool:
    """Whether the system drives a mooring system's body (a connection to the cable's body[k].* inputs)."""
    return any(c.target == "cable" and c.input.startswith("body[") for c in system.connections)


def _record_vrs(units, mooring: bool = False):
    recorded = {n: _recorded(n, units[n].vars, mooring) for n in units}
    return {n: (names, units[n].vrs(names)) for n, names in recorded.items() if names}


def run_fmpy(system: SystemStructure, parameters: dict, step: float, t_end: float, ordering: str,
             input_derivatives: bool = True, progress=None, newton: dict | None = None) -> SystemResult:
    """The system under the fmpy master; with `newton` (the options of ucable.newton.NewtonMaster) the
    cable-body interface iterated by the Newton master (Gauss-Seidel for the vessel)."""
    n = int(round(t_end / step))
    times = np.arange(n + 1) * step
    master = FmpyMaster(system, parameters, ordering, input_derivatives, t_end=times[-1] + 1e-9)
    if newton is not None:
        from .newton import NewtonMaster

        master = NewtonMaster(master, **newton)
    try:
        rec = _record_vrs(master.units, _mooring(system))
        values = {f"{u}.{v}": np.full(n + 1, math.nan) for u, (names, _) in rec.items() for v in names}

        def record(k):
            for u, (names, vrs) in rec.items():
                for v, x in zip(names, master.units[u].get(vrs)):
                    values[f"{u}.{v}"][k] = x

        cpu0 = timer.process_time()
        master.initialize()
        record(0)
        limit = DIVERGED_FACTOR * max(values["cable.towTension"][0], 1.0)
        for k in range(n):
            master.advance(step, times[k])
            record(k + 1)
            if not abs(values["cable.towTension"][k + 1]) < limit:
                raise Diverged(f"tow tension {values['cable.towTension'][k + 1]:.4g} N at t = {times[k + 1]:g} s "
                               f"(more than {DIVERGED_FACTOR:g} times the initial)")
            if progress is not None and (k % 50 == 0 or k == n - 1):
                progress.update(times[k + 1], f"t = {times[k + 1]:7.2f} s  T = {values['cable.towTension'][k + 1]:8.1f} N")
        cpu = timer.process_time() - cpu0
    except Exception as e:
        logs = list(dict.fromkeys(m for u in master.units.values() for m in u.fmu.messages))
        if logs and not isinstance(e, Diverged):
            print("--- FMU log:\n" + "\n".join(f"[{s}] {c}: {t}" for s, c, t in logs))
        raise
    finally:
        master.free()
    if newton is not None:
        return SystemResult(times, values, cpu, "", "newton", ordering, step, master.stats.as_dict())
    return SystemResult(times, values, cpu, "", "fmpy", ordering, step)


# ------------------------------------------------------------------------------------ libcosim
def run_libcosim(system: SystemStructure, parameters: dict, step: float, t_end: float,
                 progress=None) -> SystemResult:
    """The system under libcosim's fixed-step algorithm (Jacobi); the system file is rewritten with the
    step, absolute FMU paths and the extra start values."""
    from .optional import require

    require("libcosimpy", "--master libcosim")
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.ERROR)
    step_ns = int(round(step * 1e9))
    if abs(step_ns - step * 1e9) > 1e-3:
        raise ValueError("libcosim steps are integer nanoseconds")
    n = int(round(t_end / step))
    times = np.arange(n + 1) * step
    with tempfile.TemporaryDirectory(prefix="ucable-osp-") as tmp:
        path = Path(tmp) / "OspSystemStructure.xml"
        system.write(path, step, parameters)
        cpu0 = timer.process_time()
        ex = CosimExecution.from_osp_config_file(str(path))
        obs = CosimObserver.create_time_series(buffer_size=n + 16)
        ex.add_observer(obs)
        index = {s.name.decode(): s.index for s in ex.slave_infos()}
        vrs = {u: {v.name.decode(): v.reference for v in ex.slave_variables(i)} for u, i in index.items()}
        mooring = _mooring(system)
        rec = {u: _recorded(u, vrs[u], mooring) for u in index if _recorded(u, vrs[u], mooring)}
        for u, names in rec.items():
            for v in names:
                obs.start_time_series(index[u], vrs[u][v], CosimVariableType.REAL)
        for k in range(n):
            if not ex.step():
                raise RuntimeError(f"libcosim step failed at t = {times[k]:g} s")
            if progress is not None and (k % 50 == 0 or k == n - 1):
                progress.update(times[k + 1], f"t = {times[k + 1]:7.2f} s")
        cpu = timer.process_time() - cpu0
        values = {}
        for u, names in rec.items():
            for v in names:
                values[f"{u}.{v}"] = _time_series(obs, index[u], vrs[u][v], n, step_ns)
    return SystemResult(times, values, cpu, "", "libcosim", "jacobi", step)


def _time_series(obs, slave, vr, n, step_ns):
    """Samples 0..n of one variable. libcosimpy trims a sample list by the number of zero step numbers,
    which drops one sample whenever step 0 is in it: step 0 is read alone (two slots), the rest from 1."""
    t0, s0, v0 = obs.time_series_real_samples(slave, vr, 0, 2)
    t1, s1, v1 = obs.time_series_real_samples(slave, vr, 1, n)
    steps = list(s0[:1]) + list(s1)
    if steps != list(range(n + 1)) or any(t != k * step_ns for k, t in zip(steps, list(t0[:1]) + list(t1))):
        raise RuntimeError(f"libcosim time series of variable {vr}: steps {steps[:3]}..{steps[-3:]}, "
                           f"expected 0..{n}")
    return np.array(list(v0[:1]) + list(v1))


# ------------------------------------------------------------------------------------ one run
def steady_far_end(system: SystemStructure, parameters: dict, body: Body) -> dict:
    """Initial state of a body that integrates its own translation (explicit coupling): the steady far
    end of the internal body (bottomEnd 2) towed by the vessel at its initial state."""
    vessel = _Unit(system.simulators["vessel"], "vessel-probe")
    try:
        vessel.fmu.slave.setupExperiment(startTime=0.0)
        vessel.fmu.set({**system.simulators["vessel"].initial, **parameters.get("vessel", {})})
        vessel.fmu.slave.enterInitializationMode()
        tow = vessel.get(vessel.vrs([f"tow.{q}" for q in ("x", "y", "z", "vx", "vy", "vz")]))
    finally:
        vessel.fmu.free()
    internal = unit_parameters("internal", replace(body, cla=0.0))["cable"]
    probe = CableFMU(system.simulators["cable"].source, parameters=internal, instance_name="cable-probe")
    try:
        probe.initialize(0.0, inputs=dict(zip([f"tow.{q}" for q in ("x", "y", "z", "vx", "vy", "vz")], tow)))
        p = probe.get_reals([f"endPosition.{q}" for q in "xyz"])
        v = probe.get_reals([f"endVelocity.{q}" for q in "xyz"])
    finally:
        probe.free()
    return {**{f"position0.{q}": float(x) for q, x in zip("xyz", p)},
            **{f"velocity0.{q}": float(x) for q, x in zip("xyz", v)}}


def run(manoeuvre: str, step: float = 0.5, coupling: str = "external", master: str = "fmpy",
        ordering: str = "gauss-seidel", body: Body = Body(), duration: float | None = None,
        input_derivatives: bool = True, cable_parameters: dict | None = None, waves: dict | None = None,
        vessel_parameters: dict | None = None, progress=None, body_fmu: Path | None = None,
        newton: dict | None = None) -> SystemResult:
    """One system run: the manoeuvre flown by the Vessel FMU, the towed body coupled as `coupling`; `waves`
    (waves.* parameters and waterDepth) are given to the vessel, whose wave-frequency motion is then
    superimposed on its manoeuvre, and to the cable: one sea for both; `vessel_parameters` to the vessel
    alone (raoFile: its RAO table). `body_fmu`: another body FMU that integrates itself in place of the
    TowedBody (coupling explicit or proxy; the TowedBody's names: parameters mass, addedMass, volume, CdA, CLA,
    position0.*, velocity0.*, input cableForce.*, outputs position.*, velocity.*). Master newton: the
    reference iterating master (ucable.newton, options `newton`), coupling explicit."""
    if manoeuvre not in MANOEUVRES:
        raise ValueError(f"manoeuvre must be one of {', '.join(MANOEUVRES)}")
    if master not in MASTERS:
        raise ValueError(f"master must be one of {MASTERS}")
    if master == "libcosim" and ordering != "jacobi":
        raise ValueError("libcosim's fixed-step algorithm is Jacobi: use ordering jacobi")
    if master == "newton" and coupling != "explicit":
        raise ValueError("the newton master iterates with a body that integrates itself: coupling explicit")
    if body_fmu is not None and coupling not in SELF_INTEGRATING:
        raise ValueError(f"a body FMU of its own integrates itself: coupling {' or '.join(SELF_INTEGRATING)}")
    vessel, default_duration = MANOEUVRES[manoeuvre]
    t_end = default_duration if duration is None else duration
    system = load_system(coupling)
    params = unit_parameters(coupling, body)
    if body_fmu is not None:
        unit = system.simulators["body"]
        unit.source, unit.initial = Path(body_fmu), {}
        params["body"].pop("integrateTranslation")
    # when the vessel's towForce input was taken: Gauss-Seidel (fmpy, newton) steps the cable first, so the
    # vessel gets the force of its step's end; Jacobi (fmpy, libcosim) the force of its step's start
    timing = TOW_FORCE_AT_STEP_END if master == "newton" or (master == "fmpy" and ordering == "gauss-seidel") \
        else TOW_FORCE_AT_STEP_START
    params["vessel"] = {**vessel, "towForceTiming": timing, **(waves or {}), **(vessel_parameters or {})}
    params["cable"] = {**params["cable"], **(cable_parameters or {}), **(waves or {})}
    if coupling in SELF_INTEGRATING:
        start = steady_far_end(system, params, body)
        params["body"].update(start)
        # the cable's far end starts there too (its first steady state is computed before the body's
        # position has been transferred)
        params["cable"].update({f"end.{q}": start[f"position0.{q}"] for q in "xyz"})
        params["cable"].update({f"end.v{q}": start[f"velocity0.{q}"] for q in "xyz"})
    if master == "libcosim":
        result = run_libcosim(system, params, step, t_end, progress)
    elif master == "newton":
        b = body.resolved()
        options = {"body_weight": b.mass * GRAVITY, **(newton or {})}
        result = run_fmpy(system, params, step, t_end, "gauss-seidel", True, progress, newton=options)
    else:
        result = run_fmpy(system, params, step, t_end, ordering, input_derivatives, progress)
    result.coupling = coupling
    return result


# ------------------------------------------------------------------------------------ a shipped system
COUPLING_OF_SYSTEM = {d: c for c, d in SYSTEM_DIRS.items()}
SYSTEM_DURATIONS = {"heave_lowering": 300.0, "moored_platform": 300.0}  # the towed-body systems: their manoeuvre's


def named_duration(name: str, manoeuvre: str = "accelerate", duration: float | None = None) -> float:
    """The simulated time of a shipped system's run: `duration`, else the manoeuvre's or the system's."""
    if duration is not None:
        return duration
    if name in COUPLING_OF_SYSTEM:
        if manoeuvre not in MANOEUVRES:
            raise ValueError(f"manoeuvre must be one of {', '.join(MANOEUVRES)}")
        return MANOEUVRES[manoeuvre][1]
    return SYSTEM_DURATIONS.get(name, 300.0)


def run_named(name: str, master: str = "fmpy", step: float | None = None, duration: float | None = None,
              manoeuvre: str = "accelerate", progress=None) -> SystemResult:
    """A shipped system (systems/NAME) as its file describes it. The towed-body systems fly
    `manoeuvre` (their file's vessel flies accelerate); the others run from their start values."""
    if master not in MASTERS:
        raise ValueError(f"master must be one of {', '.join(MASTERS)}")
    if master == "newton" and COUPLING_OF_SYSTEM.get(name) != "explicit":
        raise ValueError(f"the newton master iterates with a body that integrates itself: system "
                         f"{SYSTEM_DIRS['explicit']}, not {name}")
    ordering = "jacobi" if master == "libcosim" else "gauss-seidel"
    system = load_named_system(name)
    h = system.step if step is None else step
    t_end = named_duration(name, manoeuvre, duration)
    if name in COUPLING_OF_SYSTEM:
        return run(manoeuvre, h, COUPLING_OF_SYSTEM[name], master, ordering, duration=t_end, progress=progress)
    if master == "libcosim":
        return run_libcosim(system, {}, h, t_end, progress)
    return run_fmpy(system, {}, h, t_end, ordering, True, progress)
