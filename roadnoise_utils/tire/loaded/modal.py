r"""Modal reduction of the loaded FE tire: the paper's Fig. 4 procedure on its own kind of tire.

The paper freezes the moduli at the most relevant vertical mode (~70 Hz, FET70Hz), computes the
eigenmodes of the *loaded* tire and builds every local FRF from them with the damping identified
on :math:`H_{tot}` (section *The FET Model*, Fig. 4-5). The loaded FE tire's contact nodes follow
the road (held along its normal, frictionless) and its rim is held, so its loaded modes are those
of the tire with its Craig-Bampton boundary held: the interior of the reduced model
(:class:`.dynamics.ReducedFootprint`), whose interior coordinates are the held tire's modes at
rest and their corrections.

With the moduli frozen, :math:`K` (reduced, boundary ``b`` first, then interior ``i``) and the
mass :math:`M`, the interior's modes :math:`K_{ii}\phi_r = \lambda_r M_{ii}\phi_r`
(:math:`\phi_r^T M_{ii}\phi_r = 1`) and, per boundary coordinate, the modal couplings
:math:`a_r = K_{bi}\phi_r`, :math:`m_r = M_{bi}\phi_r`, the hub's row of the condensed dynamic
stiffness :math:`S = D_{bb} - D_{bi}D_{ii}^{-1}D_{ib}` is, exactly,

.. math:: -S_{hp}(\omega) = -S_{hp}(0) + \sum_r \alpha_{hr}\alpha_{pr}
          \Big(\frac{1}{\lambda_r-\omega^2}-\frac{1}{\lambda_r}\Big)
          + \omega^2\Big(M_{hp}-\sum_r m_{hr}m_{pr}\Big),
   \qquad \alpha_r = a_r - \lambda_r m_r

(write :math:`a_r-\omega^2 m_r = \alpha_r + (\lambda_r-\omega^2)m_r` in the modal sum of
:math:`D_{ii}^{-1}`): the mode-acceleration form of :class:`~roadnoise_utils.response.modal_reduction.ModalModel`, with the
hub gain :math:`\alpha_{hr}`, the road gains :math:`-\alpha_{pr}`, and a mass term the modes do not
carry (the rim's row: the hub mass; the contact nodes' rows: their mass coupled to the rim's).
The modes above :data:`MODE_FACTOR` times the band respond quasi-statically: their first inertia
term :math:`\alpha_h\alpha_p/\lambda^2` joins the mass term. As in the other models the static
term :math:`-S(0)` is taken with each compound's moduli at its frequency (quasi-static anchors,
interpolated) and the modal sum with the frozen moduli. With the moduli frozen at every
frequency and every mode kept, the model is the reduced tire's direct solve (the test's second method).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg as sla

from ...response.modal_reduction import ANCHORS, ModalModel, ModalReduction, identified_start, modal_damping
from ..cross_section.dynamics import frozen_laws
from ..model import FRFResult
from .cavity import with_air_coordinates
from .dynamics import ReducedFootprint

#: Loaded modes are kept below ``MODE_FACTOR`` times the band (the other models': accurate to twice the band).
MODE_FACTOR = 2.0


@dataclass(frozen=True, eq=False)
class LoadedModes:
    """The frozen reduced tire's modes with its boundary held, and their gains.

    Attributes
    ----------
    eigenvalues : ndarray (j,) complex
        :math:`\\lambda_r` (rad^2/s^2), ascending real part.
    hub_gain : ndarray (j,) complex
        :math:`\\alpha_{hr}` (N per unit modal coordinate).
    road_gain : ndarray (j, P) complex
        :math:`\\alpha_{pr}` per contact node.
    hub_mass : complex
        Mass moving with the rim that no kept mode carries (kg).
    node_mass : ndarray (P,) complex
        Each contact node's mass coupled to the rim's that no kept mode carries (kg).
    harmonic, order : ndarray of int (j,)
        The held tire's mode at rest each loaded mode is mostly made of: its circumferential
        wave number, and the loaded mode's rank among those of that wave number.
    """

    eigenvalues: np.ndarray
    hub_gain: np.ndarray
    road_gain: np.ndarray
    hub_mass: complex
    node_mass: np.ndarray
    harmonic: np.ndarray
    order: np.ndarray


def frozen_stiffness(reduced: ReducedFootprint, laws: dict) -> np.ndarray:
    """The reduced stiffness (no inertia) with each compound's ratio from ``laws`` (frozen: any frequency)."""
    return replace(reduced, laws=laws).stiffness(0.0)


def loaded_modes(reduced: ReducedFootprint, laws: dict, f_keep: float) -> LoadedModes:
    """The interior's modes of the reduced tire with the moduli of ``laws`` (frozen), kept below
    ``f_keep`` (Hz), the others' first inertia term in the mass terms (module notes)."""
    if reduced.mode_harmonic is None:
        raise ValueError("reduced: give a reduction with its modes' wave numbers (stages.reduced_footprint)")
    b = reduced.n_boundary
    k, m = frozen_stiffness(reduced, laws), reduced.mass
    factor = np.linalg.cholesky(0.5 * (m[b:, b:] + m[b:, b:].T))
    half = sla.solve_triangular(factor, k[b:, b:], lower=True)
    standard = sla.solve_triangular(factor, half.T, lower=True).T
    values, vectors = sla.eig(0.5 * (standard + standard.T), check_finite=False)
    shapes = sla.solve_triangular(factor.T, vectors, lower=False)
    shapes = shapes / np.sqrt(np.einsum("ij,ij->j", shapes, m[b:, b:] @ shapes))  # phi^T M phi = 1, unconjugated
    order = np.argsort(values.real)
    values, shapes = values[order], shapes[:, order]
    a, mass_gain = k[:b, b:] @ shapes, m[:b, b:] @ shapes
    alpha = a - values[None, :] * mass_gain
    kept = np.sqrt(np.maximum(values.real, 0.0)) / (2 * np.pi) <= f_keep
    dropped = ~kept
    inertia = (alpha[:, dropped] / values[dropped]) @ (alpha[-1, dropped] / values[dropped])
    residual_mass = m[:b, b - 1] - mass_gain @ mass_gain[-1] + inertia  # every mode's m, the dropped ones' alpha
    harmonic = reduced.mode_harmonic[np.argmax(np.abs(shapes[: reduced.n_modes, kept]), axis=0)]
    rank = np.array([np.count_nonzero(harmonic[:j] == h) for j, h in enumerate(harmonic)], int)
    if reduced.n_air:
        air = air_modes(shapes[:, kept], np.diag(m)[-reduced.n_air :], reduced.n_air)
        harmonic = np.where(air >= 0, air, harmonic)
        rank = np.where(air >= 0, -1, rank)
    return LoadedModes(
        eigenvalues=values[kept],
        hub_gain=alpha[-1, kept],
        road_gain=alpha[:-1, kept].T,
        hub_mass=complex(residual_mass[-1]),
        node_mass=residual_mass[:-1],
        harmonic=harmonic,
        order=rank,
    )


def air_modes(shapes: np.ndarray, air_mass: np.ndarray, n_air: int) -> np.ndarray:
    """The plane-wave order of each mode whose kinetic energy lies mostly in the air's coordinates (the last
    ``n_air`` of ``shapes``, whose masses are ``air_mass``), -1 for the others. The air's coordinates are
    its resonant modes in ascending order, a doublet per order (:func:`.cavity.with_air_coordinates`)."""
    weights = np.abs(shapes) ** 2
    air = weights[-n_air:] * air_mass[:, None]
    share = air.sum(axis=0) / (air.sum(axis=0) + weights[:-n_air].sum(axis=0))  # the tire's coordinates: M ~ I
    order = np.argmax(air, axis=0) // 2 + 1
    return np.where(share > 0.5, order, -1)


def quasi_static_anchors(reduced: ReducedFootprint, anchor_freqs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The hub's row of the condensed stiffness without inertia, each compound at its modulus at each
    anchor frequency (Hz): the contact nodes' transfers (n_anchor, P) and :math:`G_H` (n_anchor,)."""
    rows = []
    for f in anchor_freqs:
        d = reduced.stiffness(2 * np.pi * f)  # no inertia
        b = reduced.n_boundary
        interior = np.linalg.solve(d[b:, b:], d[b:, b - 1])
        rows.append(-(d[b - 1, :b] - interior @ d[b:, :b]))
    rows = np.array(rows)
    return rows[:, :-1], rows[:, -1]


def modal_model(
    reduced: ReducedFootprint,
    membership: np.ndarray,
    reference_frequency: float,
    frozen: str,
    f_keep: float,
    anchor_freqs: np.ndarray,
    identification=None,
    f_band: float = 250.0,
) -> tuple[ModalModel, LoadedModes]:
    """The reduced tire's :class:`~roadnoise_utils.response.modal_reduction.ModalModel`: modes frozen at
    ``reference_frequency`` (Hz; ``frozen`` complex moduli or their storage part), kept below
    ``f_keep`` (Hz), the identified damping where ``identification`` is given (else the frozen
    model's own), and quasi-static anchors."""
    laws = frozen_laws(reduced.laws, 2 * np.pi * reference_frequency, storage_only=frozen == "storage")
    modes = loaded_modes(reduced, laws, f_keep)
    damping = "model" if identification is None else "identified"
    eigenvalues, source = modal_damping(modes.eigenvalues, modes.hub_gain, identification, frozen, damping, f_band)
    anchor_points, anchor_hub = quasi_static_anchors(reduced, anchor_freqs)
    model = ModalModel(
        reference_frequency=float(reference_frequency),
        frozen=frozen,
        eigenvalues=eigenvalues,
        damping_source=source,
        hub_gain=modes.hub_gain,
        point_gain=-modes.road_gain,
        anchor_freqs=np.asarray(anchor_freqs, float),
        anchor_points=anchor_points,
        anchor_hub=anchor_hub,
        membership=membership,
        hub_mass=modes.hub_mass,
        point_mass=modes.node_mass,
    )
    return model, modes


def loaded_modal_reduction(
    reduced: ReducedFootprint,
    membership: np.ndarray,
    visco: FRFResult,
    reference_frequency: float | None = None,
    frozen: str = "complex",
    damping: str = "identified",
    f_band: float = 250.0,
    anchors: tuple[float, ...] = ANCHORS,
) -> ModalReduction:
    """The paper's Fig. 4 procedure on the loaded FE tire (see the module notes).

    Parameters
    ----------
    reduced : ReducedFootprint
        The loaded tire's reduction with its modes' wave numbers, for at least ``anchors[-1] * f_band`` Hz;
        with its air cavity coupled, the air's modes become coordinates of their own
        (:func:`.cavity.with_air_coordinates`) and the loaded modes are the tire's and the air's
        together (an air mode's ``lateral_order`` is -1, its ``wave_number`` its plane wave's order).
    membership : ndarray (n_tasselli, P)
        Which contact nodes each tassello holds (:meth:`~roadnoise_utils.tire.tasselli.Tasselli.membership`).
    visco : FRFResult
        The direct FRFs over at least 0-``f_band`` Hz (the identification's and the returned FRFs' frequencies).
    reference_frequency, frozen, damping, f_band, anchors
        As the other models' (:func:`roadnoise_utils.tire.cross_section.modal.section_modal_reduction`).
    """
    ident, reference_frequency, anchor_freqs = identified_start(
        visco, frozen, damping, f_band, anchors, reference_frequency
    )
    if reduced.cavity is not None:  # the air's modes join the loaded modes (lossless with the storage moduli)
        reduced, _ = with_air_coordinates(reduced, lossless=frozen == "storage")
    model, modes = modal_model(
        reduced,
        membership,
        reference_frequency,
        frozen,
        MODE_FACTOR * f_band,
        anchor_freqs,
        identification=ident if damping == "identified" else None,
        f_band=f_band,
    )
    return ModalReduction(
        identification=ident,
        reference_frequency=float(reference_frequency),
        model=model,
        frozen_eigenvalues=modes.eigenvalues,
        wave_number=modes.harmonic,
        lateral_order=modes.order,
        frf=model.frf(visco.freqs),
    )


def harmonic_of_modes(theta: np.ndarray, vectors: np.ndarray, top: int = 10) -> np.ndarray:
    r"""The circumferential wave number carrying most of each mode's displacement.

    ``theta`` (n_rings,): the rings' angles as the solid mesh lays them, an arc's end ring then its
    middle ring round the wheel (:class:`~roadnoise_utils.tire.loaded.mesh.SolidMesh`); ``vectors``
    (n_dof, k): displacements ordered ring by ring, node by node, ``x, y, z``. Each field (a node's
    radial, circumferential or lateral displacement: a harmonic of those is one of the tire, whereas
    the Cartesian ones mix ``n`` with ``n +- 1``) is projected on :math:`\cos n\theta` and
    :math:`\sin n\theta` by Simpson's rule on each quadratic arc (the elements' own interpolation
    round the wheel, which a least-squares fit on the rings of a graded mesh, a few rings per long
    arc, would alias); the wave number of the largest :math:`L^2` share, ``0..top``.
    """
    n_rings = theta.size
    if n_rings % 2:
        raise ValueError(f"theta: give the rings of whole quadratic arcs (an even count), got {n_rings}")
    ends = theta[0::2]
    lengths = np.diff(np.append(ends, ends[0] + 2.0 * np.pi))
    weights = np.zeros(n_rings)
    np.add.at(weights, np.arange(0, n_rings, 2), lengths / 6.0)
    np.add.at(weights, (np.arange(0, n_rings, 2) + 2) % n_rings, lengths / 6.0)
    weights[1::2] += 4.0 * lengths / 6.0
    u = vectors.T.reshape(vectors.shape[1], n_rings, -1, 3)  # (mode, ring, node, xyz)
    s, c = np.sin(theta)[:, None], np.cos(theta)[:, None]
    cylindrical = np.stack([u[..., 0] * s - u[..., 2] * c, u[..., 0] * c + u[..., 2] * s, u[..., 1]], -1)
    fields = cylindrical.reshape(vectors.shape[1], n_rings, -1)  # (mode, ring, field)
    n = np.arange(top + 1)
    cos = np.cos(np.outer(n, theta)) * weights  # (n, ring)
    sin = np.sin(np.outer(n, theta)) * weights
    energy = (
        np.abs(np.einsum("nr,mrf->nmf", cos, fields)) ** 2 + np.abs(np.einsum("nr,mrf->nmf", sin, fields)) ** 2
    ).sum(-1)
    energy /= np.where(n == 0, 2.0 * np.pi, np.pi)[:, None]  # the L2 norms of cos n theta, sin n theta
    return np.argmax(energy, axis=0)
