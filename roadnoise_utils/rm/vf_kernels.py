"""The linear-algebra kernels of vector fitting, shared by the per-tassello and the common-pole fits.

Relaxed vector fitting (Gustavsen & Semlyen, IEEE Trans. Power Delivery 14(3), 1999; Gustavsen,
IEEE Trans. Power Delivery 21(3), 2006) in the real partial-fraction basis: each complex pair
:math:`p, \\bar p` carries the two real basis functions
:math:`\\phi_1 = 1/(s-p) + 1/(s-\\bar p)` and :math:`\\phi_2 = i/(s-p) - i/(s-\\bar p)`, so every
coefficient is real and the fitted :math:`G(s)` of paper Eq. 1 has a real impulse response.
Frequencies are scaled (``s`` divided by the band's top angular frequency) by the callers.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


def check_data(freqs: np.ndarray, frf: np.ndarray, n_poles: int) -> None:
    if freqs.ndim != 1 or frf.shape[-1] != freqs.size:
        raise ValueError(
            f"freqs ({freqs.size} values) and frf (shape {frf.shape}) disagree: frf must have one value per "
            "frequency on its last axis"
        )
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


#: The starting pole sets :func:`initial_poles` knows: lightly damped pairs spread evenly over
#: the band (Gustavsen & Semlyen 1999) or evenly on a log scale from its lowest nonzero
#: frequency (as pyvectorfit starts): the first suits modes spread evenly in frequency, the
#: second a response with low-frequency features (e.g. real poles far below the top).
STARTS = ("linear", "log")
#: The default: the linear start alone, whose fits do not follow round-off (see ``vector_fit``).
DEFAULT_STARTS = ("linear",)


def initial_poles(n_poles: int, spacing: str = "linear", lowest: float = 0.0) -> np.ndarray:
    """Starting poles (scaled ``s``): lightly damped complex pairs, one real pole if n is odd.

    ``spacing`` "linear": the pairs' imaginary parts evenly spread over (0, 1]; "log": evenly on a
    log scale from ``lowest`` (the band's lowest nonzero frequency over its top, 0 < lowest < 1)
    to 1. Damping ratio 1 % (Gustavsen & Semlyen 1999).
    """
    n_pairs = n_poles // 2
    if spacing == "log" and n_pairs and 0.0 < lowest < 1.0:
        imag = np.geomspace(lowest, 1.0, n_pairs)
    else:
        imag = np.linspace(1.0 / (n_pairs + 1), 1.0, n_pairs) if n_pairs else np.array([])
    pairs = -0.01 * imag + 1j * imag
    poles = np.concatenate([np.ravel(np.column_stack([pairs, pairs.conj()])), [-0.5] * (n_poles % 2)])
    return poles.astype(complex)


def split_poles(poles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real poles and the upper members of the complex pairs."""
    tol = 1e-10 * max(1.0, np.max(np.abs(poles)))
    real = poles[np.abs(poles.imag) <= tol].real
    upper = poles[poles.imag > tol]
    return real, upper


def basis(s: np.ndarray, real: np.ndarray, upper: np.ndarray) -> np.ndarray:
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


def state_matrices(real: np.ndarray, upper: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Real block-diagonal (A, b), batched, whose c (sI - A)^-1 b reproduces :func:`basis`."""
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


def stack_parts(m: np.ndarray) -> np.ndarray:
    """Real and imaginary parts stacked along the row axis (-2)."""
    return np.concatenate([m.real, m.imag], axis=-2)


def relocate(
    s: np.ndarray, h: np.ndarray, w: np.ndarray, real: np.ndarray, upper: np.ndarray, proportional: bool = False
) -> np.ndarray:
    """One relaxed pole relocation (Gustavsen 2006) for a batch of fits with the same pole structure.

    ``h``, ``w``: (G, n_s); ``real`` (G, n_r), ``upper`` (G, n_c); ``proportional``: the model
    has a term ``e s`` besides the constant. Returns the zeros of each fitted sigma(s),
    stabilised: (G, n) complex.

    The least squares are solved by a QR factorisation of the column-scaled real system, the
    right-hand side appended as its last column (its triangular factor then carries
    :math:`Q^T b`; :func:`solve_triangular_factor`): normal equations would square the system's
    condition number, up to about 1e10 at 20-24 poles, and their solutions would follow round-off.
    """
    g, n_s = h.shape
    n_r, n_c = real.shape[-1], upper.shape[-1]
    n = n_r + 2 * n_c
    m = n + (2 if proportional else 1)  # the model's unknowns: partial fractions, constant (and e)
    k = m + n + 1
    # the design matrix [phi w, w, (s w), -phi h w, -h w] (this step is memory-bound)
    z = np.empty((g, n_s, k), complex)
    sr = s[None, :, None]
    z[..., :n_r] = 1.0 / (sr - real[:, None, :])
    if n_c:
        a = 1.0 / (sr - upper[:, None, :])
        b = 1.0 / (sr - np.conj(upper)[:, None, :])
        z[..., n_r:n:2] = a + b
        z[..., n_r + 1 : n : 2] = 1j * (a - b)
    z[..., n] = 1.0
    if proportional:
        z[..., n + 1] = s[None, :]
    column_sum = z[..., : n + 1].sum(axis=1)
    z[..., m:] = z[..., : n + 1] * (-(h * w))[..., None]
    z[..., :m] *= w[..., None]
    # the stacked real system [Re z; Im z; relax | b] with b = [0; 0; scale N]; relaxation:
    # Re(sum_k sigma(s_k)) = N, scaled like the data rows
    scale = np.linalg.norm(h * w, axis=-1) / n_s
    system = np.zeros((g, 2 * n_s + 1, k + 1))
    system[:, :n_s, :k] = z.real
    system[:, n_s : 2 * n_s, :k] = z.imag
    system[:, -1, m:k] = scale[:, None] * np.real(column_sum)
    system[:, -1, k] = scale * n_s
    col = np.linalg.norm(system[..., :k], axis=1)
    col[col == 0] = 1.0
    system[..., :k] /= col[:, None, :]
    r = np.linalg.qr(system, mode="r")
    x = solve_triangular_factor(r[:, :k, :k], r[:, :k, k]) / col
    return sigma_zeros(real, upper, x[:, m : m + n], x[:, m + n])


def sigma_zeros(real: np.ndarray, upper: np.ndarray, c_sigma: np.ndarray, d_sigma: np.ndarray) -> np.ndarray:
    """Zeros of the fitted :math:`\\sigma(s) = c_\\sigma (sI - A)^{-1} b + d_\\sigma`, reflected into the left half-plane.

    Batched: ``real`` (G, n_r), ``upper`` (G, n_c), ``c_sigma`` (G, n), ``d_sigma`` (G,); the
    zeros, the next poles, are the eigenvalues of :math:`A - b c_\\sigma / d_\\sigma`
    (Gustavsen & Semlyen 1999). Returns (G, n) complex.
    """
    d_sigma = np.where(np.abs(d_sigma) < 1e-8, np.where(d_sigma >= 0, 1e-8, -1e-8), d_sigma)
    a, b = state_matrices(real, upper)
    zeros = np.linalg.eigvals(a - b[..., :, None] * c_sigma[..., None, :] / d_sigma[:, None, None])
    zeros = np.where(zeros.real > 0, -zeros.real + 1j * zeros.imag, zeros)  # enforce stability
    tiny = np.abs(zeros.real) < 1e-6 * np.abs(zeros)
    return np.where(tiny, -1e-6 * np.abs(zeros) + 1j * zeros.imag, zeros)


def solve_triangular_factor(r: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Least-squares solutions of a batch of QR factors, R x = Q^T b: (G, k, k), (G, k) -> (G, k).

    A factor whose smallest diagonal entry is below ``k`` round-offs of its largest is rank
    deficient: coinciding poles (e.g. two slow poles confined to the same floor) give identical
    columns, which Householder QR leaves at ~1e-16 rather than exactly 0. Such a factor gets its
    minimum-norm solution (:func:`numpy.linalg.lstsq`, whose cut-off is the same), which
    relocates the poles as well; the others a plain solve.
    """
    k = r.shape[-1]
    diagonal = np.abs(np.diagonal(r, axis1=-2, axis2=-1))
    deficient = diagonal.min(axis=-1) <= k * np.finfo(float).eps * diagonal.max(axis=-1)
    x = np.empty(rhs.shape)
    full = ~deficient
    if full.any():
        x[full] = np.linalg.solve(r[full], rhs[full][..., None])[..., 0]
    for i in np.nonzero(deficient)[0]:
        x[i] = np.linalg.lstsq(r[i], rhs[i], rcond=None)[0]
    return x


def solve_square(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solutions of a batch of square systems (G, m, m) x = (G, m); an exactly singular one by least squares.

    A selection's normal matrix of a pole set with coinciding columns can be exactly singular:
    its minimum-norm least-squares solution gives the same residual.
    """
    try:
        return np.linalg.solve(matrix, rhs[..., None])[..., 0]
    except np.linalg.LinAlgError:
        return np.stack([np.linalg.lstsq(m, r, rcond=None)[0] for m, r in zip(matrix, rhs)])


class PoleResidueModel(NamedTuple):
    """A fit for fixed poles (scaled ``s``): :math:`G(s) = \\sum_k r_k/(s - p_k) + d + e s`.

    ``fitted`` is :math:`G` at the fitted ``s``; ``error`` the weighted relative RMS error
    :math:`\\|w (G - H)\\|/\\|w H\\|` that the residues' least squares minimise; ``proportional``
    the coefficient ``e`` (0 unless the fit has the term).
    """

    poles: np.ndarray
    residues: np.ndarray
    direct: float
    fitted: np.ndarray
    error: float
    proportional: float = 0.0


def _asymptote(s: np.ndarray, proportional: bool) -> np.ndarray:
    """The columns of the model's polynomial part: the constant, and ``s`` with a proportional term."""
    return np.column_stack([np.ones_like(s), s]) if proportional else np.ones((s.size, 1))


def residues(
    s: np.ndarray, h: np.ndarray, w: np.ndarray, poles: np.ndarray, dc: complex | None, proportional: bool = False
):
    """Real-coefficient residues, direct and proportional terms for fixed poles, the DC value imposed if given.

    Returns ``(poles, residues, d, e)``, the poles and residues ordered real first, then pairs.
    """
    real, upper = split_poles(poles)
    phi = basis(s, real, upper)
    polynomial = _asymptote(s, proportional)
    if dc is None:
        design = np.concatenate([phi, polynomial], axis=1)
        target = h
    else:  # d = dc - phi(0) c (the term e s vanishes at 0)
        phi0 = basis(np.zeros(1), real, upper)[0]
        design = np.concatenate([phi - phi0[None, :], polynomial[:, 1:]], axis=1)
        target = h - dc
    system = stack_parts(design * w[:, None])
    col = np.linalg.norm(system, axis=0)
    col[col == 0] = 1.0
    coef = np.linalg.lstsq(system / col, stack_parts((target * w)[:, None])[:, 0], rcond=None)[0] / col
    n = phi.shape[1]
    c = coef[:n]
    e = float(coef[-1]) if proportional else 0.0
    d = float(np.real(dc - phi0 @ c)) if dc is not None else float(coef[n])
    pair = c[real.size :].reshape(-1, 2)
    upper_res = pair[:, 0] + 1j * pair[:, 1]
    ordered_residues = np.concatenate(
        [c[: real.size].astype(complex), np.ravel(np.column_stack([upper_res, upper_res.conj()]))]
    )
    ordered_poles = np.concatenate([real.astype(complex), np.ravel(np.column_stack([upper, upper.conj()]))])
    return ordered_poles, ordered_residues, d, e


def fit_for_poles(
    s: np.ndarray, h: np.ndarray, w: np.ndarray, poles: np.ndarray, dc: complex | None, proportional: bool = False
) -> PoleResidueModel:
    """Residues for fixed ``poles`` (:func:`residues`), the fitted response at ``s`` and the fit's selection error."""
    p, r, d, e = residues(s, h, w, poles, dc, proportional)
    fitted = (r[None, :] / (s[:, None] - p[None, :])).sum(axis=1) + d + e * s
    error = float(np.linalg.norm(w * (fitted - h)) / np.linalg.norm(w * h))
    return PoleResidueModel(p, r, d, fitted, error, e)


def errors_for_poles(
    s: np.ndarray,
    h: np.ndarray,
    w: np.ndarray,
    real: np.ndarray,
    upper: np.ndarray,
    dc: np.ndarray | None,
    proportional: bool = False,
) -> np.ndarray:
    """Selection errors of a batch of rows for fixed poles: :func:`fit_for_poles`'s error, batched.

    ``h``, ``w`` (G, n_s); ``real`` (G, n_r), ``upper`` (G, n_c); ``dc`` (G,) or None. The same
    least squares (DC imposed when given) solved by batched normal equations of the column-scaled
    system instead of one SVD per row: the same error wherever it is above ~1e-10, which is all
    the choice of the best iteration needs (the kept poles' residues and error come from
    :func:`fit_for_poles`). Returns (G,) weighted relative RMS errors.
    """
    phi = basis(s, real, upper)  # (G, n_s, n)
    polynomial = np.broadcast_to(_asymptote(s, proportional), (*phi.shape[:-1], 2 if proportional else 1))
    if dc is None:
        design = np.concatenate([phi, polynomial], axis=-1)
        target = h
    else:
        design = np.concatenate([phi - basis(np.zeros(1), real, upper), polynomial[..., 1:]], axis=-1)
        target = h - dc[:, None]
    system = stack_parts(design * w[..., None])
    col = np.linalg.norm(system, axis=-2)
    col[col == 0] = 1.0
    system /= col[:, None, :]
    rhs = stack_parts((target * w)[..., None])[..., 0]
    # normal equations, the residual then formed explicitly: an error dx in the coefficients adds
    # only |A dx|^2 to the squared residual (the least-squares minimum is stationary), far below
    # the fits' errors
    coef = solve_square(np.swapaxes(system, 1, 2) @ system, np.einsum("gij,gi->gj", system, rhs))
    residual = np.einsum("gij,gj->gi", system, coef) - rhs
    return np.linalg.norm(residual, axis=-1) / np.linalg.norm(h * w, axis=-1)


#: Smallest damping ratio of a pole above the fitted band (scaled ``|Im p| > 1``): the data do not
#: constrain a pole there, and relocation left to itself can park a nearly undamped one (seen at
#: 370-390 Hz on 0-250 Hz fits, damping ratio 1e-4, peaks 700-3300 times the tassello's static
#: stiffness) that a time simulation rings with. Tire modes are damped 1-6 %: 0.5 % leaves a real
#: mode just above the band free (a floor of 1-5 % cost fits at 18-20 poles up to 2.4-117 times
#: their error, measured on the paper tires).
OUT_OF_BAND_DAMPING = 0.005
#: Slowest decay of a pole, as a fraction of the band's lowest nonzero angular frequency (its
#: resolution when sampled from 0): a slower time constant (above 16 s on a 1 Hz grid; seen:
#: 164 s) cannot be resolved by the data and only lengthens every simulation's memory; a floor of
#: 3-10 % cost fits at 18-20 poles up to 1.6-3.6 times their error.
SLOWEST_DECAY = 0.01


def confine(poles: np.ndarray, omega_low: float) -> np.ndarray:
    """Poles (scaled ``s``, band top at 1) moved left onto the limits the data can support.

    A pole above the band is damped to at least :data:`OUT_OF_BAND_DAMPING`; every pole decays at
    least at :data:`SLOWEST_DECAY` times ``omega_low`` (the band's lowest nonzero scaled
    frequency). Imaginary parts are kept (conjugate pairs stay pairs); like the reflection of
    unstable poles, a constraint on the relocation, not a rejection.
    """
    decay = -poles.real
    zeta = OUT_OF_BAND_DAMPING  # -Re p = zeta |p| with Im p kept: -Re p = zeta |Im p| / sqrt(1 - zeta^2)
    floor = np.where(np.abs(poles.imag) > 1.0, zeta * np.abs(poles.imag) / np.sqrt(1 - zeta**2), 0.0)
    floor = np.maximum(floor, SLOWEST_DECAY * omega_low)
    return np.where(decay < floor, -floor + 1j * poles.imag, poles)


def weights(freqs: np.ndarray, frf: np.ndarray, weight: np.ndarray | str) -> np.ndarray:
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
    empty = np.nonzero(~np.any(w.reshape(-1, w.shape[-1]) > 0, axis=-1))[0]
    if empty.size:
        raise ValueError(
            f"weight is zero at every frequency of FRF row(s) {empty.tolist()[:10]}: a fit there is undetermined; "
            "give a positive weight where the FRF should be matched"
        )
    return w


def conjugate_closed(zeros: np.ndarray) -> np.ndarray:
    """The zeros of a real sigma(s) as real poles + exact conjugate pairs (round-off removed)."""
    real, upper = split_poles(zeros)
    n_pairs = (zeros.size - real.size) // 2
    if upper.size != n_pairs:  # round-off split a pair unevenly: keep the n_pairs most complex ones
        upper = upper[np.argsort(-np.abs(upper.imag))][:n_pairs]
        real = np.sort(zeros.real[np.argsort(np.abs(zeros.imag))][: zeros.size - 2 * n_pairs])
    return np.concatenate([real.astype(complex), np.ravel(np.column_stack([upper, upper.conj()]))])


#: Largest FRF magnitude a fit accepts: the least-squares system squares it (1e150 squared is
#: near the float range). Structural FRFs in SI units are below ~1e9 N/m.
MAX_FRF = 1e150


def as_arrays(freqs, frf, frf_name: str = "frf") -> tuple[np.ndarray, np.ndarray]:
    """Frequencies (float) and FRFs (complex) as arrays, or a ValueError naming the one (the FRFs as
    ``frf_name``) that is not numeric (rows of different lengths included), empty, not finite or too
    large to fit."""
    arrays = []
    for name, value, dtype in (("freqs", freqs, float), (frf_name, frf, complex)):
        try:
            arrays.append(np.asarray(value, dtype))
        except (TypeError, ValueError):
            raise ValueError(
                f"{name} must be numbers ({'real' if dtype is float else 'complex'}), every row as long as freqs"
            ) from None
    freqs, frf = arrays
    if frf.size == 0 or freqs.size == 0:
        raise ValueError(f"freqs (shape {freqs.shape}) and {frf_name} (shape {frf.shape}) must not be empty")
    if not np.all(np.isfinite(frf)):
        raise ValueError(f"{frf_name} contains NaN or inf")
    largest = float(np.abs(frf).max(initial=0.0))
    if largest > MAX_FRF:
        raise ValueError(
            f"{frf_name}: values up to {largest:.3g}, valid range is |H| <= {MAX_FRF:g} (give the FRFs in SI units, e.g. N/m)"
        )
    return freqs, frf
