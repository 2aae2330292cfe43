"""Dynamics of the loaded tire linearised about its static state: the paper's FET in the frequency domain.

About a loaded equilibrium ``u0`` (:func:`.road_contact.press_on_road`) a small motion
``u e^{i omega t}`` meets the dynamic stiffness

.. math:: D(\\omega) = \\sum_c g_c(\\omega)\\,K_c + g_p(\\omega)\\,K_p - \\omega^2 M,

with ``K_c`` the material tangent :math:`\\int B^T D B\\,dV_0` of the points of compound ``c``
(``B`` at ``u0``), scaled by that compound's modulus ratio ``g_c`` (the frequency-dependent laws
of the tire file, as the waveguide tire scales each compound's layers: the paper's FETvisco),
``K_p`` the stress's geometric stiffness :math:`\\int G^T S G\\,dV_0` with the pressure's load
stiffness, scaled like the waveguide's pneumatic stiffness (by the file's ``[pneumatic]
compound``, or not at all), and ``M`` the consistent mass. At zero frequency, with every ratio 1,
``D`` is the static tangent of :func:`.statics.residual_and_tangent`: the loaded state's.

The footprint's contact nodes follow the road along its normal (vertical on the flat road,
radial on a drum), held there and free along it (bilateral and frictionless, the contact set
frozen: the paper's linearisation and the other tire models'), and the rim is rigid and held. A
vertical road displacement ``d_p`` under contact node ``p`` gives the force on the hub :math:`h_p(\\omega)\\,d_p`; the nodes of a tassello together
give its ``H_i``, all of them ``H_tot``; a unit vertical rim motion with the contact held gives
``G_H`` (``-K_v`` at rest).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ... import guards
from ..cavity import CavityCoupling
from ..symmetric_factor import SymmetricFactor
from . import pressure, road_contact, solid
from .statics import LoadedTire, StaticState


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
        The held DOF of the contact nodes (the road's inputs): vertical on the flat road, along the
        drum's normal on a drum (the DOF are then in the contact's frame).
    road_vertical : ndarray
        The vertical component of each contact node's normal (1 on the flat road): a unit vertical
        road motion under the node moves it by that much along its held DOF.
    hub : ndarray of int
        The vertical DOF of the rim's nodes (they move together with the hub).
    free : ndarray of int
        DOF neither on the rim nor held by the road.
    state : StaticState
    curvature : csr_matrix
        The drum's curvature term (N/m): ``-lambda / R`` on each contact node's tangent DOF, lossless
        (zero on the flat road).
    road_slide : csc_matrix (n_dof, P + 1)
        Minus each boundary motion's slide of the drum's surface along a node's tangent: the road
        under a contact node moved up by one moves the drum's surface there ``-n_x`` along the
        node's tangent, and the curvature term acts on the node's slide relative to it (zero on the
        flat road and for the hub).
    """

    compounds: dict
    pneumatic: sp.csr_matrix
    mass: sp.csr_matrix
    laws: dict
    pneumatic_law: str | None
    road: np.ndarray
    road_vertical: np.ndarray
    hub: np.ndarray
    free: np.ndarray
    state: StaticState
    curvature: sp.csr_matrix
    road_slide: sp.csc_matrix

    def parts(self) -> list[sp.csr_matrix]:
        """The stiffness parts and the mass, in the order of :func:`_weights`."""
        return [self.pneumatic, *self.compounds.values(), self.mass, self.curvature]

    def weights(self, omega: float) -> np.ndarray:
        """The weight of each of :meth:`parts` at ``omega`` (rad/s)."""
        return _weights(self.laws, self.pneumatic_law, list(self.compounds), omega)

    def boundaries(self) -> list[sp.csc_matrix]:
        """Each part's boundary motions: :func:`boundary_columns`, the curvature's with the drum's slide."""
        boundary = boundary_columns(self)
        return [boundary] * (len(self.compounds) + 2) + [(boundary + self.road_slide).tocsc()]

    def stiffness(self, omega: float) -> sp.csr_matrix:
        """:math:`\\sum_c g_c K_c + g_p K_p` and the curvature term at ``omega`` (rad/s), complex (N/m)."""
        weights = self.weights(omega)
        return sum(w * part for w, part in zip(weights, self.parts()) if part is not self.mass).tocsr()


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
        b = solid.strain_operator(f, group)
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


def linearise(tire: LoadedTire, state: StaticState, nodes: np.ndarray | None = None) -> LinearisedTire:
    """The loaded tire about ``state``, contact set frozen: its stiffness parts, mass and DOF sets.

    On a drum each contact node's ``x``/``z`` pair is turned into its tangent and normal DOF (the
    contact's frame, :class:`.road_contact.RoadContact`), the normal held, and the contact forces'
    curvature term is a part of its own, lossless (the drum is rigid). The road under a node
    moved up by one moves the node ``n_z`` along its normal and the drum's surface ``-n_x`` along
    its tangent: the curvature term acts on the node's slide relative to the drum (the mixed
    derivative of the constraint), so a rigid motion of tire and drum together gives no force.

    ``nodes``: the tread nodes whose normal DOF are the road's (default the state's contact nodes;
    the one-sided cleat runs give every tread node the cleat may reach, those out of contact
    carrying no force and so no curvature term).
    """
    contact = road_contact.contact_of(tire, state)
    nodes = state.contact if nodes is None else np.asarray(nodes, int)
    contact.active = nodes
    compounds, pneumatic = tangent_parts(tire, state.u, state.pressure)
    spec = tire.spec
    mass = solid.mass_matrix(solid.element_groups(tire.mesh, spec, arc_points=3), tire.n_dof)
    _, normals = contact.gaps_and_normals(nodes, state.u)
    frame = contact.frame(normals)
    road = 3 * nodes + 2
    n_dof, n_road = tire.n_dof, road.size
    curvature = sp.csr_matrix((n_dof, n_dof))
    slide = sp.csc_matrix((n_dof, n_road + 1))
    if frame is not None:
        compounds = {name: (frame.T @ part @ frame).tocsr() for name, part in compounds.items()}
        pneumatic = (frame.T @ pneumatic @ frame).tocsr()
        mass = (frame.T @ mass @ frame).tocsr()
        force = (frame.T @ state.reactions)[road]
        curvature = sp.csr_matrix((-force / state.road.drum_radius, (road - 2, road - 2)), shape=(n_dof, n_dof))
        slide = sp.csc_matrix((normals[:, 0], (road - 2, np.arange(n_road))), shape=(n_dof, n_road + 1))
    return LinearisedTire(
        compounds=compounds,
        pneumatic=pneumatic,
        mass=mass,
        laws=spec.laws(),
        pneumatic_law=spec.pneumatic,
        road=road,
        road_vertical=normals[:, 1].copy(),
        hub=tire.rim_vertical,
        free=np.setdiff1d(np.arange(n_dof), np.concatenate([tire.fixed, road])),
        state=state,
        curvature=curvature,
        road_slide=slide,
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


def check_wall(lin: LinearisedTire, cavity: CavityCoupling) -> None:
    """Refuse a cavity wall that reaches a contact node (on a drum those nodes' DOF are turned into the
    road's frame, the wall's volume changes are not) and air that streams (the loaded tire's air is
    at rest: its solves use the modes' gains at rest alone)."""
    if cavity.flow is not None:
        raise ValueError("cavity.flow: the loaded FE tire's air is at rest; valid couplings have flow = None")
    if np.any(cavity.volume[np.ravel(lin.road[:, None] - np.arange(3))]):
        raise ValueError("the cavity's wall reaches a contact node: the inner surface touches the road")


def _weights(laws: dict, pneumatic_law: str | None, compounds: list, omega: float) -> np.ndarray:
    """The parts' weights at ``omega``: the pneumatic part's ratio, each compound's, ``-omega^2`` (mass),
    then 1 (the drum's curvature term)."""
    return np.array(
        [_ratio(laws, pneumatic_law, omega), *(_ratio(laws, name, omega) for name in compounds), -(omega**2), 1.0],
        complex,
    )


def check_freqs(freqs: np.ndarray) -> np.ndarray:
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
CUTOFF_FACTOR = 2.0


@dataclass(frozen=True, eq=False)
class ReducedFootprint:
    """The linearised tire on a Craig-Bampton basis: its boundary (each contact node's held DOF moved
    as the road under it rises by one, vertical on the flat road and along the drum's normal by
    ``n_z`` on a drum; then the rim moving vertically as one) and interior coordinates.

    Attributes
    ----------
    compounds : dict of str to ndarray (r, r)
        Each compound's projected material tangent.
    pneumatic, mass, curvature : ndarray (r, r)
    n_boundary : int
        The first ``n_boundary`` coordinates are the boundary's motions (the contact nodes', the hub's).
    n_modes : int
        The held tire's modes at rest among the interior coordinates (the first ``n_modes`` of them).
    laws, pneumatic_law
        As :class:`LinearisedTire`.
    basis : ndarray (n_dof, r) or None
        The basis itself (``reduce(..., keep_basis=True)``; else None).
    mode_harmonic : ndarray of int (n_modes,) or None
        The circumferential wave number of each held mode at rest, where known
        (:func:`roadnoise_utils.tire.loaded.stages.reduced_footprint`).
    cavity : CavityCoupling or None
        The air cavity coupled to the reduced coordinates (its modes' volume changes projected on
        the basis, ``volume`` (r, modes); ``wall`` not kept); None: no air.
    air : ndarray (r, r) or None
        The air's stiffness where its modes are coordinates of the model, the last ones
        (:func:`roadnoise_utils.tire.loaded.cavity.with_air_coordinates`: their masses in ``mass``,
        ``cavity`` then None); frequency-independent.
    n_air : int
        How many of the last coordinates are the air's (0 without ``air``).
    """

    compounds: dict
    pneumatic: np.ndarray
    mass: np.ndarray
    curvature: np.ndarray
    n_boundary: int
    n_modes: int
    laws: dict
    pneumatic_law: str | None
    basis: np.ndarray | None = None
    mode_harmonic: np.ndarray | None = None
    cavity: CavityCoupling | None = None
    air: np.ndarray | None = None
    n_air: int = 0

    def stiffness(self, omega: float) -> np.ndarray:
        """:math:`\\sum_c g_c K_c + g_p K_p`, the curvature term and the air's coordinates' stiffness at ``omega``
        (rad/s), reduced, complex (N/m): the dynamic stiffness without its inertia."""
        weights = _weights(self.laws, self.pneumatic_law, list(self.compounds), omega)
        parts = [self.pneumatic, *self.compounds.values(), self.curvature]
        out = sum(w * part for w, part in zip(np.delete(weights, -2), parts))
        return out if self.air is None else out + self.air

    def hub_stiffness(self, omega: float) -> np.ndarray:
        """The hub's row of the boundary's condensed dynamic stiffness at ``omega`` (rad/s), (n_boundary,) complex.

        The interior condensed out, :math:`S = D_{bb} - D_{bi} D_{ii}^{-1} D_{ib}`; of ``S`` only the
        hub's row is needed, and ``D`` is complex symmetric, so one solve with the interior block
        gives it:
        :math:`S_{h,:} = D_{h,b} - (D_{ii}^{-1} D_{i,h})^T D_{ib}`. With the air cavity ``D`` carries
        its term :math:`-V C(\\omega) V^T` (:meth:`roadnoise_utils.tire.cavity.CavityCoupling.terms`).
        """
        weights = _weights(self.laws, self.pneumatic_law, list(self.compounds), omega)
        parts = [self.pneumatic, *self.compounds.values(), self.mass, self.curvature]
        d = sum(w * part for w, part in zip(weights, parts))
        if self.air is not None:
            d = d + self.air
        if self.cavity is not None:
            gains, volume = self.cavity.terms(omega)
            d = d - self.cavity.volume @ gains @ volume.T
        b = self.n_boundary
        interior = np.linalg.solve(d[b:, b:], d[b:, b - 1])
        return d[b - 1, :b] - interior @ d[b:, :b]


def _ratio(laws: dict, name: str | None, omega: float) -> complex:
    return 1.0 if name is None else complex(laws[name].ratio(np.array([omega]))[0])


def reduce(
    linearised: LinearisedTire,
    f_max: float,
    cutoff_factor: float = CUTOFF_FACTOR,
    keep_basis: bool = False,
    cavity: CavityCoupling | None = None,
) -> ReducedFootprint:
    r"""Project the linearised tire on the boundary's static shapes, the held tire's modes and two corrections.

    The basis (Craig & Bampton, AIAA J. 6, 1968, enriched for moduli that change with frequency):
    for each boundary motion its static shape :math:`\Psi` (the free DOF in equilibrium at rest,
    every ratio 1); the boundary-held tire's modes :math:`\Phi` below ``cutoff_factor * f_max`` at
    rest, and their first-order change as the compounds stiffen to their storage moduli at
    ``f_max`` (unequally, by up to ~40 % over the band, which moves the modes' shapes as well as
    their frequencies): :math:`K_{ff}^{-1} \Delta K_{ff} \Phi`, the span of the modes' derivatives
    with :math:`\Phi` (Nelson, AIAA J. 14, 1976); the change of the static shapes between the two
    stiffnesses; and the inertia load of the static shapes, :math:`-K_{ff}^{-1} M [\Psi; I]` (the
    first load-dependent Ritz block: Wilson, Yuan & Dickens, Earthq. Eng. Struct. Dyn. 10, 1982),
    which the modes above the cut-off would carry. The interior coordinates are mass-orthonormalised.
    Measured at 0-400 Hz against the direct solve, relative to the largest transfer, with the
    default cut-off (twice the band's top): within 3.5e-4 on the test mesh loaded to 1 kN, 2.4e-4 on
    a 12 240-DOF mesh on the drum at 3 kN; at 2.5 times the top, the stiffened tire's own modes in
    place of the change give the same (3.4e-4 and 2.1e-4, against 3.4e-4 and 2.2e-4) from a second
    shift-invert Lanczos run; the modes at rest without their change, 2.4e-3 on the test mesh.

    With the air ``cavity`` (:func:`roadnoise_utils.tire.loaded.cavity.loaded_coupling`) the basis also holds the
    free DOF's static response to each cavity mode's pressure on the wall, :math:`K_{ff}^{-1} V_f`, and
    the coupling is projected on it.
    """
    lin = linearised
    f_max = guards.real("f_max", f_max, lo=0.0, lo_open=True, unit="Hz")
    cutoff_factor = guards.real("cutoff_factor", cutoff_factor, lo=1.0, unit="")
    rest = lin.stiffness(0.0).real.tocsr()
    boundary = boundary_columns(lin)
    slide_load = (lin.curvature[lin.free] @ lin.road_slide).toarray()  # the drum's slide on the curvature term
    mass_ff = lin.mass[lin.free][:, lin.free].tocsc()
    factor = _factor(rest[lin.free][:, lin.free])
    shapes = boundary.toarray()
    shapes[lin.free] = -factor.solve((rest[lin.free] @ boundary).toarray() + slide_load)
    omega_cut = 2 * np.pi * cutoff_factor * f_max
    modes = _modes_below(rest[lin.free][:, lin.free], mass_ff, factor, omega_cut)
    stiff = lin.stiffness(2 * np.pi * f_max).real.tocsr()
    stiff_factor = _factor(stiff[lin.free][:, lin.free])
    # the modes' first-order change as the compounds stiffen: (K_rest^-1 dK) Phi spans it with Phi
    stiffening = factor.solve((stiff - rest)[lin.free][:, lin.free] @ modes)
    stiff_shapes = -stiff_factor.solve((stiff[lin.free] @ boundary).toarray() + slide_load)
    inertia = -factor.solve(lin.mass[lin.free] @ shapes)
    ritz = [modes, stiffening, stiff_shapes - shapes[lin.free], inertia]
    if cavity is not None:
        check_wall(lin, cavity)
        ritz.append(factor.solve(cavity.volume[lin.free]))  # the air's pressures on the wall, at rest
    interior = _mass_orthonormal(np.hstack(ritz), mass_ff, keep=modes.shape[1])
    n_b = boundary.shape[1]
    basis = np.zeros((lin.mass.shape[0], n_b + interior.shape[1]))
    basis[:, :n_b] = shapes
    basis[np.ix_(lin.free, np.arange(n_b, basis.shape[1]))] = interior

    def project(matrix: sp.spmatrix) -> np.ndarray:
        out = basis.T @ (matrix @ basis)
        return 0.5 * (out + out.T)

    # the curvature term lives on the contact nodes' tangent DOF alone; it sees the basis with the drum's slide
    rows = np.unique(lin.curvature.nonzero()[0])
    slid = basis[rows]
    slid[:, :n_b] += lin.road_slide[rows].toarray()
    curvature = slid.T @ (lin.curvature[rows][:, rows] @ slid)
    return ReducedFootprint(
        compounds={name: project(part) for name, part in lin.compounds.items()},
        pneumatic=project(lin.pneumatic),
        mass=project(lin.mass),
        curvature=0.5 * (curvature + curvature.T),
        n_boundary=n_b,
        n_modes=modes.shape[1],
        laws=lin.laws,
        pneumatic_law=lin.pneumatic_law,
        basis=basis if keep_basis else None,
        cavity=None if cavity is None else replace(cavity, volume=basis.T @ cavity.volume, wall=None),
    )


def boundary_columns(lin: LinearisedTire) -> sp.csc_matrix:
    """Unit motions (n_dof, P + 1): the road under each contact node moved up by one (its held DOF by
    the normal's vertical component), then every rim node's vertical DOF together."""
    n_dof, n_road = lin.mass.shape[0], lin.road.size
    rows = np.concatenate([lin.road, lin.hub])
    cols = np.concatenate([np.arange(n_road), np.full(lin.hub.size, n_road)])
    values = np.concatenate([lin.road_vertical, np.ones(lin.hub.size)])
    return sp.csc_matrix((values, (rows, cols)), shape=(n_dof, n_road + 1))


def _factor(stiffness: sp.spmatrix) -> SymmetricFactor:
    """The factor of a real symmetric tangent, definite or not (:class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor`)."""
    return SymmetricFactor(stiffness, require_definite=False)


def _modes_below(stiffness: sp.spmatrix, mass: sp.spmatrix, factor, omega_cut: float) -> np.ndarray:
    r"""Mass-normalised modes (n, k) with eigenvalues below ``omega_cut^2``: shift-invert Lanczos about 0
    on the stiffness's ``factor``, asked for as many as there are (the negative pivots of
    :math:`K - \omega_{cut}^2 M`, Sylvester's law of inertia) with a tenth to spare; where that count
    is unavailable or falls short, the request grows like the frequency (a shell's modal density is
    flat in frequency), with a quarter to spare, until the last mode found is above the cut-off; a
    request past the cut-off that finds fewer than the count is made once more with a quarter more."""
    n = stiffness.shape[0]
    inverse = spla.LinearOperator((n, n), matvec=factor.solve, dtype=float)
    below = _count_below(stiffness, mass, omega_cut)
    count = min(24 if below is None else int(1.1 * below) + 4, n - 2)
    # ARPACK's starting vector, fixed: its default is drawn from a generator that runs on from call to call
    # in a process, so the basis, and every transfer built on it, differed in their last bits with the
    # calls a process had made before (which the reproduction's scheduling decides), and the fits'
    # automatic orders can turn such bits into visible differences
    start = np.random.default_rng(0).standard_normal(n)
    while True:
        values, vectors = spla.eigsh(stiffness, count, mass, sigma=0.0, which="LM", OPinv=inverse, v0=start)
        order = np.argsort(values)
        values, vectors = values[order], vectors[:, order]
        found = int(np.count_nonzero(values < omega_cut**2))
        if count == n - 2 or (values[-1] > omega_cut**2 and (below is None or found >= below)):
            return vectors[:, :found]
        if values[-1] > omega_cut**2:  # past the cut-off yet short of the count: ask once for more, then trust it
            count, below = min(n - 2, count + max(8, count // 4)), None
            continue
        count = min(n - 2, int(np.ceil(1.25 * count * omega_cut / np.sqrt(max(values[-1], 1e-300)))) + 1)


def _count_below(stiffness: sp.spmatrix, mass: sp.spmatrix, omega_cut: float) -> int | None:
    """How many eigenvalues of ``(stiffness, mass)`` lie below ``omega_cut^2``: the negative pivots of the
    shifted stiffness's symmetric factor (``None`` where it pivoted off the diagonal)."""
    try:
        return SymmetricFactor((stiffness - omega_cut**2 * mass).tocsc(), require_definite=False).negative_pivots
    except np.linalg.LinAlgError:  # singular at the shift: a mode exactly at the cut-off
        return None


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
    linearised: LinearisedTire,
    freqs: np.ndarray,
    reduced: ReducedFootprint | None = None,
    cavity: CavityCoupling | None = None,
) -> LoadedFootprintFRF:
    """The footprint's hub-force transfer on the reduced basis (:func:`reduce`; built here for
    ``max(freqs)``, with the air ``cavity`` if given, unless ``reduced`` is): the boundary's condensed
    dynamic stiffness ``S`` at each frequency, :math:`h_p = -S_{hub,p}`, :math:`G_H = -S_{hub,hub}`."""
    freqs = check_freqs(freqs)
    if reduced is None:
        reduced = reduce(linearised, max(float(freqs.max()), 1.0), cavity=cavity)
    hub = np.array([-reduced.hub_stiffness(2 * np.pi * f) for f in freqs])
    return LoadedFootprintFRF(freqs=freqs, hub=hub[:, :-1], G_H=hub[:, -1])
