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
  Delivery 21(3), 2006 — the relaxed non-triviality constraint used here.

Options: model order (``n_poles``, default 8), weighting, number of iterations. Poles are
kept stable (unstable ones are reflected), the coefficients real (complex poles come in
conjugate pairs, handled with the real basis of Gustavsen 1999), and the DC value is imposed
exactly when the data contain 0 Hz. Frequencies are scaled by the band's top frequency so the
linear problems stay well conditioned.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import pandas as pd
from threadpoolctl import threadpool_limits

from .. import guards
from ..analysis import relative_rms_error


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
        Pole-relocation iterations used.
    """

    poles: np.ndarray
    residues: np.ndarray
    direct: float
    rms_error: float
    max_error: float
    dc_error: float
    iterations: int

    @property
    def order(self) -> int:
        return self.poles.size

    def __call__(self, freqs: np.ndarray) -> np.ndarray:
        """Frequency response at ``freqs`` (Hz)."""
        s = 2j * np.pi * np.asarray(freqs, float)
        return (self.residues[None, :] / (s[:, None] - self.poles[None, :])).sum(axis=1) + self.direct

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
        Wall time of the fits (s).
    """

    fits: list[RationalFit]
    freqs: np.ndarray
    band: tuple[float, float]
    seconds: float

    @property
    def n_poles(self) -> int:
        """Model order (the same for every fit)."""
        return self.fits[0].order

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
        """One row per fit: order, errors, iterations, slowest pole's damping."""
        return pd.DataFrame(
            {
                "poles": [f.order for f in self.fits],
                "rms error": self.rms_errors,
                "max error": [f.max_error for f in self.fits],
                "DC error": [f.dc_error for f in self.fits],
                "iterations": [f.iterations for f in self.fits],
                "max Re(p) (1/s)": [float(np.max(f.poles.real)) for f in self.fits],
            },
            index=pd.Index(np.arange(1, len(self.fits) + 1), name="tassello"),
        )


#: BLAS threads inside the fits: their batched solves are small, and on 2 cores a second BLAS
#: thread only contends with the first (benchmarks/bench_fitting.py measures both).
FIT_THREADS = 1


def _check_options(n_poles: int, iterations: int, tolerance: float) -> int:
    """Validate the fitting options before any work; returns ``n_poles`` as an int."""
    guards.integer("iterations", iterations, 1, 1000)
    guards.real("tolerance", tolerance, 0.0, lo_open=True)
    return guards.integer("n_poles", n_poles, 1, 200)


def _check_data(freqs: np.ndarray, frf: np.ndarray, n_poles: int) -> None:
    if freqs.ndim != 1 or frf.shape[-1] != freqs.size:
        raise ValueError(f"frf must have the frequencies on its last axis ({freqs.size}), got shape {frf.shape}")
    if not np.all(np.isfinite(freqs)) or np.any(freqs < 0):
        raise ValueError("freqs must be finite and >= 0 Hz")
    if not np.all(np.diff(freqs) > 0):
        raise ValueError("freqs must be strictly increasing")
    if not np.all(np.isfinite(frf)):
        raise ValueError("frf contains NaN or inf")
    zero = np.nonzero(np.max(np.abs(frf), axis=-1) == 0)[0]
    if zero.size:
        raise ValueError(f"frf row(s) {zero.tolist()} are zero at every frequency: there is nothing to fit")
    unknowns = n_poles + 1
    if 2 * freqs.size < 2 * unknowns + 1:
        raise ValueError(
            f"{freqs.size} frequencies give {2 * freqs.size} real equations, fewer than the "
            f"{2 * unknowns + 1} needed for {n_poles} poles; give at least {unknowns + 1} frequencies"
        )


def _initial_poles(n_poles: int) -> np.ndarray:
    """Lightly damped complex pairs spread over the (scaled) band, one real pole if n is odd."""
    n_pairs = n_poles // 2
    imag = np.linspace(1.0 / (n_pairs + 1), 1.0, n_pairs) if n_pairs else np.array([])
    pairs = -0.01 * imag + 1j * imag
    poles = np.concatenate([np.ravel(np.column_stack([pairs, pairs.conj()])), [-0.5] * (n_poles % 2)])
    return poles.astype(complex)


def _split(poles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real poles and the upper members of the complex pairs."""
    tol = 1e-10 * max(1.0, np.max(np.abs(poles)))
    real = poles[np.abs(poles.imag) <= tol].real
    upper = poles[poles.imag > tol]
    return real, upper


def _basis(s: np.ndarray, real: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Real-coefficient partial-fraction basis (Gustavsen & Semlyen 1999).

    ``real`` (..., n_r) and ``upper`` (..., n_c) may carry leading batch dimensions; the result
    is (..., n_s, n_r + 2 n_c) with the columns: real poles, then (phi1, phi2) of each pair.
    """
    sr = s[:, None]
    cols = [1.0 / (sr - real[..., None, :])]
    if upper.shape[-1]:
        a = 1.0 / (sr - upper[..., None, :])
        b = 1.0 / (sr - np.conj(upper)[..., None, :])
        pair = np.stack([a + b, 1j * (a - b)], axis=-1)  # (..., n_s, n_c, 2)
        cols.append(pair.reshape(*pair.shape[:-2], -1))
    return np.concatenate(cols, axis=-1)


def _state_matrices(real: np.ndarray, upper: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real block-diagonal (A, b), batched, whose c (sI - A)^-1 b reproduces :func:`_basis`."""
    batch = real.shape[:-1]
    n_r, n_c = real.shape[-1], upper.shape[-1]
    n = n_r + 2 * n_c
    a = np.zeros((*batch, n, n))
    b = np.zeros((*batch, n))
    idx = np.arange(n_r)
    a[..., idx, idx] = real
    b[..., :n_r] = 1.0
    k = n_r + 2 * np.arange(n_c)
    a[..., k, k] = upper.real
    a[..., k + 1, k + 1] = upper.real
    a[..., k, k + 1] = upper.imag
    a[..., k + 1, k] = -upper.imag
    b[..., k] = 2.0
    return a, b


def _stack(m: np.ndarray) -> np.ndarray:
    """Real and imaginary parts stacked along the row axis (-2)."""
    return np.concatenate([m.real, m.imag], axis=-2)


def _relocate(s: np.ndarray, h: np.ndarray, w: np.ndarray, real: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """One relaxed pole relocation (Gustavsen 2006) for a batch of fits with the same pole structure.

    ``h``, ``w``: (G, n_s); ``real`` (G, n_r), ``upper`` (G, n_c). Returns the zeros of each
    fitted sigma(s), stabilised: (G, n) complex.
    """
    g, n_s = h.shape
    n_r, n_c = real.shape[-1], upper.shape[-1]
    n = n_r + 2 * n_c
    # the design matrix [phi w, w, -phi h w, -h w], written in place (this step is memory-bound)
    z = np.empty((g, n_s, 2 * n + 2), complex)
    sr = s[None, :, None]
    z[..., :n_r] = 1.0 / (sr - real[:, None, :])
    if n_c:
        a = 1.0 / (sr - upper[:, None, :])
        b = 1.0 / (sr - np.conj(upper)[:, None, :])
        z[..., n_r:n:2] = a + b
        z[..., n_r + 1 : n : 2] = 1j * (a - b)
    z[..., n] = 1.0
    column_sum = z[..., : n + 1].sum(axis=1)
    z[..., n + 1 :] = z[..., : n + 1] * (-(h * w))[..., None]
    z[..., : n + 1] *= w[..., None]
    # relaxation: Re(sum_k sigma(s_k)) = N, scaled like the data rows
    scale = np.linalg.norm(h * w, axis=-1) / n_s
    relax = np.zeros((g, z.shape[-1]))
    relax[:, n + 1 :] = scale[:, None] * np.real(column_sum)
    # normal equations of the stacked real system [Re z; Im z; relax] x = [0; 0; scale N]:
    # Re(z^H z) + relax relax^T (ten times faster than QR/SVD on these tall, narrow systems and
    # accurate enough for the iterative relocation; the final residues use an SVD solve)
    normal = np.real(np.swapaxes(z.conj(), 1, 2) @ z) + relax[:, :, None] * relax[:, None, :]
    rhs = relax * (scale * n_s)[:, None]
    col = np.sqrt(np.diagonal(normal, axis1=1, axis2=2)).copy()
    col[col == 0] = 1.0
    x = _solve_normal(normal / (col[:, :, None] * col[:, None, :]), rhs / col) / col
    c_sigma, d_sigma = x[:, n + 1 : 2 * n + 1], x[:, 2 * n + 1]
    d_sigma = np.where(np.abs(d_sigma) < 1e-8, np.where(d_sigma >= 0, 1e-8, -1e-8), d_sigma)
    a, b = _state_matrices(real, upper)
    zeros = np.linalg.eigvals(a - b[..., :, None] * c_sigma[..., None, :] / d_sigma[:, None, None])
    zeros = np.where(zeros.real > 0, -zeros.real + 1j * zeros.imag, zeros)  # enforce stability
    tiny = np.abs(zeros.real) < 1e-6 * np.abs(zeros)
    return np.where(tiny, -1e-6 * np.abs(zeros) + 1j * zeros.imag, zeros)


def _solve_normal(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solutions of a batch of normal equations (G, m, m) x = (G, m); a singular one by least squares.

    A starting pole set with coinciding columns makes a relocation's normal matrix exactly
    singular in some BLAS builds (seen with OpenBLAS's Haswell kernels on one thread): its
    minimum-norm least-squares solution relocates the poles as well.
    """
    try:
        return np.linalg.solve(matrix, rhs[..., None])[..., 0]
    except np.linalg.LinAlgError:
        return np.stack([np.linalg.lstsq(m, r, rcond=None)[0] for m, r in zip(matrix, rhs)])


def _residues(s: np.ndarray, h: np.ndarray, w: np.ndarray, poles: np.ndarray, dc: complex | None):
    """Real-coefficient residues and direct term for fixed poles, with the DC value imposed if given."""
    real, upper = _split(poles)
    phi = _basis(s, real, upper)
    if dc is None:
        design = np.concatenate([phi, np.ones((s.size, 1))], axis=1)
        target = h
    else:
        phi0 = _basis(np.zeros(1), real, upper)[0]
        design = phi - phi0[None, :]
        target = h - dc
    system = _stack(design * w[:, None])
    col = np.linalg.norm(system, axis=0)
    col[col == 0] = 1.0
    coef = np.linalg.lstsq(system / col, _stack((target * w)[:, None])[:, 0], rcond=None)[0] / col
    if dc is None:
        c, d = coef[:-1], coef[-1]
    else:
        c, d = coef, float(np.real(dc - phi0 @ coef))
    pair = c[real.size :].reshape(-1, 2)
    upper_res = pair[:, 0] + 1j * pair[:, 1]
    residues = np.concatenate(
        [c[: real.size].astype(complex), np.ravel(np.column_stack([upper_res, upper_res.conj()]))]
    )
    ordered_poles = np.concatenate([real.astype(complex), np.ravel(np.column_stack([upper, upper.conj()]))])
    return ordered_poles, residues, float(np.real(d))


def _weights(freqs: np.ndarray, frf: np.ndarray, weight: np.ndarray | str) -> np.ndarray:
    if isinstance(weight, str):
        if weight not in ("uniform", "relative"):
            raise ValueError(f"weight = {weight!r}: valid values are 'uniform', 'relative' or an array")
        if weight == "uniform":
            return np.ones(frf.shape)
        mag = np.abs(frf)
        return 1.0 / np.maximum(mag, 1e-12 * mag.max(axis=-1, keepdims=True))
    try:
        w = np.broadcast_to(np.asarray(weight, float), frf.shape)
    except ValueError:
        raise ValueError(
            f"weight of shape {np.shape(weight)}: give one weight per frequency ({frf.shape[-1]}) or per FRF value "
            f"{frf.shape}"
        ) from None
    if np.any(w < 0) or not np.all(np.isfinite(w)):
        raise ValueError("weight must be finite, >= 0 and one per frequency")
    return w


def _fit_many(
    freqs: np.ndarray,
    frf: np.ndarray,
    n_poles: int,
    weight: np.ndarray | str,
    iterations: int,
    tolerance: float,
    enforce_dc: bool,
) -> list[RationalFit]:
    """Relaxed vector fitting of each row of ``frf`` (own poles per row), batched over rows."""
    n_poles = _check_options(n_poles, iterations, tolerance)
    _check_data(freqs, frf, n_poles)
    scale = 2 * np.pi * freqs[-1]
    s = 2j * np.pi * freqs / scale
    w = _weights(freqs, frf, weight)
    m = frf.shape[0]
    poles = np.tile(_initial_poles(n_poles), (m, 1))
    used = np.zeros(m, int)
    active = np.ones(m, bool)
    for it in range(1, iterations + 1):
        splits = [_split(p) for p in poles]
        structure = np.array([r.size for r, _ in splits])
        new = poles.copy()
        for n_r in np.unique(structure[active]):
            rows = np.nonzero(active & (structure == n_r))[0]
            real = np.array([splits[i][0] for i in rows]).reshape(rows.size, n_r)
            upper = np.array([splits[i][1] for i in rows]).reshape(rows.size, (n_poles - n_r) // 2)
            zeros = _relocate(s, frf[rows], w[rows], real, upper)
            new[rows] = [_conjugate_closed(z) for z in zeros]
        moved = np.max(np.abs(np.sort_complex(new) - np.sort_complex(poles)), axis=1) / np.max(np.abs(poles), axis=1)
        poles = new
        used[active] = it
        active &= moved >= tolerance
        if not active.any():
            break
    fits = []
    for i in range(m):
        dc = frf[i, 0] if (enforce_dc and freqs[0] == 0.0) else None
        p, r, d = _residues(s, frf[i], w[i], poles[i], dc)
        fitted = (r[None, :] / (s[:, None] - p[None, :])).sum(axis=1) + d
        dc_error = abs(fitted[0] - frf[i, 0]) / abs(frf[i, 0]) if freqs[0] == 0.0 and frf[i, 0] != 0 else float("nan")
        fits.append(
            RationalFit(
                poles=p * scale,
                residues=r * scale,
                direct=d,
                rms_error=relative_rms_error(fitted, frf[i]),
                max_error=float(np.max(np.abs(fitted - frf[i])) / np.max(np.abs(frf[i]))),
                dc_error=float(dc_error),
                iterations=int(used[i]),
            )
        )
    return fits


def _conjugate_closed(zeros: np.ndarray) -> np.ndarray:
    """The zeros of a real sigma(s) as real poles + exact conjugate pairs (round-off removed)."""
    real, upper = _split(zeros)
    n_pairs = (zeros.size - real.size) // 2
    if upper.size != n_pairs:  # round-off split a pair unevenly: keep the n_pairs most complex ones
        upper = upper[np.argsort(-np.abs(upper.imag))][:n_pairs]
        real = np.sort(zeros.real[np.argsort(np.abs(zeros.imag))][: zeros.size - 2 * n_pairs])
    return np.concatenate([real.astype(complex), np.ravel(np.column_stack([upper, upper.conj()]))])


def vector_fit(
    freqs: np.ndarray,
    frf: np.ndarray,
    n_poles: int = 8,
    weight: np.ndarray | str = "uniform",
    iterations: int = 8,
    tolerance: float = 1e-3,
    enforce_dc: bool = True,
) -> RationalFit:
    """Fit one FRF with ``n_poles`` stable poles and a direct term (biproper).

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
        Maximum pole relocations (default 8; vector fitting usually converges in 3-5, and more
        iterations let poles that the data do not pin down wander without improving the fit).
    tolerance : float
        Stop a fit when its poles move less than this relative to the largest pole (default
        1e-3: well converged poles keep drifting far below any visible change of the fit).
    enforce_dc : bool
        Impose ``G(0) = frf(0)`` exactly when ``freqs[0] == 0`` (the static influence).
    """
    freqs, frf = _as_arrays(freqs, frf)
    if frf.ndim != 1:
        raise ValueError(f"frf must be 1-D (one FRF; fit_tasselli fits one per row), got shape {frf.shape}")
    return _fit_many(freqs, frf[None, :], n_poles, weight, iterations, tolerance, enforce_dc)[0]


def _as_arrays(freqs, frf) -> tuple[np.ndarray, np.ndarray]:
    """Frequencies (float) and FRFs (complex) as arrays, or a ValueError naming the one that is not numeric."""
    for name, value, dtype in (("freqs", freqs, float), ("frf", frf, complex)):
        try:
            np.asarray(value, dtype)
        except (TypeError, ValueError):
            raise ValueError(f"{name} must be numbers ({'real' if dtype is float else 'complex'})") from None
    return np.asarray(freqs, float), np.asarray(frf, complex)


def fit_tasselli(
    freqs: np.ndarray,
    H: np.ndarray,
    n_poles: int = 8,
    f_max: float | None = 250.0,
    weight: np.ndarray | str = "uniform",
    iterations: int = 8,
    tolerance: float = 1e-3,
    enforce_dc: bool = True,
) -> FitSet:
    """One rational fit per row of ``H`` [tassello, frequency] over ``0-f_max`` Hz (paper Eq. 1).

    Each row gets its own poles; the pole relocations of all rows run batched.

    Parameters
    ----------
    freqs : ndarray
        Frequencies (Hz) of the columns of ``H``.
    H : ndarray (n_fits, n_freq) or (n_freq,), complex
        The FRFs (N/m).
    n_poles : int
        Poles (= zeros) per fit; the paper's 8 by default.
    f_max : float or None
        Top of the fitted band (Hz); paper: 250 Hz. ``None`` fits all frequencies.
    weight, iterations, tolerance, enforce_dc
        As in :func:`vector_fit`.
    """
    freqs, H = _as_arrays(freqs, H)
    H = np.atleast_2d(H)
    if H.ndim != 2:
        raise ValueError(f"H must be 1-D or 2-D [fit, frequency], got shape {H.shape}")
    if freqs.ndim != 1 or H.shape[-1] != freqs.size:
        raise ValueError(f"H must have the frequencies on its last axis ({freqs.size}), got shape {H.shape}")
    if not np.all(np.isfinite(freqs)):
        raise ValueError("freqs must be finite (a NaN frequency is not dropped silently)")
    _check_options(n_poles, iterations, tolerance)
    if f_max is not None:
        guards.real("f_max", f_max, 0.0, lo_open=True, unit="Hz")
    band = freqs <= f_max if f_max is not None else np.ones(freqs.size, bool)
    if not band.any():
        raise ValueError(f"no frequency below f_max = {f_max} Hz")
    if not isinstance(weight, str) and np.shape(weight)[-1:] != (freqs.size,):
        raise ValueError(f"weight of shape {np.shape(weight)}: give one weight per frequency ({freqs.size})")
    w = weight if isinstance(weight, str) else np.asarray(weight, float)[..., band]
    start = time.perf_counter()
    with threadpool_limits(FIT_THREADS, user_api="blas"):  # small batched solves: threads only fight
        fits = _fit_many(freqs[band], H[:, band], n_poles, w, iterations, tolerance, enforce_dc)
    return FitSet(
        fits=fits,
        freqs=freqs[band],
        band=(float(freqs[band][0]), float(freqs[band][-1])),
        seconds=time.perf_counter() - start,
    )
