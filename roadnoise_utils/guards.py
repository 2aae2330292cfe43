"""Guards every stage uses on its input: the package's warning, memory limits, number checks.

The rule (README, "Bad input, warnings and limits"): what cannot be computed, or would be physically impossible,
raises ``ValueError`` naming the argument, its value and the valid range, before any work is
done; what is valid but doubtful (a tire loaded to a third of its section height, a road
shorter than its longest wavelength, a decay component outside the fitted band) gives a
:class:`RoadnoiseWarning`, which users can filter like any warning category. Allocations that
grow with the input are estimated first and refused above :func:`memory_limit`
(:class:`ResourceLimitError`), never left to a ``MemoryError`` or a swap storm.
"""

from __future__ import annotations

import math
import numbers
import warnings

import numpy as np

#: Vertical loads a tire accepts (N): a small car tire to a light truck's (``[operating] vertical_load``).
LOAD_RANGE = (500.0, 15000.0)
#: Default limit of one estimated allocation (bytes): a quarter of a 16 GB machine.
DEFAULT_MEMORY_LIMIT = 4 * 1024**3


class RoadnoiseWarning(UserWarning):
    """Valid but doubtful input or result (like scipy's ``OptimizeWarning``)."""


class ResourceLimitError(ValueError):
    """An input would need more memory than :func:`memory_limit` allows."""


def memory_limit() -> float:
    """Largest estimated allocation a stage may make (bytes): ``ROADNOISE_MAX_BYTES`` or 4 GiB."""
    from .settings import positive_number  # settings warns through this module

    return positive_number("ROADNOISE_MAX_BYTES", DEFAULT_MEMORY_LIMIT)


def check_memory(n_bytes: float, what: str, parameter: str) -> None:
    """Refuse an allocation of ``n_bytes`` (estimated) for ``what``, caused by ``parameter``, above the limit."""
    limit = memory_limit()
    if n_bytes > limit:
        raise ResourceLimitError(
            f"{parameter}: {what} would need about {n_bytes / 1024**3:.1f} GiB, above the limit of "
            f"{limit / 1024**3:.1f} GiB (set ROADNOISE_MAX_BYTES to raise it)"
        )


def warn(message: str, stacklevel: int = 3) -> None:
    """Issue a :class:`RoadnoiseWarning` pointing at the caller's caller."""
    warnings.warn(message, RoadnoiseWarning, stacklevel=stacklevel)


def _range_text(lo: float, hi: float, lo_open: bool, hi_open: bool, unit: str) -> str:
    left = "(" if lo_open else "["
    right = ")" if hi_open or math.isinf(hi) else "]"
    return f"{left}{lo:g}, {hi:g}{right}" + (f" {unit}" if unit else "")


def real(
    name: str,
    value: object,
    lo: float = -math.inf,
    hi: float = math.inf,
    *,
    lo_open: bool = False,
    hi_open: bool = False,
    unit: str = "",
) -> float:
    """``value`` as a float if it is a finite real number in the range, else ``ValueError`` naming ``name``."""
    valid = _range_text(lo, hi, lo_open, hi_open, unit)
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {value!r} must be a number; valid range is {valid}")
    x = float(value)
    inside = (lo < x if lo_open else lo <= x) and (x < hi if hi_open else x <= hi)
    if not (math.isfinite(x) and inside):
        raise ValueError(f"{name} = {value!r}: valid range is {valid}")
    return x


def integer(name: str, value: object, lo: int = 0, hi: float = math.inf) -> int:
    """``value`` as an int if it is a whole number (int, numpy integer, or integral float) in ``[lo, hi]``."""
    valid = f"integers in [{lo}, {hi:g}]" if math.isfinite(hi) else f"integers >= {lo}"
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {value!r} must be an integer; valid range is {valid}")
    if not (math.isfinite(float(value)) and float(value).is_integer() and lo <= value <= hi):
        raise ValueError(f"{name} = {value!r}: valid range is {valid}")
    return int(value)


def flag(name: str, value: object) -> bool:
    """``value`` if it is a boolean (Python or numpy), else ``ValueError`` naming ``name``: a string such as
    ``"no"`` or a number is not taken for a flag (``bool("no")`` is True)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ValueError(f"{name} = {value!r} must be True or False")


def interval(name: str, value: object, unit: str = "m") -> tuple[float, float]:
    """A pair ``(start, end)`` of finite numbers, the end beyond the start (a travel range, say)."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise ValueError(f"{name} = {value!r} must be a pair (start, end) in {unit}")
    start = real(f"{name}[0]", value[0], unit=unit)
    return start, real(f"{name}[1]", value[1], start, lo_open=True, unit=f"{unit} (after the start)")


def seed(value: object) -> int:
    """A random-road seed: a non-negative integer (the same seed gives the same road)."""
    return integer("seed", value, 0)


#: Elements checked at a time by :func:`all_finite` and :func:`uniform_step`: their temporaries stay ~2 MB.
CHECK_CHUNK = 1 << 18


def all_finite(values: np.ndarray, chunk: int = CHECK_CHUNK) -> bool:
    """Whether every element of a real array is finite, checked ``chunk`` elements at a time.

    A chunk's minimum and maximum are NaN or infinite when any of its elements is, so no boolean
    array as large as ``values`` is made (a 65 x 2e6 input: 130 MB for ``np.isfinite``).
    """
    values = np.asarray(values)
    if np.iscomplexobj(values):
        return all_finite(values.real, chunk) and all_finite(values.imag, chunk)
    if values.size == 0:
        return True
    if not values.flags.c_contiguous and values.ndim > 1:
        return all(all_finite(row, chunk) for row in values)
    flat = values.reshape(-1)
    for start in range(0, flat.size, chunk):
        part = flat[start : start + chunk]
        if not (math.isfinite(float(part.min())) and math.isfinite(float(part.max()))):
            return False
    return True


def uniform_step(t: np.ndarray, rtol: float = 1e-9, chunk: int = CHECK_CHUNK) -> float:
    """The step of a uniform, increasing grid ``t`` (at least two points), checked ``chunk`` steps at a time;
    raises ValueError naming ``t`` otherwise."""
    t = np.asarray(t, float)
    dt = float(t[1] - t[0]) if t.size >= 2 else 0.0
    if not dt > 0:
        raise ValueError("time step must be uniform and positive")
    for start in range(0, t.size - 1, chunk):
        steps = np.diff(t[start : start + chunk + 1])
        if np.max(np.abs(steps - dt)) > rtol * abs(dt):
            raise ValueError("time step must be uniform and positive")
    return dt
