"""Modal reduction of the cross-section tire: the paper's Fig. 4 procedure on the harmonic model.

The paper freezes the moduli at the most relevant vertical mode (~70 Hz, FET70Hz), computes
the eigenmodes of the *loaded* tire and builds every local FRF from them with the damping
identified on :math:`H_{tot}` (section *The FET Model*, Fig. 4-5). The loaded cross-section
tire's contact points follow the road (bilateral, frictionless), so its eigenmodes are those
of the tire with the rim fixed and the contact points held vertically. The harmonics are not
coupled by the tire but by the held points, so the loaded modes come from a component-mode
synthesis (MacNeal 1971; Craig & Kurdila, *Fundamentals of Structural Dynamics*, ch. 19):

1. **Free modes** (rim fixed, tread free) of every dynamic harmonic at the frozen moduli, below
   ``f_free``, from the harmonic's Ritz reduction (:mod:`roadnoise_utils.tire.cross_section.dynamics`): eigenvalues
   :math:`\\Lambda`, vertical shapes at the contact points :math:`\\Psi` (mirror-even set),
   vertical momentum :math:`L` (``n = 1`` only).
2. **Residual flexibility** of everything else (the free modes above ``f_free`` and every
   quasi-static harmonic): :math:`R = S(0) - \\Psi\\Lambda^{-1}\\Psi^T`, with :math:`S(0)` the
   frozen static receptance of the even coordinates (:class:`roadnoise_utils.tire.cross_section.footprint.EvenFootprint`).
3. **Held points.** Point forces ``Q`` hold the points at the road ``d``:
   :math:`\\Psi q + R Q = d`, :math:`(\\Lambda - \\omega^2) q = \\Psi^T Q`, so

   .. math:: (K_L - \\omega^2)\\,q = \\Psi^T R^{-1} d, \\qquad K_L = \\Lambda + \\Psi^T R^{-1} \\Psi,

   whose eigenpairs :math:`(\\mu_j, V_j)` are the loaded modes.
4. **Hub force** from the tire's vertical momentum balance (rim fixed):
   :math:`F_H = \\mathbf{1}^T Q + \\omega^2 L^T q`. Each loaded mode has the hub gain
   :math:`a_j = V_j^T(\\mu_j L - \\Psi^T R^{-1}\\mathbf 1)` and the road gain
   :math:`b_j = V_j^T \\Psi^T R^{-1}`; with the points held and the rim moving, the same
   :math:`a_j` drive the modes, and the mass the modes do not carry (the beads, the residual)
   moves with the rim: :math:`m_{res} = m - L^T L`.

The result is the ring model's :class:`.modal_reduction.ModalModel` (mode-acceleration form,
quasi-static anchors with the moduli at each frequency), so both tire models give the same
:class:`.modal_reduction.ModalReduction`. :func:`frozen_check` also solves the frozen model
directly (the footprint solve with frozen laws): the check of steps 1-4.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from ...response.modal_reduction import (
    ANCHORS,
    ModalModel,
    ModalReduction,
    check_options,
    identified_start,
    modal_damping,
)
from ..model import FRFResult
from .dynamics import frozen_laws, parity_bases, tire_mass
from .footprint import EvenFootprint, FootprintFRF, FootprintReductions
from .static import SectionStaticState, SectionTire

#: Free modes are kept up to ``FREE_FACTOR`` times the highest loaded mode the model must carry.
FREE_FACTOR = 2.5


@dataclass(frozen=True, eq=False)
class FreeModes:
    """Free modes (rim fixed, tread free) of the dynamic harmonics at frozen moduli.

    Attributes
    ----------
    eigenvalues : ndarray (m,) complex
        rad^2/s^2.
    shapes : ndarray (R, m) complex
        Vertical displacement of each even coordinate (mirror pair) per unit modal coordinate,
        patch factor included (m).
    momentum : ndarray (m,) complex
        Vertical momentum per unit modal coordinate (kg); zero unless ``n = 1``.
    harmonic, order : ndarray of int (m,)
        Circumferential harmonic ``n`` and rank within it (1 = lowest).
    parity : ndarray of int (m,)
        Left-right symmetric (+1) or antisymmetric (-1) mode; 0 where the harmonic is not symmetric.
    """

    eigenvalues: np.ndarray
    shapes: np.ndarray
    momentum: np.ndarray
    harmonic: np.ndarray
    order: np.ndarray
    parity: np.ndarray


def free_modes(even: EvenFootprint, laws: dict, f_free: float) -> FreeModes:
    """Free modes of every dynamic harmonic of ``even`` below ``f_free`` (Hz), moduli from ``laws`` (frozen)."""
    grid, static = even.tire.grid, even.static
    col, row = static.points
    col, theta = col[even.keep], grid.theta[row[even.keep]]
    c = grid.n_cols
    lam_cut = (2 * np.pi * f_free) ** 2
    parts = []
    for red in even.harmonics[: even.n_dynamic + 1]:
        n, proj = red.n, red.projected
        k = proj.dynamic_stiffness(laws, np.zeros(1), inertia=False)[0]
        vals, vecs, parity = _modes_by_parity(k, proj.mass, red.mirror)
        order = np.argsort(vals.real)
        vals, vecs, parity = vals[order], vecs[:, order], parity[order]
        keep = vals.real < lam_cut
        vals, vecs, parity = vals[keep], vecs[:, keep], parity[keep]
        vecs = vecs / np.sqrt(np.einsum("kr,kr->r", vecs, proj.mass @ vecs))  # X^T M X = I (unconjugated)
        at = proj.contact.T @ vecs  # (2c, m): r then theta DOF of the columns
        patch = np.sinc(n * grid.dtheta / (2 * np.pi))
        shapes = patch * (
            -(np.cos(theta) * np.cos(n * theta))[:, None] * at[col]
            + (np.sin(theta) * np.sin(n * theta))[:, None] * at[c + col]
        )
        parts.append((vals, shapes, proj.momentum @ vecs, np.full(vals.size, n), np.arange(1, vals.size + 1), parity))
    return FreeModes(*(np.concatenate(p, axis=-1) for p in zip(*parts)))


def _modes_by_parity(
    stiffness: np.ndarray, mass: np.ndarray, mirror: np.ndarray | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Eigenpairs of ``(stiffness, mass)`` and each one's left-right parity (+1, -1; 0 without a mirror).

    With the harmonic's mirror (:class:`roadnoise_utils.tire.cross_section.dynamics.ReducedHarmonic`) the pencil has
    no coupling between its symmetric and antisymmetric coordinates: each half is solved alone
    (a quarter of the work).
    """
    if mirror is None:
        vals, vecs = _eig_mass(stiffness, mass)
        return vals, vecs, np.zeros(vals.size, int)
    out = []
    for parity, part in parity_bases(mirror):
        vals, vecs = _eig_mass(part.T @ stiffness @ part, part.T @ mass @ part)
        out.append((vals, part @ vecs, np.full(vals.size, parity)))
    return tuple(np.concatenate(p, axis=-1) for p in zip(*out))


def _eig_mass(stiffness: np.ndarray, mass: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Eigenpairs of ``stiffness x = lambda mass x`` for a symmetric positive definite ``mass``.

    As a standard problem through the Cholesky factor ``mass = L L^T`` (the QR algorithm on
    ``L^-1 K L^-T``, about three times faster than the QZ of the pencil).
    """
    factor = np.linalg.cholesky(0.5 * (mass + mass.T))
    half = sla.solve_triangular(factor, stiffness, lower=True)  # L^-1 K
    standard = sla.solve_triangular(factor, half.T, lower=True).T  # L^-1 K L^-T
    vals, vecs = sla.eig(standard, check_finite=False)
    return vals, sla.solve_triangular(factor.T, vecs, lower=False)  # x = L^-T y


@dataclass(frozen=True, eq=False)
class SectionLoadedModes:
    """Loaded modes (rim fixed, contact points held) of the frozen model and their gains.

    Attributes
    ----------
    eigenvalues : ndarray (j,) complex
        :math:`\\mu_j` (rad^2/s^2), ascending real part.
    hub_gain : ndarray (j,) complex
        :math:`a_j` (N per unit modal coordinate).
    road_gain : ndarray (j, R) complex
        :math:`b_j` (modal force per unit displacement of each even coordinate).
    residual_mass : complex
        Mass moving with the rim, not carried by the free modes (kg).
    harmonic, order : ndarray of int (j,)
        The free mode each loaded mode is mostly made of (harmonic, rank in it).
    """

    eigenvalues: np.ndarray
    hub_gain: np.ndarray
    road_gain: np.ndarray
    residual_mass: complex
    harmonic: np.ndarray
    order: np.ndarray


def section_loaded_modes(even: EvenFootprint, laws: dict, f_free: float) -> SectionLoadedModes:
    """Steps 1-4 of the module notes for the frozen ``laws``, free modes below ``f_free`` (Hz)."""
    free = free_modes(even, laws, f_free)
    weight = even.pair_weight
    _, static_comp = next(even.receptances(np.zeros(1), laws, inertia=False))
    static = static_comp[0] / weight[None, :]  # S = comp W^-1
    residual = static - (free.shapes / free.eigenvalues) @ free.shapes.T
    residual = 0.5 * (residual + residual.T)
    r_inv_psi = sla.solve(residual, free.shapes, assume_a="sym")
    r_inv_one = sla.solve(residual, np.ones(weight.size), assume_a="sym")
    k_loaded = np.diag(free.eigenvalues) + free.shapes.T @ r_inv_psi
    mu, vecs = _eig_by_parity(k_loaded, free.parity)
    order = np.argsort(mu.real)
    mu, vecs = mu[order], vecs[:, order]
    vecs = vecs / np.sqrt(np.einsum("mj,mj->j", vecs, vecs))  # V^T V = I (unconjugated)
    hub_gain = np.einsum("mj,mj->j", vecs, mu[None, :] * free.momentum[:, None] - (free.shapes.T @ r_inv_one)[:, None])
    # A residual flexibility not quite positive definite (the sampled quasi-static harmonics) gives
    # a few spurious modes with Re mu < 0, beyond f_free and with tiny gains: they respond
    # quasi-statically (the anchors carry them) and their first inertia term, a_j^2 / mu_j^2,
    # moves with the rim.
    keep = mu.real > 0
    dropped_mass = np.sum(hub_gain[~keep] ** 2 / mu[~keep] ** 2)
    vecs, mu, hub_gain = vecs[:, keep], mu[keep], hub_gain[keep]
    dominant = np.argmax(np.abs(vecs), axis=0)
    return SectionLoadedModes(
        eigenvalues=mu,
        hub_gain=hub_gain,
        road_gain=vecs.T @ r_inv_psi.T,
        residual_mass=complex(tire_mass(even.tire.ops) - free.momentum @ free.momentum + dropped_mass),
        harmonic=free.harmonic[dominant],
        order=free.order[dominant],
    )


def _eig_by_parity(k_loaded: np.ndarray, parity: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Eigenpairs of the loaded-mode matrix, its symmetric and antisymmetric free modes apart.

    The held points and the residual flexibility are left-right symmetric, so the matrix does
    not couple free modes of opposite parity (checked: below 1e-9 of its largest entry); each
    block is solved alone, a quarter of the work. Free modes of unknown parity: one solve.
    """
    blocks = [np.nonzero(parity == p)[0] for p in (1, -1)]
    scale = np.abs(k_loaded).max()
    coupled = blocks[0].size and blocks[1].size and np.abs(k_loaded[np.ix_(*blocks)]).max() > 1e-9 * scale
    if np.any(parity == 0) or coupled:
        return sla.eig(k_loaded)
    mu = np.zeros(parity.size, complex)
    vecs = np.zeros((parity.size, parity.size), complex)
    start = 0
    for block in blocks:
        values, vectors = sla.eig(k_loaded[np.ix_(block, block)])
        mu[start : start + block.size] = values
        vecs[block, start : start + block.size] = vectors
        start += block.size
    return mu, vecs


def reduction_band(f_band: float, anchors: tuple[float, ...] = ANCHORS) -> tuple[float, float]:
    """``(f_top, f_free)`` (Hz) of the reduced harmonics for a band: up to the last anchor, modes to
    ``FREE_FACTOR * 2 f_band`` (:func:`roadnoise_utils.tire.cross_section.reductions.footprint_reductions` of the tire)."""
    return float(anchors[-1]) * f_band, FREE_FACTOR * 2 * f_band


def _synthesis(tire, static, reference_frequency: float, frozen: str, f_band: float, f_top: float, reductions=None):
    """The reduced harmonics for 0-``f_top`` Hz (``reductions`` if given), the laws frozen at
    ``reference_frequency`` and the loaded modes they give (free modes to ``FREE_FACTOR * 2 f_band``):
    ``(even, laws, modes)``."""
    f_free = FREE_FACTOR * 2 * f_band
    even = EvenFootprint.build(tire, static, f_top, f_free, reductions)
    laws = frozen_laws(tire.ops.laws, 2 * np.pi * reference_frequency, storage_only=frozen == "storage")
    return even, laws, section_loaded_modes(even, laws, f_free)


def _model_of(
    modes: SectionLoadedModes,
    even: EvenFootprint,
    anchors: FootprintFRF,
    eigenvalues: np.ndarray,
    source,
    f_ref,
    frozen,
) -> ModalModel:
    """The ring model's ModalModel from the loaded modes (gains per contact point, anchors)."""
    weight = even.pair_weight[even.representative]
    road = modes.road_gain[:, even.representative] / weight[None, :]  # per single point (mirror not moved)
    return ModalModel(
        reference_frequency=float(f_ref),
        frozen=frozen,
        eigenvalues=eigenvalues,
        damping_source=source,
        hub_gain=modes.hub_gain,
        point_gain=-road,
        anchor_freqs=anchors.freqs,
        anchor_points=anchors.hub,
        anchor_hub=anchors.G_H,
        membership=even.static.tasselli.membership(),
        hub_mass=modes.residual_mass,
    )


def section_modal_reduction(
    tire: SectionTire,
    static: SectionStaticState,
    visco: FRFResult,
    freqs: np.ndarray | None = None,
    reference_frequency: float | None = None,
    frozen: str = "complex",
    damping: str = "identified",
    f_band: float = 250.0,
    anchors: tuple[float, ...] = ANCHORS,
    reductions: FootprintReductions | None = None,
) -> ModalReduction:
    """The paper's Fig. 4 procedure on the cross-section tire (see the module notes).

    Parameters
    ----------
    tire, static : SectionTire, SectionStaticState
    visco : FRFResult
        Direct FRFs of the viscoelastic model over at least 0-``f_band`` Hz
        (:meth:`roadnoise_utils.tire.cross_section.footprint.FootprintFRF.to_frf_result`).
    freqs : ndarray, optional
        Frequencies of the returned FRFs (Hz); default those of ``visco``.
    reference_frequency : float, optional
        Frozen frequency (Hz); default the identified mode with the largest static share of
        :math:`H_{tot}(0)`.
    frozen, damping : str
        As :func:`roadnoise_utils.tire.ring.modal_reduction.modal_reduction`.
    f_band : float
        Band of the identification (Hz); loaded modes are accurate to ``2 f_band`` (free modes
        kept to ``FREE_FACTOR * 2 f_band``, every loaded mode they give kept).
    anchors : tuple of float
        Quasi-static anchor frequencies as fractions of ``f_band``, 0 first.
    reductions : FootprintReductions, optional
        The tire's :func:`roadnoise_utils.tire.cross_section.reductions.footprint_reductions` for :func:`reduction_band`
        of this band and anchors, if computed before (they do not depend on the loaded state).
    """
    ident, reference_frequency, anchor_freqs = identified_start(
        visco, frozen, damping, f_band, anchors, reference_frequency
    )
    even, laws, modes = _synthesis(
        tire, static, reference_frequency, frozen, f_band, float(anchor_freqs[-1]), reductions
    )
    eigenvalues, source = modal_damping(modes.eigenvalues, modes.hub_gain, ident, frozen, damping, f_band)
    model = _model_of(
        modes, even, even.footprint(anchor_freqs, inertia=False), eigenvalues, source, reference_frequency, frozen
    )
    return ModalReduction(
        identification=ident,
        reference_frequency=float(reference_frequency),
        model=model,
        frozen_eigenvalues=modes.eigenvalues,
        wave_number=modes.harmonic,
        lateral_order=modes.order,
        frf=model.frf(visco.freqs if freqs is None else np.asarray(freqs, float)),
    )


@dataclass(frozen=True, eq=False)
class FrozenCheck:
    """The frozen model two ways: by the synthesis and solved directly (:func:`frozen_check`).

    Attributes
    ----------
    synthesis : FRFResult
        The loaded-mode synthesis (one frozen static anchor, every loss the model's own).
    direct : FootprintFRF
        The footprint solve with every compound law frozen.
    eigenvalues : ndarray, complex
        The loaded modes of the synthesis (rad^2/s^2).
    """

    synthesis: FRFResult
    direct: FootprintFRF
    eigenvalues: np.ndarray


def frozen_check(
    tire: SectionTire,
    static: SectionStaticState,
    freqs: np.ndarray,
    reference_frequency: float,
    storage: bool = False,
    f_band: float = 250.0,
    reductions: FootprintReductions | None = None,
) -> FrozenCheck:
    """The frozen model two ways at ``freqs`` (Hz): by the synthesis and solved directly.

    Every law frozen at ``reference_frequency`` (Hz), every loss the model's own (no
    identification), one static anchor. Both use the same reduced harmonics (those of
    :func:`section_modal_reduction` with this ``f_band``; ``reductions`` if given, see
    :func:`reduction_band`), so they differ only by the inertia of what the residual flexibility
    stands for: the check of the synthesis.
    """
    freqs = np.asarray(freqs, float)
    frozen = "storage" if storage else "complex"
    check_options(frozen, "identified", f_band)
    f_top, _ = reduction_band(f_band)
    even, laws, modes = _synthesis(tire, static, float(reference_frequency), frozen, f_band, f_top, reductions)
    anchor = even.footprint(np.zeros(1), laws=laws, inertia=False)
    source = np.full(modes.eigenvalues.size, "frozen model", dtype=object)
    model = _model_of(modes, even, anchor, modes.eigenvalues, source, reference_frequency, frozen)
    return FrozenCheck(model.frf(freqs), even.footprint(freqs, laws=laws, interpolate=False), modes.eigenvalues)
