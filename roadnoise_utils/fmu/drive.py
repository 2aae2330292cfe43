"""Driving an exported tire FMU from Python with a standard FMU runner (fmpy), step by step.

A co-simulation master's loop at each communication point ``t_k``: set the inputs at ``t_k``,
read the outputs at ``t_k``, then ``doStep(t_k, dt)``. The tire FMU has direct feedthrough (its
exact first-order hold needs the input at ``t_k``), so its outputs are read after the inputs
are set. :class:`TireSlave` wraps fmpy's ``FMU2Slave`` for that loop; :func:`run_fmu` drives it over
whole input histories. fmpy is needed here only (the FMU itself runs without Python).
"""

from __future__ import annotations

import shutil
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .export import REFERENCES, ROAD_REFERENCE


class FmuError(RuntimeError):
    """The FMU answered a call with an error; the message is what its logger reported."""


@dataclass(frozen=True, eq=False)
class FmuRun:
    """Outputs of :func:`run_fmu` (N), one per communication point, and the times (s)."""

    t: np.ndarray
    F_M: np.ndarray
    F_F: np.ndarray
    F_H: np.ndarray


class TireSlave:
    """An exported tire FMU instantiated by fmpy, with the messages its logger reports kept in :attr:`messages`."""

    def __init__(self, path: str | Path, instance_name: str = "tire"):
        from fmpy import calloc, extract, free, read_model_description
        from fmpy.fmi2 import (
            FMU2Slave,
            fmi2CallbackAllocateMemoryTYPE,
            fmi2CallbackFreeMemoryTYPE,
            fmi2CallbackFunctions,
            fmi2CallbackLoggerTYPE,
        )

        self.path = Path(path)
        self.description = read_model_description(str(self.path))
        self.dt = float(self.description.defaultExperiment.stepSize)
        self.variables = {v.name: v for v in self.description.modelVariables}
        self.n_strips = sum(1 for name in self.variables if name.startswith("road_height["))
        self.speed = float(self.variables["speed"].start)
        self.leading_edge = float(self.variables["leading_edge_x"].start)
        self.strip_y = np.array([float(self.variables[f"road_y[{k + 1}]"].start) for k in range(self.n_strips)])
        self.messages: list[str] = []

        def logger(environment, instance, status, category, message):
            self.messages.append(message.decode() if isinstance(message, bytes) else str(message))

        # kept on the instance: the FMU holds pointers to them for its lifetime
        self._callbacks = fmi2CallbackFunctions()
        self._callbacks.logger = fmi2CallbackLoggerTYPE(logger)
        self._callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self._callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self._unzipped = extract(str(self.path))
        self.slave = FMU2Slave(
            guid=self.description.guid,
            unzipDirectory=self._unzipped,
            modelIdentifier=self.description.coSimulation.modelIdentifier,
            instanceName=instance_name,
        )
        try:
            self.slave.instantiate(callbacks=self._callbacks, loggingOn=False)
        except Exception as error:
            shutil.rmtree(self._unzipped, ignore_errors=True)
            raise FmuError(self.messages[-1] if self.messages else str(error)) from error
        self.slave.setupExperiment(startTime=0.0)
        self.slave.enterInitializationMode()
        self.slave.exitInitializationMode()
        self.time = 0.0
        self._road = [ROAD_REFERENCE + k for k in range(self.n_strips)]
        self._outputs = [REFERENCES[name] for name in ("F_M", "F_F", "F_H")]

    def _call(self, function, *args):
        try:
            return function(*args)
        except Exception as error:  # fmpy raises on fmi2Error; the FMU's own message is in the log
            detail = self.messages[-1] if self.messages else str(error)
            raise FmuError(detail) from error

    def set(self, road: np.ndarray, hub: float) -> None:
        """Set the inputs at the current point: the leading-edge heights (n_strips,) and the hub displacement (m)."""
        self._call(self.slave.setReal, self._road + [REFERENCES["hub_displacement"]], [*map(float, road), float(hub)])

    def outputs(self) -> np.ndarray:
        """``[F_M, F_F, F_H]`` (N) at the current point, for the inputs set."""
        return np.array(self._call(self.slave.getReal, self._outputs))

    def step(self, dt: float | None = None) -> None:
        """Advance one communication step (the FMU's own unless ``dt`` is given)."""
        dt = self.dt if dt is None else dt
        self._call(self.slave.doStep, self.time, dt)
        self.time += dt

    def close(self) -> None:
        self.slave.terminate()
        self.slave.freeInstance()
        shutil.rmtree(self._unzipped, ignore_errors=True)

    def __enter__(self) -> TireSlave:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def run_fmu(path: str | Path, road: np.ndarray, hub: np.ndarray | None = None) -> FmuRun:
    """Drive the FMU at ``path`` over ``road`` (n_strips, n) leading-edge heights (m; a 1-D road feeds every
    strip) with the hub displacement ``hub`` (n,) (m; default held at 0); outputs at each of the n points.

    The FMU starts in the steady state of the first inputs (constant inputs give the static force throughout);
    :func:`roadnoise_utils.rm.simulation.simulate` starts at rest, so the two agree for inputs starting at 0."""
    road = np.asarray(road, float)
    with TireSlave(path) as slave:
        road = np.broadcast_to(road, (slave.n_strips, road.shape[-1])) if road.ndim == 1 else road
        if road.ndim != 2 or road.shape[0] != slave.n_strips:
            raise ValueError(f"road must be (n_strips = {slave.n_strips}, n) or (n,), got shape {road.shape}")
        n = road.shape[1]
        hub = np.zeros(n) if hub is None else np.asarray(hub, float)
        if hub.shape != (n,):
            raise ValueError(f"hub must have one value per road sample ({n}), got shape {hub.shape}")
        out = np.empty((n, 3))
        for k in range(n):
            slave.set(road[:, k], hub[k])
            out[k] = slave.outputs()
            if k + 1 < n:
                slave.step()
        t = slave.dt * np.arange(n)
    return FmuRun(t=t, F_M=out[:, 0], F_F=out[:, 1], F_H=out[:, 2])
