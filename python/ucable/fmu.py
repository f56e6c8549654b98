"""CableFMU: a thin, name-based wrapper around fmpy's FMU2Slave for the UnderwaterCable FMU.

    from ucable.fmu import CableFMU
    with CableFMU(parameters={"nElements": 20}) as cable:
        cable.initialize(inputs={"tow.vx": 0.566})
        cable.do_step(0.5)
        print(cable.get("towTension"))

The FMU is extracted once per process (per file and modification time) and every CableFMU
instantiates from that directory: fmpy dlopens the same .so, which also exercises the FMU's
"no global state" promise when several instances are alive.
"""

from __future__ import annotations

import atexit
import itertools
import shutil
import weakref
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException  # noqa: F401  (re-exported for tests)
from fmpy.fmi2 import (FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE)
from fmpy import calloc, free

from .paths import require_fmu
from .variables import NUM_STATIONS

STATUS_LABELS = ["OK", "WARNING", "DISCARD", "ERROR", "FATAL", "PENDING"]

_extracted: dict = {}  # (path, mtime) -> (unzip dir, model description)


def _cleanup() -> None:
    for unzipdir, _ in _extracted.values():
        shutil.rmtree(unzipdir, ignore_errors=True)


atexit.register(_cleanup)


# The FMU formats its messages itself and hands the logger a text in which '%' and '#' are doubled
# (a printf format without arguments), so the wrapper needs no formatting proxy: fmpy's logger proxy
# keeps ONE Python logger per process, and whoever registers next (fmpy.simulate_fmu(logger=...), another
# wrapper) leaves the earlier instances calling a logger that may be gone (a crash). Every CableFMU
# passes the same process-wide logger, kept alive for the process, directly to the FMU, with its own
# number as the componentEnvironment the FMU passes back with each message; the logger hands the message
# to the live instance with that number (held weakly: an instance dropped without free() is collected,
# and its finalizer frees the FMU instance).
_instances: "weakref.WeakValueDictionary[int, CableFMU]" = weakref.WeakValueDictionary()
_numbers = itertools.count(1)


def _unescape(message: bytes | None) -> str:
    text = message.decode("utf-8", "replace") if message else ""
    return text.replace("%%", "%").replace("##", "#")


def _dispatch_log(env, instance, status, category, message) -> None:
    unit = _instances.get(env)
    if unit is not None:
        unit._log(env, instance, status, category, message)


_process_logger = fmi2CallbackLoggerTYPE(_dispatch_log)


def _release(slave, state: dict) -> None:
    """Frees the FMU instance once (free(), or the finalizer of an instance dropped without it); the
    slave holds the callbacks, so they live as long as the FMU instance."""
    if not state["freed"]:
        state["freed"] = True
        slave.freeInstance()


def load(path: str | Path | None = None):
    """(unzip directory, model description) of the FMU, extracted once per process."""
    path = Path(path) if path is not None else require_fmu()
    key = (str(path.resolve()), path.stat().st_mtime_ns)
    if key not in _extracted:
        md = read_model_description(str(path))
        _extracted[key] = (extract(str(path)), md)
    return _extracted[key]


class CableFMU:
    """One instance of the UnderwaterCable FMU, addressed by variable names.

    Log messages of the FMU are collected in `self.messages` as (status label, category, text)
    and, if `echo_log` is true, printed as well; a path inside the FMU's temporary extraction reads
    <UnderwaterCable.fmu>/resources/...
    """

    def __init__(self, path: str | Path | None = None, parameters: dict | None = None,
                 instance_name: str = "cable", logging_on: bool = False, echo_log: bool = False):
        self.unzipdir, self.model_description = load(path)
        # messages name the FMU's files as <UnderwaterCable.fmu>/..., not fmpy's temporary extraction
        self._extracted_as = (str(self.unzipdir), f"<{Path(path if path is not None else require_fmu()).name}>")
        md = self.model_description
        self.variables = {v.name: v for v in md.modelVariables}
        self._real_vrs: dict = {}  # get_reals: value references by tuple of names
        self.messages: list = []
        self._echo = echo_log
        self.time = None
        self._initialized = False

        # Callbacks must outlive the FMU instance (it keeps the pointers): the slave keeps them, and
        # the logger is the process-wide one; componentEnvironment routes its messages back here.
        self._number = next(_numbers)
        self._callbacks = fmi2CallbackFunctions()
        self._callbacks.logger = _process_logger
        self._callbacks.componentEnvironment = self._number
        self._callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self._callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)

        self.slave = FMU2Slave(guid=md.guid, unzipDirectory=self.unzipdir,
                               modelIdentifier=md.coSimulation.modelIdentifier,
                               instanceName=instance_name)
        _instances[self._number] = self
        try:
            self.slave.instantiate(callbacks=self._callbacks, loggingOn=logging_on)
        except BaseException:
            _instances.pop(self._number, None)
            raise
        self._release_state = {"freed": False}
        self._finalizer = weakref.finalize(self, _release, self.slave, self._release_state)
        self._pending_parameters = dict(parameters or {})

    # ------------------------------------------------------------------ logging
    def _log(self, _env, _instance, status, category, message):
        text = _unescape(message).replace(*self._extracted_as)
        label = STATUS_LABELS[status] if 0 <= status < len(STATUS_LABELS) else str(status)
        cat = category.decode("utf-8", "replace") if category else ""
        self.messages.append((label, cat, text))
        if self._echo:
            print(f"[{label}] {cat}: {text}")

    def log_text(self) -> str:
        return "\n".join(f"[{s}] {c}: {m}" for s, c, m in self.messages)

    # ------------------------------------------------------------------ set/get by name
    def _var(self, name: str):
        try:
            return self.variables[name]
        except KeyError:
            raise KeyError(f"the FMU has no variable named {name!r}") from None

    def set(self, values: dict) -> None:
        """Set parameters or inputs by name (Real, Integer, Boolean, String), one fmi2Set call per type."""
        groups: dict = {"Real": ([], []), "Integer": ([], []), "Boolean": ([], []),
                        "Enumeration": ([], []), "String": ([], [])}
        for name, value in values.items():
            v = self._var(name)
            vrs, vals = groups[v.type]
            vrs.append(v.valueReference)
            vals.append(value)
        if groups["Real"][0]:
            self.slave.setReal(groups["Real"][0], [float(x) for x in groups["Real"][1]])
        ints = groups["Integer"][0] + groups["Enumeration"][0]
        if ints:
            self.slave.setInteger(ints, [int(x) for x in groups["Integer"][1] + groups["Enumeration"][1]])
        if groups["Boolean"][0]:
            self.slave.setBoolean(groups["Boolean"][0], [bool(x) for x in groups["Boolean"][1]])
        if groups["String"][0]:
            self.slave.setString(groups["String"][0], [str(x) for x in groups["String"][1]])

    def get(self, name: str):
        """One output/parameter by name."""
        v = self._var(name)
        if v.type == "Real":
            return self.slave.getReal([v.valueReference])[0]
        if v.type in ("Integer", "Enumeration"):
            return self.slave.getInteger([v.valueReference])[0]
        if v.type == "Boolean":
            return self.slave.getBoolean([v.valueReference])[0]
        if v.type == "String":
            return self.slave.getString([v.valueReference])[0].decode("utf-8")
        raise TypeError(f"{name}: unsupported type {v.type}")

    def get_reals(self, names) -> np.ndarray:
        """Several Real variables with one fmi2GetReal call (the value references of a list of names looked
        up once: a scene reads the same list at every communication point)."""
        key = names if isinstance(names, tuple) else tuple(names)
        vrs = self._real_vrs.get(key)
        if vrs is None:
            vrs = self._real_vrs[key] = [self._var(n).valueReference for n in key]
        return np.array(self.slave.getReal(vrs))

    def shape(self) -> dict:
        """shape.x/y/z[k] and tension[k], k = 1..21 (index 0 = tow point), as numpy arrays."""
        out = {}
        for key in ("shape.x", "shape.y", "shape.z", "tension"):
            out[key] = self.get_reals([f"{key}[{k}]" for k in range(1, NUM_STATIONS + 1)])
        return out

    # ------------------------------------------------------------------ life cycle
    def initialize(self, start_time: float = 0.0, stop_time: float | None = None,
                   parameters: dict | None = None, inputs: dict | None = None,
                   tolerance: float | None = None) -> None:
        """setupExperiment, parameters, initial inputs, enter/exit initialization mode."""
        self.slave.setupExperiment(tolerance=tolerance, startTime=start_time, stopTime=stop_time)
        params = dict(self._pending_parameters)
        params.update(parameters or {})
        if params:
            self.set(params)
        if inputs:
            self.set(inputs)
        self.slave.enterInitializationMode()
        self.slave.exitInitializationMode()
        self.time = start_time
        self._initialized = True

    def do_step(self, h: float, t: float | None = None) -> None:
        """One communication step from t (default: the current time) to t + h."""
        t0 = self.time if t is None else t
        self.slave.doStep(currentCommunicationPoint=t0, communicationStepSize=h)
        self.time = t0 + h

    def set_input_derivatives(self, names, order: int, values) -> None:
        vrs = [self._var(n).valueReference for n in names]
        self.slave.setRealInputDerivatives(vrs, [order] * len(vrs), [float(v) for v in values])

    @property
    def can_interpolate_inputs(self) -> bool:
        cs = self.model_description.coSimulation
        return bool(getattr(cs, "canInterpolateInputs", False))

    # ------------------------------------------------------------------ FMU state
    def get_state(self):
        return self.slave.getFMUstate()

    def set_state(self, state, time: float | None = None) -> None:
        self.slave.setFMUstate(state)
        if time is not None:
            self.time = time

    def free_state(self, state) -> None:
        self.slave.freeFMUstate(state)

    def serialize_state(self, state) -> bytes:
        return self.slave.serializeFMUstate(state)

    def deserialize_state(self, data: bytes):
        return self.slave.deSerializeFMUstate(data)

    # ------------------------------------------------------------------ teardown
    def terminate(self) -> None:
        self.slave.terminate()

    def free(self) -> None:
        """Frees the FMU instance (also done when the CableFMU is collected or at exit)."""
        try:
            self._finalizer()
        finally:
            _instances.pop(self._number, None)

    @property
    def _freed(self) -> bool:
        return self._release_state["freed"]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        try:
            if self._initialized and exc[0] is None:
                self.terminate()
        finally:
            self.free()
        return False
