"""Frequency-dependent rubber moduli: the fractional-derivative Zener law.

The paper's FETvisco model gives each rubber compound "both elastic and loss moduli
dependent on frequency" (section "The FET Model"). We use the four-parameter fractional
Zener law (Bagley & Torvik 1983; Pritz 1996), which reproduces the broad, flat loss peak of
filled rubber with few parameters:

.. math:: \\frac{E^*(\\omega)}{E_0} = g(\\omega)
          = \\frac{1 + r\\,(i\\omega\\tau)^\\alpha}{1 + (i\\omega\\tau)^\\alpha}

with :math:`E_0` the static (relaxed) modulus, :math:`r = E_\\infty/E_0 > 1` the ratio of
the glassy to the relaxed modulus, :math:`\\tau` a relaxation time and
:math:`0 < \\alpha \\le 1` the fractional order. :math:`g(0) = 1`, so the stiffness
matrix of a compound assembled with :math:`E_0` is simply scaled by :math:`g(\\omega)`:
``K(omega) = K_elastic + sum_c g_c(omega) K_c``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike
from scipy.linalg.blas import daxpy


@dataclass(frozen=True)
class FractionalZener:
    """Normalised complex modulus of one rubber compound.

    Parameters
    ----------
    modulus_ratio : float
        :math:`r = E_\\infty / E_0` (-), > 1.
    relaxation_time : float
        :math:`\\tau` (s), > 0.
    order : float
        Fractional order :math:`\\alpha` (-), in (0, 1].
    """

    modulus_ratio: float
    relaxation_time: float
    order: float

    def __post_init__(self) -> None:
        if not self.modulus_ratio > 1.0:
            raise ValueError(f"modulus_ratio = {self.modulus_ratio} must be > 1 (E_inf / E_0)")
        if not self.relaxation_time > 0.0:
            raise ValueError(f"relaxation_time = {self.relaxation_time} s must be > 0")
        if not 0.0 < self.order <= 1.0:
            raise ValueError(f"order = {self.order} must be in (0, 1]")

    def ratio(self, omega: ArrayLike) -> np.ndarray:
        """Complex modulus ratio :math:`g(\\omega) = E^*(\\omega)/E_0` at angular frequency ``omega`` (rad/s)."""
        omega = np.asarray(omega, dtype=float)
        s = (1j * np.abs(omega) * self.relaxation_time) ** self.order
        g = (1.0 + self.modulus_ratio * s) / (1.0 + s)
        # negative frequencies: g(-w) = conj(g(w)) (real impulse response)
        return np.where(omega < 0, np.conj(g), g)

    def storage(self, omega: ArrayLike) -> np.ndarray:
        """Storage modulus ratio :math:`E'(\\omega)/E_0` (-)."""
        return np.real(self.ratio(omega))

    def loss_factor(self, omega: ArrayLike) -> np.ndarray:
        """Loss factor :math:`\\eta = E''/E'` (-)."""
        g = self.ratio(omega)
        return np.imag(g) / np.real(g)


def compound_table(laws: dict[str, FractionalZener], f_low: float = 1.0, f_high: float = 250.0) -> pd.DataFrame:
    """Storage rise from ``f_low`` to ``f_high`` (Hz) and loss factors of each compound."""
    w_low, w_high = 2 * np.pi * f_low, 2 * np.pi * f_high
    rows = {
        name: {
            f"storage rise {f_low:g}->{f_high:g} Hz": float(law.storage(w_high) / law.storage(w_low) - 1.0),
            f"loss factor at {f_low:g} Hz": float(law.loss_factor(w_low)),
            "loss factor at 80 Hz": float(law.loss_factor(2 * np.pi * 80.0)),
            f"loss factor at {f_high:g} Hz": float(law.loss_factor(w_high)),
        }
        for name, law in laws.items()
    }
    return pd.DataFrame(rows).T.rename_axis("compound")


@dataclass(frozen=True)
class PronySeries:
    """A generalised-Maxwell (Prony) approximation of a modulus law, for time stepping.

    .. math:: g(\\omega) \\approx 1 + \\sum_m a_m \\frac{i\\omega\\tau_m}{1 + i\\omega\\tau_m}

    :math:`g(0) = 1` exactly, so statics are untouched; each term is one auxiliary state
    :math:`v_m` per degree of freedom with :math:`\\tau_m \\dot v_m + v_m = u` and the force
    :math:`k\\,[u + \\sum_m a_m (u - v_m)]` (a spring in parallel with Maxwell branches).

    Attributes
    ----------
    weights : ndarray
        :math:`a_m \\ge 0` (-).
    times : ndarray
        :math:`\\tau_m` (s).
    max_error : float
        Largest relative error :math:`|g_{Prony} - g|/|g|` over the fitted band (-).
    band : tuple of float
        Fitted band (Hz).
    """

    weights: np.ndarray
    times: np.ndarray
    max_error: float
    band: tuple[float, float]

    def ratio(self, omega: ArrayLike) -> np.ndarray:
        """:math:`g(\\omega)` of the series at angular frequency ``omega`` (rad/s)."""
        s = 1j * np.asarray(omega, float)[..., None] * self.times
        return 1.0 + np.sum(self.weights * s / (1.0 + s), axis=-1)

    def step_constants(self, dt: float) -> tuple[np.ndarray, np.ndarray, float]:
        """Exact one-step update of the auxiliary states for ``u`` linear over a step ``dt`` (s).

        ``v_new = decay * v_old + gain * u_new + (1 - decay - gain) * u_old``; returns
        ``(decay, gain, stiffness_factor)`` with ``stiffness_factor = 1 + sum_m a_m (1 - gain_m)``,
        the instantaneous stiffness of the step relative to the static one.
        """
        x = dt / self.times
        decay = np.exp(-x)
        gain = 1.0 - (-np.expm1(-x)) / x
        return decay, gain, float(1.0 + np.sum(self.weights * (1.0 - gain)))


def prony_series(
    law: FractionalZener, f_min: float = 0.1, f_max: float = 2000.0, terms_per_decade: float = 2.0
) -> PronySeries:
    """Fit a :class:`PronySeries` to ``law`` over ``[f_min, f_max]`` Hz (non-negative least squares).

    Relaxation times are spaced ``terms_per_decade`` per decade, half a decade beyond each end
    of the band; the weights minimise the relative error of :math:`g` (real and imaginary
    parts) on a logarithmic grid. Non-negative weights keep every branch dissipative.
    """
    from scipy.optimize import nnls

    if not 0 < f_min < f_max:
        raise ValueError(f"band [{f_min}, {f_max}] Hz: valid range is 0 < f_min < f_max")
    decades = np.log10(f_max / f_min) + 1.0
    n_terms = int(np.ceil(decades * terms_per_decade)) + 1
    f_relax = np.logspace(np.log10(f_min) - 0.5, np.log10(f_max) + 0.5, n_terms)
    times = 1.0 / (2 * np.pi * f_relax)
    omega = 2 * np.pi * np.logspace(np.log10(f_min), np.log10(f_max), 40 * int(np.ceil(decades)))
    target = law.ratio(omega) - 1.0
    s = 1j * omega[:, None] * times[None, :]
    basis = s / (1.0 + s)
    scale = 1.0 / np.abs(law.ratio(omega))[:, None]
    matrix = np.vstack([(basis.real * scale), (basis.imag * scale)])
    rhs = np.concatenate([target.real * scale[:, 0], target.imag * scale[:, 0]])
    weights, _ = nnls(matrix, rhs)
    fitted = 1.0 + basis @ weights
    error = float(np.max(np.abs(fitted - law.ratio(omega)) / np.abs(law.ratio(omega))))
    return PronySeries(weights=weights, times=times, max_error=error, band=(f_min, f_max))


#: Columns of the states updated together by :meth:`PronyBranches.update_in_place` (4 vectors of
#: 256 kB: within a core's L2 cache).
CHUNK = 32768


class PronyBranches:
    """The Prony branches of one compound or layer in a time step ``dt`` (s): weights, times and step constants.

    Shared by the time-stepped runs of both tire models (:mod:`roadnoise_utils.tire.contact`,
    :mod:`roadnoise_utils.tire.cross_section.stepping`); zero-weight terms are dropped.
    """

    def __init__(self, series: PronySeries, dt: float):
        self.weights = series.weights[series.weights > 0]
        self.times = series.times[series.weights > 0]
        decay, gain, self.factor = PronySeries(self.weights, self.times, 0.0, series.band).step_constants(dt)
        self.decay, self.gain = decay, gain
        self.rest = 1.0 - decay - gain

    def history(self, states: np.ndarray, value: np.ndarray) -> np.ndarray:
        """:math:`\\sum_m a_m (E_m v_m + (1 - E_m - \\beta_m) u)`: the step's history term."""
        return (self.weights * self.decay) @ states + (self.weights @ self.rest) * value

    def update(self, states: np.ndarray, old: np.ndarray, new: np.ndarray) -> np.ndarray:
        """Auxiliary states at the end of the step."""
        return self.decay[:, None] * states + self.gain[:, None] * new[None, :] + self.rest[:, None] * old[None, :]

    def update_in_place(
        self, states: np.ndarray, old: np.ndarray, new: np.ndarray, history: np.ndarray | None = None
    ) -> None:
        """:meth:`update` written into ``states`` (C-contiguous float64): no temporaries of its size.

        With ``history`` (float64, the size of ``new``), also writes the next step's
        :meth:`history` ``(states_new, new)`` into it, in the same pass: each state row is
        updated and summed while it is in cache (one read and one write of the states per step
        instead of four and three).
        """
        if states.dtype != np.float64 or not states.flags.c_contiguous:
            raise ValueError("states must be a C-contiguous float64 array to be updated in place")
        if history is not None:
            history[:] = (self.weights @ self.rest) * new
        constants = list(zip(self.decay, self.gain, self.rest, self.weights * self.decay))
        for start in range(0, new.size, CHUNK):  # a chunk of every vector stays in cache across the rows
            part = slice(start, start + CHUNK)
            new_part, old_part = new[part], old[part]
            history_part = None if history is None else history[part]
            for row, (decay, gain, rest, weight) in zip(states[:, part], constants):
                row *= decay
                daxpy(new_part, row, a=gain)  # in place: each row's chunk is contiguous
                daxpy(old_part, row, a=rest)
                if history_part is not None:
                    daxpy(row, history_part, a=weight)

    def extra(self, states: np.ndarray, value: np.ndarray) -> np.ndarray:
        """:math:`\\sum_m a_m (u - v_m)`: the branches' share of the force, per unit stiffness."""
        return self.weights.sum() * value - self.weights @ states


class SharedPronyStates:
    """The Maxwell states of several compounds' branches, one state per distinct relaxation time.

    A branch's state obeys :math:`\\tau_m \\dot v_m + v_m = u` whatever compound it belongs to,
    so compounds driven by the same displacement ``u`` and fitted on the same grid of times
    (:func:`prony_series` spaces them per decade of a fixed band) have identical states for a
    shared :math:`\\tau_m`. Keeping one state per time instead of one per compound and time reads
    and writes a quarter of the states per step on four compounds; every compound's history
    is summed over its own branches in the same order as :meth:`PronyBranches.history`, so the
    numbers are those of separate states, bit for bit.

    Parameters
    ----------
    branches : dict of str to PronyBranches
        Each compound's branches, all for the same time step.
    size : int
        Length of the displacement vector ``u``.

    Raises
    ------
    ValueError
        Two compounds give one relaxation time different step constants (another time step).
    """

    def __init__(self, branches: dict[str, PronyBranches], size: int):
        self.names = list(branches)
        times = np.concatenate([b.times for b in branches.values()])
        self.times = np.unique(times)[::-1]  # descending, as every series lists them
        self.rows = {c: np.searchsorted(-self.times, -b.times) for c, b in branches.items()}
        self.decay, self.gain = np.empty(self.times.size), np.empty(self.times.size)
        for c, b in branches.items():
            if not np.array_equal(self.times[self.rows[c]], b.times) or np.any(np.diff(b.times) >= 0):
                raise ValueError(f"compound {c!r}: its relaxation times must be distinct and descending")
            self.decay[self.rows[c]], self.gain[self.rows[c]] = b.decay, b.gain
        for c, b in branches.items():
            if not (
                np.array_equal(self.decay[self.rows[c]], b.decay) and np.array_equal(self.gain[self.rows[c]], b.gain)
            ):
                raise ValueError(f"compound {c!r}: a relaxation time with other step constants (another time step)")
        self.rest = 1.0 - self.decay - self.gain
        self.branches = branches
        self.states = np.zeros((self.times.size, size))
        # per time: the compounds that have it and their weight a_m E_m in the history
        self._terms = [
            [
                (c, float(b.weights[k] * b.decay[k]))
                for c, b in branches.items()
                for k in np.nonzero(self.rows[c] == m)[0]
            ]
            for m in range(self.times.size)
        ]

    def start(self, value: np.ndarray) -> dict[str, np.ndarray]:
        """Every branch relaxed at ``value``; returns each compound's history term for the first step."""
        self.states[:] = np.asarray(value, float)[None, :]
        return {c: self.history(c, value) for c in self.names}

    def history(self, name: str, value: np.ndarray) -> np.ndarray:
        """Compound ``name``'s :meth:`PronyBranches.history` on the shared states."""
        return self.branches[name].history(self.states[self.rows[name]], value)

    def extra(self, name: str, value: np.ndarray) -> np.ndarray:
        """Compound ``name``'s :meth:`PronyBranches.extra` on the shared states."""
        return self.branches[name].extra(self.states[self.rows[name]], value)

    def update_in_place(self, old: np.ndarray, new: np.ndarray, histories: dict[str, np.ndarray]) -> None:
        """Every state updated from ``old`` to ``new`` and each compound's next history written into ``histories``.

        As :meth:`PronyBranches.update_in_place` with its history, for every compound in one pass.
        """
        for c in self.names:
            histories[c][:] = (self.branches[c].weights @ self.rest[self.rows[c]]) * new
        for start in range(0, new.size, CHUNK):
            part = slice(start, start + CHUNK)
            new_part, old_part = new[part], old[part]
            parts = {c: histories[c][part] for c in self.names}
            for row, decay, gain, rest, terms in zip(
                self.states[:, part], self.decay, self.gain, self.rest, self._terms
            ):
                row *= decay
                daxpy(new_part, row, a=gain)
                daxpy(old_part, row, a=rest)
                for c, weight in terms:
                    daxpy(row, parts[c], a=weight)
