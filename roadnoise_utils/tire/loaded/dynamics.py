"""Dynamics of the loaded tire linearised about its static state: the paper's FET in the frequency domain.

About a loaded equilibrium ``u0`` (:func:`.statics.press_on_flat_road`) a small motion
``u e^{i omega t}`` meets the dynamic stiffness

.. math:: D(\\omega) = \\sum_c g_c(\\omega)\\,K_c + g_p(\\omega)\\,K_p - \\omega^2 M,

with ``K_c`` the material tangent :math:`\\int B^T D B\\,dV_0` of the points of compound ``c``
(``B`` at ``u0``), scaled by that compound's modulus ratio ``g_c`` (the frequency-dependent laws
of the tire file, as the waveguide tire scales each compound's layers: the paper's FETvisco),
``K_p`` the stress's geometric stiffness :math:`\\int G^T S G\\,dV_0` with the pressure's load
stiffness, scaled like the waveguide's pneumatic stiffness (by the file's ``[pneumatic]
compound``, or not at all), and ``M`` the consistent mass. At zero frequency, with every ratio 1,
``D`` is the static tangent of :func:`.statics.residual_and_tangent`: the loaded state's.

The footprint's contact nodes follow the road vertically, held there and free along it
(bilateral and frictionless, the contact set frozen: the paper's linearisation and the other
tire models'), and the rim is rigid and held. A vertical road displacement ``d_p`` of contact node
``p`` gives the force on the hub :math:`h_p(\\omega)\\,d_p`; the nodes of a tassello together
give its ``H_i``, all of them ``H_tot``; a unit vertical rim motion with the contact held gives
``G_H`` (``-K_v`` at rest).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ... import guards
from ..banded import BandedCholesky, banded_sum
from . import pressure, solid
from .statics import LoadedTire, StaticState, held_dof


@dataclass(frozen=True, eq=False)
class LinearisedTire:
    """The loaded tire's stiffness about a static state, split by the law that scales each part, and its mass.

    Attributes
    ----------
    compounds : dict of str to csr_matrix
        Material tangent of each compound's integration points (N/m), all DOF.
    pneumatic : csr_matrix
        The stress's geometric stiffness and the pressure's load stiffness (N/m), all DOF.
    mass : csr_matrix
        Consistent mass (kg).
    laws : dict
        Each compound's modulus law (``ratio(omega)``: 1 at rest).
    pneumatic_law : str or None
        The compound whose law scales ``pneumatic``; None: lossless.
    road : ndarray of int
        The vertical DOF of the contact nodes (the road's inputs).
    hub : ndarray of int
        The vertical DOF of the rim's nodes (they move together with the hub).
    free : ndarray of int
        DOF neither on the rim nor held by the road.
    state : StaticState
    """

    compounds: dict
    pneumatic: sp.csr_matrix
    mass: sp.csr_matrix
    laws: dict
    pneumatic_law: str | None
    road: np.ndarray
    hub: np.ndarray
    free: np.ndarray
    state: StaticState

    def stiffness(self, omega: float) -> sp.csr_matrix:
        """:math:`\\sum_c g_c K_c + g_p K_p` at ``omega`` (rad/s), complex (N/m)."""
        weights = _weights(self.laws, self.pneumatic_law, list(self.compounds), omega)[:-1]
        return sum(w * part for w, part in zip(weights, [self.pneumatic, *self.compounds.values()])).tocsr()


def tangent_parts(tire: LoadedTire, u: np.ndarray, p: float) -> tuple[dict, sp.csr_matrix]:
    """Material tangent per compound and the pneumatic part (geometric and pressure) at ``u``, pressure ``p``.

    Their sum is :func:`.statics.residual_and_tangent`'s tangent.
    """
    names = tire.mesh.section.points.compounds
    material: dict[str, list] = {name: [] for name in names}
    geometric = []
    for group in tire.groups:
        f = solid.deformation_gradient(group, u)
        stress, d = solid.stress_and_tangent(solid.green_strain(f), group.materials)
        b = solid.strain_operator(f, group.grad)
        geometric.append(solid.element_tangent(group, b, np.zeros_like(d), stress))
        for index, name in enumerate(names):
            own = group.compound == index
            material[name].append(
                solid.element_tangent(group, b, d * own[None, :, None, None], np.zeros_like(stress))
                if own.any()
                else np.zeros((group.elements.size, 81, 81))
            )
    compounds = {name: solid.assemble_blocks(tire.groups, blocks, tire.n_dof) for name, blocks in material.items()}
    pneumatic = solid.assemble_blocks(tire.groups, geometric, tire.n_dof) - pressure.pressure_stiffness(
        tire.mesh, tire.surface, u, p
    )
    return compounds, pneumatic.tocsr()


def linearise(tire: LoadedTire, state: StaticState) -> LinearisedTire:
    """The loaded tire about ``state``, contact set frozen: its stiffness parts, mass and DOF sets."""
    if state.contact.size == 0:
        raise ValueError("state: the tire touches no road (give a loaded state: statics.press_on_flat_road)")
    compounds, pneumatic = tangent_parts(tire, state.u, state.pressure)
    spec = tire.spec
    mass = solid.mass_matrix(solid.element_groups(tire.mesh, spec, arc_points=3), tire.n_dof)
    rim_nodes = np.unique(tire.fixed // 3)
    return LinearisedTire(
        compounds=compounds,
        pneumatic=pneumatic,
        mass=mass,
        laws=spec.laws(),
        pneumatic_law=spec.pneumatic,
        road=3 * np.asarray(state.contact, int) + 2,
        hub=3 * rim_nodes + 2,
        free=np.setdiff1d(np.arange(tire.n_dof), held_dof(tire, state.contact)),
        state=state,
    )


@dataclass(frozen=True, eq=False)
class LoadedFootprintFRF:
    """Hub-force transfer of the loaded FE tire's contact nodes.

    Attributes
    ----------
    freqs : ndarray (n_f,)
        Hz.
    hub : ndarray (n_f, P) complex
        Force on the hub (N/m, upward) per unit upward road displacement at each contact node, in the
        order of ``state.contact``.
    G_H : ndarray (n_f,) complex
        Force on the hub per unit upward hub displacement, the contact held (N/m): ``-K_v`` at rest.
    """

    freqs: np.ndarray
    hub: np.ndarray
    G_H: np.ndarray

    @property
    def H_tot(self) -> np.ndarray:
        """Force on the hub per unit displacement of the whole footprint (N/m), (n_f,)."""
        return self.hub.sum(axis=1)


def footprint_frf_direct(linearised: LinearisedTire, freqs: np.ndarray) -> LoadedFootprintFRF:
    r"""The footprint's hub-force transfer by a direct solve of :math:`D(\omega)` at every frequency.

    The reference of the reduced solve: every DOF, no basis. Per frequency, the free DOF follow
    unit motions of each contact node and of the rim,
    :math:`u_f = -D_{ff}^{-1} D_{f,b}`, and the force on the hub is minus the rim's vertical
    reactions, :math:`-\sum_{hub}(D_{h,f} u_f + D_{h,b})`. :math:`D_{ff}` is factorised as a band
    (:func:`~roadnoise_utils.tire.banded.banded_sum`: the closed ring's band after reverse
    Cuthill-McKee), SuperLU where no narrow band exists.
    """
    freqs = _check_freqs(freqs)
    lin = linearised
    boundary = _boundary_columns(lin)
    parts = [lin.pneumatic, *lin.compounds.values(), lin.mass]
    free_parts = [part[lin.free][:, lin.free] for part in parts]
    coupling = [(part[lin.free] @ boundary).toarray() for part in parts]
    hub_rows = [(part[lin.hub] @ boundary).toarray().sum(axis=0) for part in parts]
    hub_free = [np.asarray(part[lin.hub][:, lin.free].sum(axis=0)).ravel() for part in parts]
    banded = banded_sum(free_parts)
    out = []
    for frequency in freqs:
        w = _weights(lin.laws, lin.pneumatic_law, list(lin.compounds), 2 * np.pi * frequency)
        rhs = -sum(wj * c for wj, c in zip(w, coupling))
        if banded is not None:
            u_free = banded.lu(w).solve(rhs)
        else:
            u_free = spla.splu(sum(wj * m for wj, m in zip(w, free_parts)).tocsc()).solve(rhs)
        rim = sum(wj * r for wj, r in zip(w, hub_rows)) + sum(wj * h for wj, h in zip(w, hub_free)) @ u_free
        out.append(-rim)
    hub = np.array(out)
    return LoadedFootprintFRF(freqs=freqs, hub=hub[:, :-1], G_H=hub[:, -1])


def _weights(laws: dict, pneumatic_law: str | None, compounds: list, omega: float) -> np.ndarray:
    """The parts' weights at ``omega``: the pneumatic part's ratio, each compound's, then ``-omega^2`` (mass)."""
    return np.array(
        [_ratio(laws, pneumatic_law, omega), *(_ratio(laws, name, omega) for name in compounds), -(omega**2)], complex
    )


def _check_freqs(freqs: np.ndarray) -> np.ndarray:
    """Refuse frequencies that are not finite, strictly ascending and >= 0; warn above 2 kHz."""
    try:
        freqs = np.asarray(freqs, float)
    except (TypeError, ValueError) as error:
        raise ValueError(f"freqs must be real numbers (Hz): {error}") from None
    if freqs.ndim != 1 or freqs.size == 0 or not np.all(np.isfinite(freqs)) or freqs.min() < 0:
        raise ValueError("freqs must be a non-empty 1-D array of finite frequencies >= 0 Hz")
    if np.any(np.diff(freqs) <= 0):
        raise ValueError("freqs must be strictly increasing")
    if freqs.max() > 2000.0:
        guards.warn(f"freqs reach {freqs.max():g} Hz: the loaded tire's laws are those of a 0-400 Hz model")
    return freqs


#: The reduced solve keeps the held tire's modes below ``CUTOFF_FACTOR`` times the highest frequency.
CUTOFF_FACTOR = 2.5


@dataclass(frozen=True, eq=False)
class ReducedFootprint:
    """The linearised tire on a Craig-Bampton basis: its boundary (each contact node's vertical DOF,
    then the rim moving vertically as one) and interior coordinates.

    Attributes
    ----------
    compounds : dict of str to ndarray (r, r)
        Each compound's projected material tangent.
    pneumatic, mass : ndarray (r, r)
    n_boundary : int
        The first ``n_boundary`` coordinates are the boundary's motions (the contact nodes', the hub's).
    n_modes : int
        The held tire's modes at rest among the interior coordinates (the first ``n_modes`` of them).
    laws, pneumatic_law
        As :class:`LinearisedTire`.
    """

    compounds: dict
    pneumatic: np.ndarray
    mass: np.ndarray
    n_boundary: int
    n_modes: int
    laws: dict
    pneumatic_law: str | None

    def boundary_stiffness(self, omega: float) -> np.ndarray:
        """The boundary's condensed dynamic stiffness at ``omega`` (rad/s), (n_boundary, n_boundary) complex."""
        weights = _weights(self.laws, self.pneumatic_law, list(self.compounds), omega)
        d = sum(w * part for w, part in zip(weights, [self.pneumatic, *self.compounds.values(), self.mass]))
        b = self.n_boundary
        return d[:b, :b] - d[:b, b:] @ np.linalg.solve(d[b:, b:], d[b:, :b])


def _ratio(laws: dict, name: str | None, omega: float) -> complex:
    return 1.0 if name is None else complex(laws[name].ratio(np.array([omega]))[0])


def reduce(linearised: LinearisedTire, f_max: float, cutoff_factor: float = CUTOFF_FACTOR) -> ReducedFootprint:
    r"""Project the linearised tire on the boundary's static shapes, the held tire's modes and two corrections.

    The basis (Craig & Bampton, AIAA J. 6, 1968, enriched for moduli that change with frequency):
    for each boundary motion its static shape :math:`\Psi` (the free DOF in equilibrium at rest,
    every ratio 1); the boundary-held tire's modes below ``cutoff_factor * f_max``, at rest and
    again with the storage moduli at ``f_max`` (the laws stiffen the compounds unequally, by up to
    ~40 % over the band, which moves the modes' shapes as well as their frequencies); the change of
    the static shapes between the two; and the inertia load of the static shapes,
    :math:`-K_{ff}^{-1} M [\Psi; I]` (the first load-dependent Ritz block: Wilson, Yuan & Dickens,
    Earthq. Eng. Struct. Dyn. 10, 1982), which the modes above the cut-off would carry. The interior
    coordinates are mass-orthonormalised. Measured on the test tire (6 arcs, 5 mm): within 4.3e-4 of
    the direct solve at 0-400 Hz; the modes at rest alone, 5.5e-3; lossless laws, 5e-10.
    """
    lin = linearised
    f_max = guards.real("f_max", f_max, lo=0.0, lo_open=True, unit="Hz")
    cutoff_factor = guards.real("cutoff_factor", cutoff_factor, lo=1.0, unit="")
    rest = lin.stiffness(0.0).real.tocsr()
    boundary = _boundary_columns(lin)
    mass_ff = lin.mass[lin.free][:, lin.free].tocsc()
    factor = _factor(rest[lin.free][:, lin.free])
    shapes = boundary.toarray()
    shapes[lin.free] = -factor.solve((rest[lin.free] @ boundary).toarray())
    omega_cut = 2 * np.pi * cutoff_factor * f_max
    modes = _modes_below(rest[lin.free][:, lin.free], mass_ff, factor, omega_cut)
    stiff = lin.stiffness(2 * np.pi * f_max).real.tocsr()
    stiff_factor = _factor(stiff[lin.free][:, lin.free])
    stiff_modes = _modes_below(stiff[lin.free][:, lin.free], mass_ff, stiff_factor, omega_cut)
    stiff_shapes = -stiff_factor.solve((stiff[lin.free] @ boundary).toarray())
    inertia = -factor.solve(lin.mass[lin.free] @ shapes)
    interior = _mass_orthonormal(
        np.hstack([modes, stiff_modes, stiff_shapes - shapes[lin.free], inertia]), mass_ff, keep=modes.shape[1]
    )
    n_b = boundary.shape[1]
    basis = np.zeros((lin.mass.shape[0], n_b + interior.shape[1]))
    basis[:, :n_b] = shapes
    basis[np.ix_(lin.free, np.arange(n_b, basis.shape[1]))] = interior

    def project(matrix: sp.spmatrix) -> np.ndarray:
        out = basis.T @ (matrix @ basis)
        return 0.5 * (out + out.T)

    return ReducedFootprint(
        compounds={name: project(part) for name, part in lin.compounds.items()},
        pneumatic=project(lin.pneumatic),
        mass=project(lin.mass),
        n_boundary=n_b,
        n_modes=modes.shape[1],
        laws=lin.laws,
        pneumatic_law=lin.pneumatic_law,
    )


def _boundary_columns(lin: LinearisedTire) -> sp.csc_matrix:
    """Unit motions (n_dof, P + 1): each contact node's vertical DOF, then every rim node's together."""
    n_dof, n_road = lin.mass.shape[0], lin.road.size
    rows = np.concatenate([lin.road, lin.hub])
    cols = np.concatenate([np.arange(n_road), np.full(lin.hub.size, n_road)])
    return sp.csc_matrix((np.ones(rows.size), (rows, cols)), shape=(n_dof, n_road + 1))


def _factor(stiffness: sp.spmatrix):
    """A factor with ``solve`` of a real symmetric tangent: banded Cholesky, SuperLU if it is not definite."""
    try:
        return BandedCholesky(stiffness)
    except np.linalg.LinAlgError:
        return spla.splu(sp.csc_matrix(stiffness))


def _modes_below(stiffness: sp.spmatrix, mass: sp.spmatrix, factor, omega_cut: float) -> np.ndarray:
    """Mass-normalised modes (n, k) with eigenvalues below ``omega_cut^2``: shift-invert Lanczos about 0
    on the stiffness's ``factor``. A first call for 24 modes sets how many to ask for next, the count
    growing like the frequency (a shell's modal density is flat in frequency), with a quarter to spare."""
    n = stiffness.shape[0]
    inverse = spla.LinearOperator((n, n), matvec=factor.solve, dtype=float)
    count = min(24, n - 2)
    while True:
        values, vectors = spla.eigsh(stiffness, count, mass, sigma=0.0, which="LM", OPinv=inverse)
        order = np.argsort(values)
        values, vectors = values[order], vectors[:, order]
        if values[-1] > omega_cut**2 or count == n - 2:
            return vectors[:, values < omega_cut**2]
        count = min(n - 2, int(np.ceil(1.25 * count * omega_cut / np.sqrt(max(values[-1], 1e-300)))) + 1)


def _mass_orthonormal(vectors: np.ndarray, mass: sp.spmatrix, keep: int) -> np.ndarray:
    """An M-orthonormal basis of ``vectors``' span, the first ``keep`` (modes) as they are, the rest
    orthogonalised against them and each other (directions below 1e-10 of their norm dropped)."""
    basis = vectors[:, :keep]
    rest = vectors[:, keep:]
    rest = rest - basis @ (basis.T @ (mass @ rest))
    norms = np.sqrt(np.einsum("ij,ij->j", rest, mass @ rest))
    rest = rest[:, norms > 0] / norms[norms > 0]  # columns of any units on one scale before the threshold
    gram = rest.T @ (mass @ rest)
    values, rotation = np.linalg.eigh(0.5 * (gram + gram.T))
    kept = values > 1e-10 * values.max() if values.size else np.zeros(0, bool)
    return np.hstack([basis, rest @ (rotation[:, kept] / np.sqrt(values[kept]))])


def footprint_frf(
    linearised: LinearisedTire, freqs: np.ndarray, reduced: ReducedFootprint | None = None
) -> LoadedFootprintFRF:
    """The footprint's hub-force transfer on the reduced basis (:func:`reduce`; built here for
    ``max(freqs)`` unless given): the boundary's condensed dynamic stiffness ``S`` at each frequency,
    :math:`h_p = -S_{hub,p}`, :math:`G_H = -S_{hub,hub}`."""
    freqs = _check_freqs(freqs)
    if reduced is None:
        reduced = reduce(linearised, max(float(freqs.max()), 1.0))
    hub = np.array([-reduced.boundary_stiffness(2 * np.pi * f)[-1] for f in freqs])
    return LoadedFootprintFRF(freqs=freqs, hub=hub[:, :-1], G_H=hub[:, -1])
