"""The moving-hub RM tire's numbers for the FMU: the footprint's road taps and the modal sections.

The FMU (:mod:`roadnoise_utils.fmu.export`) runs one C source for every tire; what makes it a
given tire is this table, written to ``resources/tire.bin`` and read at instantiation.

**The road.** The FMU is given, at every step, the road height at the footprint's leading
edge, one per lateral strip (a 2-D road: one height for all). With a rolling speed ``V`` and a
step ``dt`` the road advances ``V dt`` per step, so the road under the footprint is the last
``n_taps`` leading-edge heights. For a road linear between those samples, the displacement of
tassello ``i`` is exactly a fixed weighted sum of them, the weights being the footprint's
averaging kernels (paper, *Simulation of Wheel-Road Interaction*; :func:`.road.kernels.strip_kernels`)
correlated with a linear hat (:func:`road_taps`): the same correlation, on the same grid,
as :func:`.road.input.profile_input` and :func:`.rm.aggregated.road_hub_force`.

**The tire.** The moving-hub model of Eq. 7 (:func:`.rm.moving_hub.assemble_moving_hub`) split
into modal sections (:func:`.rm.simulation.modal_sections`), each with its exact first-order
hold (FOH) recursion :math:`x_k = e\\,x_{k-1} + b_0 v_{k-1} + b_1 v_k` (the section's gain folded
into :math:`b_0, b_1`), output ``factor * Re(x_k)``: as :func:`.rm.simulation.simulate` runs them.

**The file** (little-endian): ``b"RNTIRE\\0\\0"``; int32 ``[version, n_strips, n_tasselli, n_taps,
n_sections, n_rows]``; the FMU's GUID, ASCII, zero-padded to 64 bytes (the C source refuses a file whose
GUID is not its model description's: resources swapped between FMUs); float64 ``[dt, speed, leading_edge]``; float64 ``strip_y[n_strips]``; float64 ``direct[n_tasselli + 1]``;
int32 ``row_strip[n_rows]``, ``row_tassello[n_rows]``; float64 ``taps[n_rows, n_taps]``; int32
``source[n_sections]``; float64 ``e_re, e_im, b0_re, b0_im, b1_re, b1_im, factor`` (each
``[n_sections]``); ``b"RNTIREND"``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import guards
from ..rm.fitting import FitSet
from ..rm.moving_hub import assemble_moving_hub
from ..rm.simulation import ModalSections, foh_coefficients, modal_sections
from ..road.input import MAX_SPEED, ROAD_GRID, check_sampling, sample_rate_for, strip_centres
from ..road.kernels import strip_kernels
from ..tire.model import Footprint

MAGIC, END, VERSION = b"RNTIRE\0\0", b"RNTIREND", 2
GUID_BYTES = 64
#: The correlation grid is this many times finer than one step of road (:func:`.road.input.profile_input`'s default).
OVERSAMPLE = 4


@dataclass(frozen=True, eq=False)
class TireTables:
    """Everything the FMU's C source needs of one tire at one speed and step.

    Attributes
    ----------
    dt, speed : float
        The FMU's only communication step (s) and the rolling speed it was built for (m/s).
    leading_edge : float
        Where the road heights are taken: this far ahead of the footprint's centre (m, along the
        travel): the road point that enters the footprint at this step.
    strip_y : ndarray (n_strips,)
        Lateral position of each road input (m); one input at 0 for a road uniform across the width.
    direct : ndarray (n_tasselli + 1,)
        Feedthrough of each tassello's displacement, then of the hub's (N/m).
    row_strip, row_tassello : ndarray of int (n_rows,)
        Each tap row's road input and tassello.
    taps : ndarray (n_rows, n_taps)
        Weight of the road input ``m`` steps ago on the row's tassello (-).
    source : ndarray of int (n_sections,)
        Input of each modal section: a tassello, or ``n_tasselli`` for the hub.
    e, b0, b1 : ndarray complex (n_sections,)
        FOH recursion of each section, its gain folded into ``b0`` and ``b1``.
    factor : ndarray (n_sections,)
        2 for a conjugate pair (its upper member stands for both), 1 for a real pole.
    """

    dt: float
    speed: float
    leading_edge: float
    strip_y: np.ndarray
    direct: np.ndarray
    row_strip: np.ndarray
    row_tassello: np.ndarray
    taps: np.ndarray
    source: np.ndarray
    e: np.ndarray
    b0: np.ndarray
    b1: np.ndarray
    factor: np.ndarray

    @property
    def n_strips(self) -> int:
        return int(self.strip_y.size)

    @property
    def n_tasselli(self) -> int:
        return int(self.direct.size - 1)

    @property
    def n_states(self) -> int:
        """States of the moving-hub model: 2 per conjugate pair, 1 per real pole."""
        return int(np.sum(np.where(self.factor == 2.0, 2, 1)))


def road_taps(static: Footprint, speed: float, dt: float, lateral: bool) -> tuple[list, float, int, np.ndarray]:
    """Tap rows ``[(strip, tassello, weights (n_taps,))]``, the leading edge (m), ``n_taps`` and the strips' y.

    Row ``(s, i, w)``: tassello ``i``'s displacement at step ``k`` gets ``sum_m w[m] z_s[k - m]`` from the
    leading-edge heights ``z_s`` of strip ``s``. The footprint point at ``x`` sees the road at ``x + d``
    (:func:`.road.input.profile_input`): on the correlation grid ``x_n = x0 + n step`` (``step = V dt / 4``)
    the point ``x_n`` sees the road ``q_n = (x_lead - x_n) / (V dt)`` steps behind the leading edge, a
    height linear between the samples ``floor(q_n)`` and ``floor(q_n) + 1``.
    """
    grid = speed * dt
    step = grid / OVERSAMPLE
    parts, x0 = strip_kernels(static.tasselli, step)
    n_x = parts[0][2].shape[1]
    leading_edge = x0 + (n_x - 1) * step
    behind = (n_x - 1 - np.arange(n_x)) / OVERSAMPLE  # q_n, in steps
    below = np.floor(behind).astype(int)
    frac = behind - below
    n_taps = int(below.max()) + 2
    hat = np.zeros((n_x, n_taps))  # the road at x_n as weights of the leading-edge samples
    hat[np.arange(n_x), below] += 1.0 - frac
    hat[np.arange(n_x), below + 1] += frac
    strips = sorted({strip for strip, _, _ in parts}) if lateral else [0]
    rows: dict[tuple[int, int], np.ndarray] = {}
    for strip, tasselli, kernels in parts:
        weights = step * kernels @ hat  # (rows, n_taps)
        target = strips.index(strip) if lateral else 0
        for tassello, w in zip(tasselli, weights):
            key = (target, int(tassello))
            rows[key] = rows.get(key, 0.0) + w
    y = strip_centres(static)[strips] if lateral else np.zeros(1)
    return [(s, i, w) for (s, i), w in sorted(rows.items())], float(leading_edge), n_taps, np.asarray(y, float)


def check_stable(fits: FitSet, hub: FitSet) -> None:
    """Refuse fits with a pole of real part >= 0, naming the tassello (or the hub): the FMU would diverge."""
    for label, fit_set in (("tassello", fits), ("hub", hub)):
        for k, fit in enumerate(fit_set):
            worst = float(np.max(fit.poles.real)) if fit.poles.size else -1.0
            if worst >= 0.0:
                where = f"tassello {k}" if label == "tassello" else "the hub (G_H)"
                raise ValueError(
                    f"the fit of {where} has a pole with real part {worst:.3g} 1/s >= 0: an FMU of an unstable "
                    "tire would diverge; refit it (ru.fit_tasselli / stages.fit_hub)"
                )


def check_sections(sections: ModalSections) -> None:
    """Refuse a model the FMU cannot run exactly: unstable poles, or blocks without a modal form."""
    if sections.blocks:
        raise ValueError(
            "the tire's fits have repeated poles (blocks without a modal form): the FMU steps modal sections only; "
            "refit the tasselli (ru.fit_tasselli) so that every pole is simple"
        )
    unstable = [s for s in sections.sections if s.pole.real >= 0.0]
    if unstable:
        worst = max(s.pole.real for s in unstable)
        sources = sorted({s.source for s in unstable})
        raise ValueError(
            f"the tire's fits have {len(unstable)} pole(s) with real part >= 0 (largest {worst:.3g} 1/s; inputs "
            f"{sources}, the last index being the hub): an FMU of an unstable tire would diverge; refit them"
        )


def tire_tables(
    fits: FitSet, hub: FitSet, static: Footprint, speed: float, sample_rate: float | None = None, lateral: bool = True
) -> TireTables:
    """The :class:`TireTables` of the moving-hub tire (Eq. 7) of ``fits`` and ``hub`` on the footprint ``static``.

    Parameters
    ----------
    fits, hub : FitSet
        The tasselli's fits (Eq. 1-4) and the hub's (Eq. 6), e.g. :func:`roadnoise_utils.repro.stages.fit_tasselli`
        and :func:`~roadnoise_utils.repro.stages.fit_hub`.
    static : Footprint
        The loaded tire the fits belong to (its tasselli's kernels).
    speed : float
        Rolling speed (m/s), in (0, 100].
    sample_rate : float, optional
        Steps per second; default :func:`.road.input.sample_rate_for` the speed (the band 0-250 Hz sampled
        as the simulation samples it).
    lateral : bool
        One road input per lateral strip (a 3-D road); ``False``: one input for a road uniform across the width.
    """
    if not isinstance(static, Footprint):
        raise TypeError(f"static must be a Footprint (the loaded tire), got {type(static).__name__}")
    for name, value in (("fits", fits), ("hub", hub)):
        if not isinstance(value, FitSet):
            raise TypeError(f"{name} must be a FitSet (ru.fit_tasselli / stages.fit_hub), got {type(value).__name__}")
    if len(fits) != static.tasselli.n:
        raise ValueError(f"fits has {len(fits)} tasselli; the footprint has {static.tasselli.n}")
    speed = guards.real("speed", speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s (km/h / 3.6)")
    lateral = guards.flag("lateral", lateral)
    fs = sample_rate_for(speed) if sample_rate is None else guards.real("sample_rate", sample_rate, 0.0, lo_open=True)
    check_sampling(speed, fs)
    dt = 1.0 / fs
    if speed * dt < ROAD_GRID:
        raise ValueError(
            f"speed * dt = {speed * dt:g} m: the FMU needs >= {ROAD_GRID:g} m of road per step; raise the speed or "
            f"lower sample_rate to <= {speed / ROAD_GRID:g} Hz"
        )
    check_stable(fits, hub)
    sections = modal_sections(assemble_moving_hub(fits, hub))
    check_sections(sections)
    rows, leading_edge, n_taps, strip_y = road_taps(static, speed, dt, lateral)
    coefficients = [foh_coefficients(s.pole, dt) for s in sections.sections]
    gains = np.array([s.gain for s in sections.sections])
    e = np.array([c[0] for c in coefficients], complex)
    real = np.array([s.pole.imag == 0.0 for s in sections.sections])
    return TireTables(
        dt=dt,
        speed=speed,
        leading_edge=leading_edge,
        strip_y=strip_y,
        direct=np.asarray(sections.direct, float),
        row_strip=np.array([r[0] for r in rows], np.int32),
        row_tassello=np.array([r[1] for r in rows], np.int32),
        taps=np.array([r[2] for r in rows], float).reshape(len(rows), n_taps),
        source=np.array([s.source for s in sections.sections], np.int32),
        e=np.where(real, e.real, e),
        b0=np.where(real, (gains * [c[1] for c in coefficients]).real, gains * [c[1] for c in coefficients]),
        b1=np.where(real, (gains * [c[2] for c in coefficients]).real, gains * [c[2] for c in coefficients]),
        factor=np.where(real, 1.0, 2.0),
    )


def write_tables(tables: TireTables, path: str | Path, guid: str) -> None:
    """Write ``tables`` to ``path`` in the layout of the module notes (what the C source reads), for the FMU
    whose model description has ``guid``."""
    encoded = guid.encode("ascii")
    if len(encoded) >= GUID_BYTES:
        raise ValueError(f"guid = {guid!r}: at most {GUID_BYTES - 1} ASCII characters")
    header = np.array(
        [VERSION, tables.n_strips, tables.n_tasselli, tables.taps.shape[1], tables.source.size, tables.taps.shape[0]],
        "<i4",
    )
    parts = [
        MAGIC,
        header.tobytes(),
        encoded.ljust(GUID_BYTES, b"\0"),
        np.array([tables.dt, tables.speed, tables.leading_edge], "<f8").tobytes(),
        np.asarray(tables.strip_y, "<f8").tobytes(),
        np.asarray(tables.direct, "<f8").tobytes(),
        np.asarray(tables.row_strip, "<i4").tobytes(),
        np.asarray(tables.row_tassello, "<i4").tobytes(),
        np.asarray(tables.taps, "<f8").tobytes(),
        np.asarray(tables.source, "<i4").tobytes(),
    ]
    for values in (tables.e.real, tables.e.imag, tables.b0.real, tables.b0.imag, tables.b1.real, tables.b1.imag):
        parts.append(np.asarray(values, "<f8").tobytes())
    parts += [np.asarray(tables.factor, "<f8").tobytes(), END]
    Path(path).write_bytes(b"".join(parts))


def read_tables(path: str | Path) -> tuple[TireTables, str]:
    """Read a file of :func:`write_tables` back: the tables and the GUID of the FMU they belong to."""
    data = Path(path).read_bytes()
    if data[:8] != MAGIC or data[-8:] != END:
        raise ValueError(f"{path}: not a roadnoise tire file, or truncated (magic or end marker missing)")
    version, n_strips, n_tasselli, n_taps, n_sections, n_rows = np.frombuffer(data, "<i4", 6, 8)
    if version != VERSION:
        raise ValueError(f"{path}: format version {version}, this reader knows {VERSION}")
    try:
        guid = data[32 : 32 + GUID_BYTES].rstrip(b"\0").decode("ascii")
    except UnicodeDecodeError:
        raise ValueError(f"{path}: its GUID field is not ASCII: not a roadnoise tire file, or damaged") from None
    offset = 32 + GUID_BYTES

    def take(dtype: str, count: int) -> np.ndarray:
        nonlocal offset
        out = np.frombuffer(data, dtype, count, offset)
        offset += out.nbytes
        return out

    dt, speed, leading_edge = take("<f8", 3)
    strip_y = take("<f8", n_strips)
    direct = take("<f8", n_tasselli + 1)
    row_strip, row_tassello = take("<i4", n_rows), take("<i4", n_rows)
    taps = take("<f8", n_rows * n_taps).reshape(n_rows, n_taps)
    source = take("<i4", n_sections)
    e_re, e_im, b0_re, b0_im, b1_re, b1_im, factor = (take("<f8", n_sections) for _ in range(7))
    if offset != len(data) - 8:
        raise ValueError(f"{path}: {len(data) - 8 - offset} bytes more than its header announces")
    tables = TireTables(
        dt=float(dt), speed=float(speed), leading_edge=float(leading_edge),
        strip_y=strip_y, direct=direct,
        row_strip=row_strip, row_tassello=row_tassello, taps=taps, source=source,
        e=e_re + 1j * e_im, b0=b0_re + 1j * b0_im, b1=b1_re + 1j * b1_im, factor=factor,
    )  # fmt: skip
    return tables, guid
