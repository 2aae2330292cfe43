"""Rational fits of the local FRFs: relaxed vector fitting (paper Eq. 1, Fig. 6).

The paper fits each tassello's FRF with "a transfer function with eight poles and eight zeros"
(Eq. 1, :math:`G_i(s) = h_i(s)/d_i(s)`) using MATLAB's Frequency Domain Identification
Toolbox. Polynomial coefficients of degree 8 are badly conditioned, so we fit the same model in
pole-residue form,

.. math:: G(s) = \\sum_{k=1}^{n} \\frac{r_k}{s - p_k} + d,

(biproper: ``n`` poles and ``n`` zeros), by relaxed vector fitting:

* Gustavsen & Semlyen, "Rational approximation of frequency domain responses by vector
  fitting", IEEE Trans. Power Delivery 14(3), 1999 — pole relocation by a linear problem;
* Gustavsen, "Improving the pole relocating properties of vector fitting", IEEE Trans. Power
  Delivery 21(3), 2006 — the relaxed non-triviality constraint used here;
* Deschrijver, Mrozowski, Dhaene & De Zutter, "Macromodeling of multiport systems using a fast
  implementation of the vector fitting method", IEEE Microwave Wireless Compon. Lett. 18(6),
  2008 — one pole set for many responses (``common_poles=True``, :mod:`.common_poles`).

Options: model order (``n_poles``, default 8, or ``"auto"``: the lowest even order reaching a
target error), weighting, number of iterations, one pole set per tassello or one for all, the
starting poles (lightly damped pairs spread evenly over the band by default, or also spread evenly
on a log scale: ``starting_poles``) and a proportional term (for responses other than the tire's). Each
pole relocation is followed by the residues' least-squares solve, and the iteration with the
smallest error is kept, not the last (relocation is not monotone: poles the data do not pin
down can wander and worsen the fit). Poles are kept stable (unstable ones are reflected), the
coefficients real (complex poles come in conjugate pairs, handled with the real basis of
Gustavsen 1999), poles the band cannot pin down held where it supports them
(:func:`.vf_kernels.confine`: above the band damped at least 0.5 %, none slower than the grid
resolves), and the DC value is imposed exactly when the data contain 0 Hz. Frequencies
are scaled by the band's top frequency so the linear problems stay well conditioned.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import pandas as pd
from threadpoolctl import threadpool_limits

from .. import guards
from ..analysis import relative_rms_error
from . import common_poles as common
from .relocation import Relocations, lowest_frequency, relocate_rows
from .vf_kernels import (
    DEFAULT_STARTS,
    STARTS,
    PoleResidueModel,
    as_arrays,
    check_data,
    fit_for_poles,
    initial_poles,
)
from .vf_kernels import weights as resolve_weights


@dataclass(frozen=True)
class RationalFit:
    """One fitted transfer function :math:`G(s) = \\sum_k r_k/(s - p_k) + d` (s in rad/s).

    Attributes
    ----------
    poles : ndarray, complex
        Poles :math:`p_k` (rad/s); complex ones come in conjugate pairs, positive imaginary
        part first.
    residues : ndarray, complex
        Residues :math:`r_k` (unit of the data x rad/s), conjugate where the poles are.
    direct : float
        Direct term :math:`d` (unit of the data).
    rms_error : float
        Relative RMS error over the fitted band, :math:`\\|G - H\\|/\\|H\\|` (-).
    max_error : float
        Largest :math:`|G - H|` over the band relative to :math:`\\max|H|` (-).
    dc_error : float
        :math:`|G(0) - H(0)|/|H(0)|` when 0 Hz was fitted, else NaN (-).
    iterations : int
        Pole relocations run (at most the ``iterations`` asked for; fewer when the poles
        stopped moving by ``tolerance``).
    best_iteration : int
        The relocation whose poles are kept (0: the starting poles): the one with the smallest
        error in :attr:`errors`.
    errors : tuple of float
        The selection error after 0, 1, ..., :attr:`iterations` relocations: the weighted
        relative RMS error :math:`\\|w (G - H)\\|/\\|w H\\|` of the residues' least-squares fit
        on those poles (with the default uniform weight, :attr:`rms_error`). For a common-pole
        fit, this tassello's errors; the kept iteration is the one with the smallest worst
        tassello's error. Iterations and errors are those of the kept start.
    proportional : float
        Coefficient ``e`` of a proportional term :math:`e s` (unit of the data x s/rad); 0
        unless fitted with ``proportional=True`` (the tire's FRFs have none: paper Eq. 1 is
        biproper).
    start : str
        The starting pole set whose relocations gave the kept poles (``"linear"`` or ``"log"``,
        :data:`.vf_kernels.STARTS`).
    """

    poles: np.ndarray
    residues: np.ndarray
    direct: float
    rms_error: float
    max_error: float
    dc_error: float
    iterations: int
    best_iteration: int = 0
    errors: tuple[float, ...] = ()
    proportional: float = 0.0
    start: str = "linear"

    @property
    def order(self) -> int:
        return self.poles.size

    def __call__(self, freqs: np.ndarray) -> np.ndarray:
        """Frequency response at ``freqs`` (Hz)."""
        s = 2j * np.pi * np.asarray(freqs, float)
        partial_fractions = (self.residues[None, :] / (s[:, None] - self.poles[None, :])).sum(axis=1)
        return partial_fractions + self.direct + self.proportional * s

    @property
    def dc_gain(self) -> float:
        """:math:`G(0)`."""
        return float(np.real(np.sum(-self.residues / self.poles) + self.direct))


@dataclass(frozen=True)
class FitSet:
    """Rational fits of many FRFs (one per tassello) and how they were made.

    Attributes
    ----------
    fits : list of RationalFit
        One per row of the fitted data.
    freqs : ndarray
        Fitted frequencies (Hz).
    band : tuple of float
        First and last fitted frequency (Hz).
    seconds : float
        Wall time of the fits (s); with ``n_poles="auto"``, of the whole order search.
    common_poles : bool
        Every fit has the same poles (``fit_tasselli(..., common_poles=True)``): the state
        space shares one state matrix (:func:`.realisation.assemble_fixed_hub`).
    """

    fits: list[RationalFit]
    freqs: np.ndarray
    band: tuple[float, float]
    seconds: float
    common_poles: bool = False

    @property
    def n_poles(self) -> int:
        """Model order (the same for every fit)."""
        return self.fits[0].order

    @property
    def n_states(self) -> int:
        """States of the fixed-hub state space (Eq. 3): one per pole, shared when the poles are common."""
        return self.n_poles if self.common_poles else sum(f.order for f in self.fits)

    def __len__(self) -> int:
        return len(self.fits)

    def __getitem__(self, i: int) -> RationalFit:
        return self.fits[i]

    def responses(self, freqs: np.ndarray) -> np.ndarray:
        """All fitted FRFs at ``freqs`` (Hz), (n_fits, n_freq)."""
        return np.array([f(freqs) for f in self.fits])

    @property
    def rms_errors(self) -> np.ndarray:
        return np.array([f.rms_error for f in self.fits])

    def table(self) -> pd.DataFrame:
        """One row per fit: order, errors, iterations run and kept, slowest pole's damping."""
        return pd.DataFrame(
            {
                "poles": [f.order for f in self.fits],
                "rms error": self.rms_errors,
                "max error": [f.max_error for f in self.fits],
                "DC error": [f.dc_error for f in self.fits],
                "iterations": [f.iterations for f in self.fits],
                "best iteration": [f.best_iteration for f in self.fits],
                "max Re(p) (1/s)": [float(np.max(f.poles.real)) for f in self.fits],
            },
            index=pd.Index(np.arange(1, len(self.fits) + 1), name="tassello"),
        )


#: BLAS threads inside the fits: their batched solves are small, and on 2 cores a second BLAS
#: thread only contends with the first (benchmarks/bench_fitting.py measures both).
FIT_THREADS = 1
#: Largest order tried by ``n_poles="auto"`` unless told (``max_poles``).
AUTO_MAX_POLES = 24
#: Target of ``n_poles="auto"`` unless told (``target_error``): every fit within 1 % relative RMS error.
AUTO_TARGET_ERROR = 0.01


def _check_options(n_poles: int, iterations: int, tolerance: float) -> int:
    """Validate the fitting options before any work; returns ``n_poles`` as an int."""
    guards.integer("iterations", iterations, 1, 1000)
    guards.real("tolerance", tolerance, 0.0, lo_open=True)
    return guards.integer("n_poles", n_poles, 1, 200)


def _make_fit(
    freqs: np.ndarray, h: np.ndarray, scale: float, model: PoleResidueModel, run: Relocations, i: int
) -> RationalFit:
    """A :class:`RationalFit` of row ``i`` from its model in scaled ``s`` and the relocations that found its poles."""
    fitted = model.fitted
    dc_error = abs(fitted[0] - h[0]) / abs(h[0]) if freqs[0] == 0.0 and h[0] != 0 else float("nan")
    return RationalFit(
        poles=model.poles * scale,
        residues=model.residues * scale,
        direct=model.direct,
        rms_error=relative_rms_error(fitted, h),
        max_error=float(np.max(np.abs(fitted - h)) / np.max(np.abs(h))),
        dc_error=float(dc_error),
        iterations=int(run.used[i]),
        best_iteration=int(run.best_iteration[i]),
        errors=tuple(float(e) for e in run.errors[i]),
        proportional=model.proportional / scale,
        start=run.start,
    )


def _fit_many(
    freqs: np.ndarray,
    frf: np.ndarray,
    n_poles: int,
    weight: np.ndarray | str,
    iterations: int,
    tolerance: float,
    enforce_dc: bool,
    starts: tuple[str, ...] = DEFAULT_STARTS,
    proportional: bool = False,
) -> list[RationalFit]:
    """Relaxed vector fitting of each row of ``frf`` (own poles per row) from each starting pole set.

    Each row keeps the poles of its smallest error over every start and relocation (ties: the
    earlier start, then the earlier iteration): relocation finds a local optimum, and which
    start reaches the better one differs from row to row.
    """
    n_poles = _check_options(n_poles, iterations, tolerance)
    check_data(freqs, frf, n_poles)
    scale = 2 * np.pi * freqs[-1]
    s = 2j * np.pi * freqs / scale
    w = resolve_weights(freqs, frf, weight)
    dc = frf[:, 0] if (enforce_dc and freqs[0] == 0.0) else None
    runs = [relocate_rows(s, frf, w, dc, n_poles, start, iterations, tolerance, proportional) for start in starts]
    fits = []
    for i in range(frf.shape[0]):
        run = min(runs, key=lambda r: r.best_error(i))
        model = fit_for_poles(s, frf[i], w[i], run.best_poles[i], None if dc is None else dc[i], proportional)
        run.errors[i][run.best_iteration[i]] = model.error  # the kept poles' error from the final (SVD) solve
        fits.append(_make_fit(freqs, frf[i], scale, model, run, i))
    return fits


def _fit_common(
    freqs: np.ndarray,
    frf: np.ndarray,
    n_poles: int,
    weight: np.ndarray | str,
    iterations: int,
    tolerance: float,
    enforce_dc: bool,
    starts: tuple[str, ...] = DEFAULT_STARTS,
    proportional: bool = False,
) -> list[RationalFit]:
    """One pole set for every row of ``frf`` (:func:`.common_poles.fit_common`), per-row residues.

    From each starting pole set; the one whose worst row's error is the smallest is kept. No
    proportional term (``fit_tasselli`` refuses ``proportional`` with ``common_poles``).
    """
    n_poles = _check_options(n_poles, iterations, tolerance)
    check_data(freqs, frf, n_poles)
    scale = 2 * np.pi * freqs[-1]
    s = 2j * np.pi * freqs / scale
    w = resolve_weights(freqs, frf, weight)
    dc = frf[:, 0] if (enforce_dc and freqs[0] == 0.0) else None
    found = [
        (
            start,
            common.fit_common(s, frf, w, initial_poles(n_poles, start, lowest_frequency(s)), iterations, tolerance, dc),
        )
        for start in starts
    ]
    start, best = min(found, key=lambda item: max(model.error for model in item[1].models))
    m = frf.shape[0]
    run = Relocations(
        start, np.empty((m, 0)), np.full(m, best.best_iteration), best.errors, np.full(m, best.iterations)
    )
    return [_make_fit(freqs, frf[i], scale, best.models[i], run, i) for i in range(m)]


def vector_fit(
    freqs: np.ndarray,
    frf: np.ndarray,
    n_poles: int = 8,
    weight: np.ndarray | str = "uniform",
    iterations: int = 8,
    tolerance: float = 1e-3,
    enforce_dc: bool = True,
    starting_poles: tuple[str, ...] = DEFAULT_STARTS,
    proportional: bool = False,
) -> RationalFit:
    """Fit one FRF with ``n_poles`` stable poles and a direct term (biproper, paper Eq. 1).

    Parameters
    ----------
    freqs : ndarray
        Frequencies (Hz), strictly increasing, >= 0.
    frf : ndarray, complex
        Data to fit.
    n_poles : int
        Model order: poles = zeros (default 8, the paper's).
    weight : ndarray or {"uniform", "relative"}
        Per-frequency weights; ``"relative"`` uses ``1/|frf|`` (equal relative accuracy
        everywhere), ``"uniform"`` (default) minimises the absolute error, i.e. the relative
        RMS error reported.
    iterations : int
        Maximum pole relocations (default 8; vector fitting usually converges in 3-5). The
        relocation with the smallest weighted relative RMS error is kept
        (:attr:`RationalFit.best_iteration`), not the last.
    tolerance : float
        Stop a fit when its poles move less than this relative to the largest pole (default
        1e-3: well converged poles keep drifting far below any visible change of the fit).
    enforce_dc : bool
        Impose ``G(0) = frf(0)`` exactly when ``freqs[0] == 0`` (the static influence).
    starting_poles : tuple of {"linear", "log"}
        The starting pole sets (:data:`.vf_kernels.STARTS`; default ``("linear",)``): the
        relocations run from each, and the fit keeps the poles with the smallest error over all
        of them (:attr:`RationalFit.start`). Relocation reaches a local optimum that depends on
        the start: lightly damped pairs evenly spread over the band suit evenly spread modes, a
        log spacing suits low-frequency features. ``("linear", "log")`` brings the paper tires'
        tasselli within 1.2x of the better of scikit-rf's and pyvectorfit's errors at 8 and 10-20
        poles (the linear start alone: up to 1.5-6.7x), at twice the time; but the log start's
        relocations amplify round-off in the data: a 1e-15 change of the data moved the fits from
        both starts by up to 1.3e-6 of the response at 14-17 poles and 4.6e-4 at 20 (165/65 R14
        tires), against at most 6e-9 from the linear start at 8-24 poles. The pipeline keeps the default.
    proportional : bool
        Add a term :math:`e s` to the model (improper: a response that keeps rising at the top
        of the band, e.g. an admittance). The tire's footprint FRFs have none (paper Eq. 1 is
        biproper) and :func:`.realisation.realize` refuses such a fit.
    """
    freqs, frf = as_arrays(freqs, frf)
    guards.flag("enforce_dc", enforce_dc)
    guards.flag("proportional", proportional)
    starts = _check_starts(starting_poles)
    if frf.ndim != 1:
        raise ValueError(f"frf must be 1-D (one FRF; fit_tasselli fits one per row), got shape {frf.shape}")
    return _fit_many(freqs, frf[None, :], n_poles, weight, iterations, tolerance, enforce_dc, starts, proportional)[0]


def _check_starts(starting_poles) -> tuple[str, ...]:
    """``starting_poles`` as a tuple of known start names, or a ValueError naming the valid ones."""
    if isinstance(starting_poles, str):
        starting_poles = (starting_poles,)
    try:
        starts = tuple(starting_poles)
    except TypeError:
        raise ValueError(f"starting_poles = {starting_poles!r}: give some of {STARTS}") from None
    if not starts or any(not isinstance(x, str) or x not in STARTS for x in starts) or len(set(starts)) != len(starts):
        raise ValueError(f"starting_poles = {starting_poles!r}: give one or more of {STARTS}, each once")
    return starts


def fit_tasselli(
    freqs: np.ndarray,
    H: np.ndarray,
    n_poles: int | str = 8,
    f_max: float | None = None,
    weight: np.ndarray | str = "uniform",
    iterations: int = 8,
    tolerance: float = 1e-3,
    enforce_dc: bool = True,
    common_poles: bool = False,
    target_error: float | None = None,
    max_poles: int = AUTO_MAX_POLES,
    starting_poles: tuple[str, ...] = DEFAULT_STARTS,
    proportional: bool = False,
) -> FitSet:
    """One rational fit per row of ``H`` [tassello, frequency] over ``0-f_max`` Hz (paper Eq. 1).

    Each row gets its own poles (the pole relocations of all rows run batched), or, with
    ``common_poles=True``, all rows share one pole set and each has its own residues and direct
    term: a state space of ``n_poles`` states in all instead of ``n_poles`` per tassello.

    Parameters
    ----------
    freqs : ndarray
        Frequencies (Hz) of the columns of ``H``.
    H : ndarray (n_fits, n_freq) or (n_freq,), complex
        The FRFs (N/m).
    n_poles : int or "auto"
        Poles (= zeros) per fit; the paper's 8 by default. ``"auto"``: the lowest even order
        from 2 to ``max_poles`` at which the largest relative RMS error over the rows
        (:attr:`FitSet.rms_errors`) is at most ``target_error``; when none gets there, the
        order with the smallest largest error, with a
        :class:`~roadnoise_utils.guards.RoadnoiseWarning` naming it.
    f_max : float or None
        Top of the fitted band (Hz). ``None`` (default) fits all the data's frequencies; the
        paper's band is 0-250 Hz (``f_max=250.0``).
    weight, iterations, tolerance, enforce_dc, starting_poles, proportional
        As in :func:`vector_fit` (``proportional`` only with ``common_poles=False``).
    common_poles : bool
        One pole set for all rows (fast relaxed vector fitting, :mod:`.common_poles`); the
        kept iteration is the one with the smallest worst row's error.
    target_error : float, optional
        Target of ``n_poles="auto"`` (default :data:`AUTO_TARGET_ERROR`, 1 %); only with it.
    max_poles : int
        Largest order ``n_poles="auto"`` tries (default :data:`AUTO_MAX_POLES`).
    """
    freqs, H = as_arrays(freqs, H, "H")
    guards.flag("enforce_dc", enforce_dc)
    guards.flag("common_poles", common_poles)
    guards.flag("proportional", proportional)
    if proportional and common_poles:
        raise ValueError("proportional=True is for fits with their own poles per FRF: give common_poles=False")
    starts = _check_starts(starting_poles)
    H = np.atleast_2d(H)
    if H.ndim != 2:
        raise ValueError(f"H must be 1-D or 2-D [fit, frequency], got shape {H.shape}")
    if freqs.ndim != 1 or H.shape[-1] != freqs.size:
        raise ValueError(f"H must have the frequencies (freqs, {freqs.size}) on its last axis, got shape {H.shape}")
    if not np.all(np.isfinite(freqs)):
        raise ValueError("freqs must be finite (a NaN frequency is not dropped silently)")
    orders, target = _orders(n_poles, target_error, max_poles)
    _check_options(orders[0], iterations, tolerance)
    if f_max is not None:
        guards.real("f_max", f_max, 0.0, lo_open=True, unit="Hz")
        if f_max > freqs.max() * (1 + 1e-9):
            guards.warn(
                f"f_max = {f_max:g} Hz is beyond the FRFs' last frequency {freqs.max():g} Hz: the fit covers "
                f"0-{freqs.max():g} Hz only"
            )
    band = freqs <= f_max if f_max is not None else np.ones(freqs.size, bool)
    if not band.any():
        raise ValueError(f"no frequency below f_max = {f_max} Hz")
    if not isinstance(weight, str) and np.shape(weight)[-1:] != (freqs.size,):
        raise ValueError(f"weight of shape {np.shape(weight)}: give one weight per frequency ({freqs.size})")
    if not isinstance(common_poles, (bool, np.bool_)):
        raise ValueError(f"common_poles = {common_poles!r}: give True or False")
    w = weight if isinstance(weight, str) else np.asarray(weight, float)[..., band]
    run = _fit_common if common_poles else _fit_many
    start = time.perf_counter()
    tried: list[list[RationalFit]] = []
    with threadpool_limits(FIT_THREADS, user_api="blas"):  # small batched solves: threads only fight
        for n in orders:
            if target is not None and 2 * int(band.sum()) < 2 * (n + 1) + 1:
                break  # too few frequencies for this order (and the higher ones)
            tried.append(run(freqs[band], H[:, band], n, w, iterations, tolerance, enforce_dc, starts, proportional))
            if target is not None and max(f.rms_error for f in tried[-1]) <= target:
                break
    fits = (
        tried[-1]
        if tried
        else run(freqs[band], H[:, band], orders[0], w, iterations, tolerance, enforce_dc, starts, proportional)
    )
    if target is not None and max(f.rms_error for f in fits) > target:
        fits = min(tried, key=lambda t: max(f.rms_error for f in t))
        worst = max(f.rms_error for f in fits)
        guards.warn(
            f"n_poles='auto': no even order up to {tried[-1][0].order} reaches target_error = {target:.3g} "
            f"(largest relative RMS error); using {fits[0].order} poles, the smallest largest error ({worst:.3g}). "
            f"Raise max_poles (now {max_poles}) or the target",
            stacklevel=2,
        )
    return FitSet(
        fits=fits,
        freqs=freqs[band],
        band=(float(freqs[band][0]), float(freqs[band][-1])),
        seconds=time.perf_counter() - start,
        common_poles=bool(common_poles),
    )


def _orders(n_poles: int | str, target_error: float | None, max_poles: int) -> tuple[list[int], float | None]:
    """The orders to fit and the target error (None: one given order)."""
    if isinstance(n_poles, str):
        if n_poles != "auto":
            raise ValueError(f"n_poles = {n_poles!r}: give an integer 1-200 or 'auto'")
        target = (
            AUTO_TARGET_ERROR if target_error is None else guards.real("target_error", target_error, 0.0, lo_open=True)
        )
        top = guards.integer("max_poles", max_poles, 2, 200)
        return list(range(2, top + 1, 2)), target
    if target_error is not None:
        raise ValueError(f"target_error = {target_error!r} is used only with n_poles='auto' (n_poles = {n_poles!r})")
    return [_check_options(n_poles, 1, 1.0)], None
