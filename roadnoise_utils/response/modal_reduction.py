"""Global damping identification and modal reduction (paper stages 3-5, Fig. 4-5).

The paper avoids a viscoelastic solve per tassello and frequency with a three-step procedure
(section *The FET Model*, Fig. 4):

1. **Global damping identification.** From the whole-footprint FRF :math:`H_{tot}(\\omega)` of
   the viscoelastic model (FETvisco) "the damping coefficients of the principal vertical modes
   have been identified in the frequency range 0-250 Hz".
2. **Modal reduction.** The moduli are "frozen to the frequency of the most relevant vertical
   mode (~70 Hz)" (FET70Hz) and the eigenmodes computed.
3. **Local FRF computation.** Modes + identified damping give every local FRF :math:`H_i`.

**Identification** (:func:`identify_modes`) fits a hysteretic modal model

.. math:: H(\\omega) \\approx \\sum_r \\frac{A_r}{\\omega_r^2 (1 + i\\eta_r) - \\omega^2} + R_0 + R_2\\,\\omega^2

(rubber damping is hysteretic: a loss factor, not a viscous rate), with complex residues
:math:`A_r` and residual terms for the modes outside the band. The poles
:math:`(\\omega_r, \\eta_r)` are found by nonlinear least squares with the linear parameters
projected out (variable projection, Golub & Pereyra 1973); the half-power bandwidth of each
peak gives an independent estimate of the damping ratio :math:`\\zeta_r \\approx \\eta_r/2`.

**Reduction** (:func:`modal_reduction`). Only modes symmetric fore-aft and left-right move the
hub vertically (:mod:`roadnoise_utils.tire.ring.symmetry`), so the modes are computed in that subspace, exactly. Two
frozen models are offered:

* ``frozen="storage"`` — the paper as written: real modes of the storage stiffness at the
  reference frequency (FET70Hz has no loss) joined with the identified loss factors for the
  modes seen in :math:`H_{tot}`, interpolated ones for the others;
* ``frozen="complex"`` (default) — the complex moduli (storage *and* loss) frozen at the
  reference frequency. Its complex modes carry the coupling of the rubber losses between
  modes and the loss of the tread springs that push the footprint, which the individual
  tasselli need; the identified loss factors are joined to the modes seen in :math:`H_{tot}`
  (``damping="identified"``, default) or the modes keep their own (``damping="model"``),
  which checks the identification.

For contact point (or tassello) ``n`` the reduced FRF is

.. math:: H_n(\\omega) = S_n(\\omega) - \\sum_r (K_{hf}\\phi_r)(\\phi_r^T b_n)
          \\left[\\frac{1}{\\lambda_r - \\omega^2} - \\frac{1}{\\lambda_r}\\right]

with :math:`\\lambda_r` the (complex) eigenvalues and :math:`S_n(\\omega)` the *quasi-static*
response (no inertia) of the viscoelastic model with the moduli at :math:`\\omega`: the
residual (static) correction for the truncated modes. :math:`S` is computed at a few anchor
frequencies (0 Hz included, so :math:`H_n(0)` is exact) and interpolated between them; it is
smooth because it only follows the rubber moduli. :math:`G_H` has the same form.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.interpolate import PchipInterpolator
from scipy.optimize import least_squares

from .. import guards
from ..analysis import resonance_peaks
from ..tire.model import FRFResult


@dataclass(frozen=True)
class ModeIdentification:
    """Modal parameters identified from one FRF (hysteretic damping).

    Attributes
    ----------
    freqs : ndarray
        Natural frequencies :math:`\\omega_r / 2\\pi` (Hz).
    loss_factor : ndarray
        Modal loss factors :math:`\\eta_r` (-) from the least-squares fit.
    damping_half_power : ndarray
        Damping ratios from the half-power bandwidth of each peak (-), NaN where the peak is
        not isolated enough to measure it.
    residues : ndarray, complex
        :math:`A_r` (N/m rad^2/s^2).
    residual : tuple of complex
        :math:`(R_0, R_2)` (N/m, N s^2/m).
    band : tuple of float
        Frequency band of the fit (Hz).
    rms_error : float
        Relative RMS error of the fit over the band (-).
    """

    freqs: np.ndarray
    loss_factor: np.ndarray
    damping_half_power: np.ndarray
    residues: np.ndarray
    residual: tuple[complex, complex]
    band: tuple[float, float]
    rms_error: float

    @property
    def damping(self) -> np.ndarray:
        """Equivalent damping ratios :math:`\\zeta_r = \\eta_r / 2` (-)."""
        return 0.5 * self.loss_factor

    @property
    def static_share(self) -> np.ndarray:
        """Static contribution of each mode :math:`\\mathrm{Re}[A_r / \\omega_r^2(1 + i\\eta_r)]` (N/m)."""
        return np.real(self.residues / ((2 * np.pi * self.freqs) ** 2 * (1 + 1j * self.loss_factor)))

    def evaluate(self, freqs: np.ndarray) -> np.ndarray:
        """The fitted FRF at ``freqs`` (Hz)."""
        basis = _basis(2 * np.pi * np.asarray(freqs, float), 2 * np.pi * self.freqs, self.loss_factor)
        return basis @ np.concatenate([self.residues, self.residual])

    def table(self, total_static: complex | None = None) -> pd.DataFrame:
        """Modes: frequency, damping ratio (fit, half-power), static share (N/mm, share of ``total_static``)."""
        out = pd.DataFrame(
            {
                "frequency (Hz)": self.freqs,
                "damping ratio (fit, eta/2)": self.damping,
                "damping ratio (half-power)": self.damping_half_power,
                "static share (N/mm)": self.static_share / 1e3,
            },
            index=pd.Index(np.arange(1, self.freqs.size + 1), name="mode"),
        )
        if total_static is not None:
            out["share of H(0)"] = self.static_share / np.real(total_static)
        return out


def _basis(omega: np.ndarray, omega_r: np.ndarray, eta: np.ndarray) -> np.ndarray:
    den = (omega_r**2 * (1 + 1j * eta))[None, :] - omega[:, None] ** 2
    return np.column_stack([1.0 / den, np.ones_like(omega), omega**2])


def _half_power_damping(freqs: np.ndarray, mag: np.ndarray, f_peak: float) -> float:
    """Half-power bandwidth estimate zeta = (f2 - f1) / (2 f_peak), or NaN if not measurable."""
    i = int(np.argmin(np.abs(freqs - f_peak)))
    level = mag[i] / np.sqrt(2.0)
    lo = i
    while lo > 0 and mag[lo] > level:
        lo -= 1
    hi = i
    while hi < mag.size - 1 and mag[hi] > level:
        hi += 1
    if lo == 0 or hi == mag.size - 1 or np.any(np.diff(mag[lo : i + 1]) < 0) or np.any(np.diff(mag[i : hi + 1]) > 0):
        return float("nan")  # another peak or a valley inside the half-power band
    f1 = np.interp(level, [mag[lo], mag[lo + 1]], [freqs[lo], freqs[lo + 1]])
    f2 = np.interp(level, [mag[hi], mag[hi - 1]], [freqs[hi], freqs[hi - 1]])
    return float((f2 - f1) / (2 * f_peak))


def identify_modes(
    freqs: np.ndarray, frf: np.ndarray, f_max: float = 250.0, min_ratio: float = 2.0
) -> ModeIdentification:
    """Identify the resonant modes of an FRF in ``[0, f_max]`` Hz by modal least squares.

    Parameters
    ----------
    freqs : ndarray
        Frequencies (Hz), strictly increasing.
    frf : ndarray, complex
        The FRF (e.g. :math:`H_{tot}`, N/m).
    f_max : float
        Upper end of the fitted band (Hz); paper: 250 Hz.
    min_ratio : float
        A peak counts as a mode when ``|frf|`` there exceeds ``min_ratio * |frf(f_0)|``.
    """
    f_max = guards.real("f_max", f_max, 0.0, lo_open=True, unit="Hz")
    min_ratio = guards.real("min_ratio", min_ratio, 0.0, lo_open=True)
    freqs = np.asarray(freqs, float)
    frf = np.asarray(frf, complex)
    if freqs.shape != frf.shape or freqs.ndim != 1:
        raise ValueError(f"freqs {freqs.shape} and frf {frf.shape} must be 1-D arrays of the same length")
    if not np.all(np.isfinite(frf)):
        raise ValueError("frf contains NaN or inf")
    if not np.all(np.diff(freqs) > 0):
        raise ValueError("freqs must be strictly increasing")
    peaks, _ = resonance_peaks(freqs, frf, min_ratio)
    peaks = peaks[peaks <= f_max]
    if peaks.size == 0:
        raise ValueError(f"no resonance peak in 0-{f_max:g} Hz above {min_ratio} x |H(0)|")
    hp = np.array([_half_power_damping(freqs, np.abs(frf), f) for f in peaks])
    band = freqs <= f_max
    omega = 2 * np.pi * freqs[band]
    data = frf[band]
    weight = 1.0 / np.maximum(np.abs(data), 1e-3 * np.abs(data).max())
    n = peaks.size

    def solve_linear(params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        basis = _basis(omega, params[:n], params[n:])
        weighted = basis * weight[:, None]
        scale = np.linalg.norm(weighted, axis=0)  # equilibrate the columns (1/den ~ 1e-6, w^2 ~ 1e6)
        coef, *_ = np.linalg.lstsq(weighted / scale, data * weight, rcond=None)
        return coef / scale, basis

    def residual(params: np.ndarray) -> np.ndarray:
        coef, basis = solve_linear(params)
        r = (basis @ coef - data) * weight
        return np.concatenate([r.real, r.imag])

    omega0 = 2 * np.pi * peaks
    eta0 = np.clip(np.where(np.isfinite(hp), 2 * hp, 0.05), 4e-3, 0.6)
    fit = least_squares(
        residual,
        np.concatenate([omega0, eta0]),
        bounds=(np.concatenate([omega0 * 0.9, np.full(n, 1e-4)]), np.concatenate([omega0 * 1.1, np.full(n, 1.0)])),
        x_scale=np.concatenate([omega0, np.full(n, 0.02)]),
        ftol=1e-12,
        xtol=1e-12,
        gtol=1e-12,
        max_nfev=2000,
    )
    coef, basis = solve_linear(fit.x)
    err = np.sqrt(np.mean(np.abs(basis @ coef - data) ** 2) / np.mean(np.abs(data) ** 2))
    return ModeIdentification(
        freqs=fit.x[:n] / (2 * np.pi),
        loss_factor=fit.x[n:],
        damping_half_power=hp,
        residues=coef[:n],
        residual=(complex(coef[n]), complex(coef[n + 1])),
        band=(float(freqs[band][0]), float(f_max)),
        rms_error=float(err),
    )


@dataclass(frozen=True, eq=False)
class ModalModel:
    """The reduced tire: frozen modes, identified damping, quasi-static residual correction.

    Attributes
    ----------
    reference_frequency : float
        Frequency at which the moduli are frozen (Hz).
    frozen : str
        ``"complex"`` or ``"storage"`` (see the module docstring).
    eigenvalues : ndarray (n_modes,), complex
        :math:`\\lambda_r = \\omega_r^2 (1 + i\\eta_r)` used by the model (rad^2/s^2).
    damping_source : ndarray of str
        ``"identified"`` (loss factor from :math:`H_{tot}`), ``"frozen model"`` or ``"interpolated"``.
    hub_gain : ndarray (n_modes,), complex
        :math:`K_{hf}\\phi_r` (N/m per unit modal coordinate).
    point_gain : ndarray (n_modes, n_contact), complex
        :math:`\\phi_r^T b_n` (N/m per unit modal coordinate).
    anchor_freqs : ndarray (n_anchor,)
        Frequencies of the quasi-static solves (Hz), 0 Hz first.
    anchor_points : ndarray (n_anchor, n_contact), complex
        Quasi-static response :math:`S_n` (no inertia, moduli at the anchor) (N/m).
    anchor_hub : ndarray (n_anchor,), complex
        Quasi-static :math:`G_H` at the anchors (N/m).
    membership : ndarray (n_tasselli, n_contact)
        Which contact points each tassello moves.
    hub_mass : complex
        Mass that moves with the hub and no mode carries (kg): adds :math:`\\omega^2 m` to
        :math:`G_H` (0 for the ring model, whose rim-side mass is outside :math:`G_H`).
    point_mass : ndarray (n_contact,) complex or None
        Each contact point's mass coupled to the hub's that no mode carries (kg): adds
        :math:`\\omega^2 m_n` to its transfer (the loaded FE tire's consistent mass couples its held
        nodes to the rim; None: the ring's and the cross-section's points carry none).
    """

    reference_frequency: float
    frozen: str
    eigenvalues: np.ndarray
    damping_source: np.ndarray
    hub_gain: np.ndarray
    point_gain: np.ndarray
    anchor_freqs: np.ndarray
    anchor_points: np.ndarray
    anchor_hub: np.ndarray
    membership: np.ndarray
    hub_mass: complex = 0.0
    point_mass: np.ndarray | None = None

    @property
    def freqs(self) -> np.ndarray:
        """Natural frequencies :math:`\\sqrt{\\mathrm{Re}\\,\\lambda_r}/2\\pi` (Hz)."""
        return np.sqrt(self.eigenvalues.real) / (2 * np.pi)

    @property
    def loss_factor(self) -> np.ndarray:
        """Modal loss factors :math:`\\mathrm{Im}\\,\\lambda_r / \\mathrm{Re}\\,\\lambda_r` (-)."""
        return self.eigenvalues.imag / self.eigenvalues.real

    def _residual(self, freqs: np.ndarray, anchors: np.ndarray) -> np.ndarray:
        """Quasi-static anchors interpolated to ``freqs`` (PCHIP on real and imaginary parts)."""
        if self.anchor_freqs.size == 1:
            return np.repeat(anchors[:1], freqs.size, axis=0)
        clipped = np.clip(freqs, self.anchor_freqs[0], self.anchor_freqs[-1])
        re = PchipInterpolator(self.anchor_freqs, anchors.real, axis=0)(clipped)
        im = PchipInterpolator(self.anchor_freqs, anchors.imag, axis=0)(clipped)
        return re + 1j * im

    def frf(self, freqs: np.ndarray) -> FRFResult:
        """Local FRFs, :math:`H_{tot}` and :math:`G_H` of the reduced model at ``freqs`` (Hz)."""
        freqs = np.asarray(freqs, float)
        w2 = (2 * np.pi * freqs)[None, :] ** 2
        lam = self.eigenvalues[:, None]
        dyn = 1.0 / (lam - w2) - 1.0 / lam  # (modes, freqs): mode-acceleration form
        coupling = self.point_gain * self.hub_gain[:, None]  # (modes, points)
        points = self._residual(freqs, self.anchor_points).T - coupling.T @ dyn
        if self.point_mass is not None:
            points = points + self.point_mass[:, None] * w2
        hub = self._residual(freqs, self.anchor_hub[:, None])[:, 0] + (self.hub_gain**2) @ dyn
        hub = hub + self.hub_mass * w2[0]
        tasselli = self.membership @ points
        return FRFResult(
            freqs=freqs,
            H=tasselli,
            H_tot=tasselli.sum(axis=0),
            G_H=hub,
            H_points=points,
            method=f"modal ({self.frozen} moduli frozen at {self.reference_frequency:.1f} Hz, "
            f"{self.eigenvalues.size} modes, damping from {', '.join(sorted(set(self.damping_source)))})",
        )


@dataclass(frozen=True, eq=False)
class ModalReduction:
    """Everything the paper's Fig. 4 procedure produces.

    Attributes
    ----------
    identification : ModeIdentification
        Modes identified from the viscoelastic :math:`H_{tot}` (0-250 Hz).
    reference_frequency : float
        Frozen frequency (Hz): the identified mode with the largest static share.
    model : ModalModel
        The reduced model.
    frozen_eigenvalues : ndarray, complex
        Eigenvalues of the frozen model before the identified damping replaced some loss factors.
    wave_number, lateral_order : ndarray of int
        Dominant circumferential wave number and lateral order of each mode.
    frf : FRFResult
        The reduced model's FRFs at the requested frequencies.
    """

    identification: ModeIdentification
    reference_frequency: float
    model: ModalModel
    frozen_eigenvalues: np.ndarray
    wave_number: np.ndarray
    lateral_order: np.ndarray
    frf: FRFResult

    def mode_table(self) -> pd.DataFrame:
        """Modes of the reduced model with the damping each one was given."""
        m = self.model
        return pd.DataFrame(
            {
                "frequency (Hz)": m.freqs,
                "n": self.wave_number,
                "m": self.lateral_order,
                "loss factor, frozen model": self.frozen_eigenvalues.imag / self.frozen_eigenvalues.real,
                "loss factor used": m.loss_factor,
                "damping from": m.damping_source,
                "static share (N/mm)": -np.real(m.hub_gain * m.point_gain.sum(axis=1) / m.eigenvalues) / 1e3,
            },
            index=pd.Index(np.arange(1, m.freqs.size + 1), name="mode"),
        )

    def damping_comparison(self) -> pd.DataFrame:
        """The identified loss factors against the frozen model's own, for the modes seen in H_tot.

        Two independent routes to each mode's damping (paper approximation b): the hysteretic fit
        of the viscoelastic H_tot sees the rubber's loss at the mode's own frequency, the frozen
        model at the freezing frequency. Columns ``frequency (Hz)``, ``eta identified``,
        ``eta frozen model`` and their ``ratio``.
        """
        table = self.mode_table()
        table = table[table["damping from"] == "identified"]
        comparison = pd.DataFrame(
            {
                "frequency (Hz)": table["frequency (Hz)"],
                "eta identified": table["loss factor used"],
                "eta frozen model": table["loss factor, frozen model"],
            }
        )
        comparison["ratio"] = comparison["eta identified"] / comparison["eta frozen model"]
        return comparison


def apply_identified_damping(
    eigenvalues: np.ndarray, hub_gain: np.ndarray, ident: ModeIdentification, frozen: str, f_band: float
) -> tuple[np.ndarray, np.ndarray]:
    """Give the identified loss factors to the modes seen in H_tot: the visible modes (hub gain above 1e-3
    of the largest, up to 1.1 times the band), matched to the identified ones in order of frequency
    with the least total distance in frequency (:func:`matched_in_order`). Not simply the next in
    order: a visible mode that H_tot's fit does not resolve (a weak structural mode below the air
    cavity's resonance) must not take the loss factor of the one it does."""
    freqs = np.sqrt(eigenvalues.real) / (2 * np.pi)
    eta = eigenvalues.imag / eigenvalues.real
    source = np.full(eigenvalues.size, "frozen model", dtype=object)
    if frozen == "storage":
        eta = np.interp(freqs, ident.freqs, ident.loss_factor)  # the paper: no loss in FET70Hz
        source[:] = "interpolated"
    visible = np.nonzero((np.abs(hub_gain) > 1e-3 * np.abs(hub_gain).max()) & (freqs <= 1.1 * f_band))[0]
    for k, j in matched_in_order(ident.freqs, freqs[visible]):
        eta[visible[j]] = ident.loss_factor[k]
        source[visible[j]] = "identified"
    return eigenvalues.real * (1 + 1j * eta), source


def matched_in_order(identified: np.ndarray, visible: np.ndarray) -> list[tuple[int, int]]:
    """Pairs ``(k, j)``, as many as the shorter list has: identified frequency ``k`` (Hz, ascending) matched
    to a distinct visible one ``j`` (ascending), the order kept and the sum of :math:`|f_k - f_j|`
    least (dynamic programming over the two sorted lists; the longer list's extra entries left out)."""
    if identified.size > visible.size:
        return [(k, j) for j, k in matched_in_order(visible, identified)]
    n_i, n_v = identified.size, visible.size
    cost = np.full((n_i + 1, n_v + 1), np.inf)
    cost[0, :] = 0.0
    for k in range(1, n_i + 1):
        for j in range(k, n_v + 1):  # the k-th identified to the j-th visible, or the j-th left out
            cost[k, j] = min(cost[k, j - 1], cost[k - 1, j - 1] + abs(identified[k - 1] - visible[j - 1]))
    pairs, k, j = [], n_i, n_v
    while k > 0:
        if j > k and cost[k, j] == cost[k, j - 1]:
            j -= 1
        else:
            pairs.append((k - 1, j - 1))
            k, j = k - 1, j - 1
    return pairs[::-1]


def modal_damping(
    eigenvalues: np.ndarray,
    hub_gain: np.ndarray,
    ident: ModeIdentification | None,
    frozen: str,
    damping: str,
    f_band: float,
) -> tuple[np.ndarray, np.ndarray]:
    """The frozen modes' eigenvalues with the damping asked for, and where each mode's came from: the
    identified loss factors (``damping="identified"``: :func:`apply_identified_damping`) or the frozen
    model's own (``"model"``; ``ident`` unused)."""
    if damping == "identified":
        return apply_identified_damping(eigenvalues, hub_gain, ident, frozen, f_band)
    return eigenvalues, np.full(eigenvalues.size, "frozen model", dtype=object)


def check_options(frozen: str, damping: str, f_band: float) -> None:
    """Refuse a freezing, damping or band the reduction does not have (both tire models)."""
    if frozen not in ("complex", "storage"):
        raise ValueError(f"frozen = {frozen!r}: valid values are 'complex' and 'storage'")
    if damping not in ("model", "identified") or (frozen == "storage" and damping == "model"):
        raise ValueError(
            f"damping = {damping!r} with frozen = {frozen!r}: valid are 'model' or 'identified' with "
            "frozen='complex', and 'identified' with frozen='storage' (the storage model has no loss)"
        )
    if not (np.isfinite(f_band) and f_band > 0):
        raise ValueError(f"f_band = {f_band} Hz: valid range is (0, inf)")


#: Quasi-static anchors of the FE tires' residual, as fractions of the band (0 first).
ANCHORS = (0.0, 0.1, 0.25, 0.5, 1.0, 1.6)


def identified_start(
    visco: FRFResult,
    frozen: str,
    damping: str,
    f_band: float,
    anchors: tuple[float, ...] = ANCHORS,
    reference_frequency: float | None = None,
) -> tuple[ModeIdentification, float, np.ndarray]:
    """The procedure's first steps on an FE tire's direct FRFs ``visco`` (the cross-section's and the loaded
    FE tire's): the options checked (:func:`check_options`), the modes identified on :math:`H_{tot}` over
    0-``f_band`` Hz, the frozen frequency (:func:`reference_mode`) and the anchors in Hz.

    Raises
    ------
    TypeError
        ``visco`` is not an :class:`~roadnoise_utils.tire.model.FRFResult`.
    ValueError
        An option the reduction does not have; ``anchors`` not starting at 0 and increasing.
    """
    check_options(frozen, damping, f_band)
    if not isinstance(visco, FRFResult):
        raise TypeError(f"visco must be an FRFResult (a model's fixed_hub_frfs), got {type(visco).__name__}")
    anchor_freqs = np.asarray(anchors, float) * f_band
    if anchor_freqs[0] != 0.0 or np.any(np.diff(anchor_freqs) <= 0):
        raise ValueError("anchors must start at 0 and increase")
    ident = identify_modes(visco.freqs, visco.H_tot, f_max=f_band)
    return ident, reference_mode(ident, reference_frequency), anchor_freqs


def reference_mode(ident: ModeIdentification, reference_frequency: float | None = None) -> float:
    """The frozen frequency (Hz): the given one, or the identified mode with the largest static share."""
    if reference_frequency is None:
        reference_frequency = float(ident.freqs[np.argmax(np.abs(ident.static_share))])
    if not (np.isfinite(reference_frequency) and reference_frequency > 0):
        raise ValueError(f"reference_frequency = {reference_frequency} Hz: valid range is (0, inf)")
    return float(reference_frequency)
