"""One-sided contact of the loaded FE tire over a cleat on the drum, about its nonlinear loaded state.

The tire is loaded on the drum by large-deformation statics (:func:`.road_contact.press_on_road`);
the cleat's passage is a small motion about that state, on its tangent (material, geometric,
pressure and the drum's curvature term: :func:`.dynamics.linearise`), the hub held at its static
height. Every tread node the cleat can reach is a candidate (:class:`CleatContact`): the nodes
within :data:`HALF_LENGTH` of the axle along the drum whose gap to the drum at the loaded state is
less than the cleat's height and :data:`MARGIN`. Each carries a force along the drum's normal
through it, :math:`\\lambda_i = \\lambda_{0,i} + \\Delta\\lambda_i \\ge 0` (the loaded state's force
and its change), and may lift off or touch: frictionless one-sided contact, as in the statics.
A node's gap is its loaded gap :math:`g_{0,i}` plus its motion along the normal less the cleat's
height under it (averaged over the node's hat along the tread, :func:`~roadnoise_utils.road.cleat.point_heights`).

* **Quasi-static** (:func:`quasi_static_run`): at each travel the contact problem on the
  compliance :math:`C` of the candidates' normal DOF (the tangent at rest, every candidate free),
  :math:`C_{AA}\\lambda_A = p_A` with :math:`p = h - g_0 + C\\lambda_0`
  (:func:`~roadnoise_utils.tire.active_set.held_contact`); the hub force is the rim's reaction.
* **Dynamic** (:func:`dynamic_runs`): the linearised tire on a Craig-Bampton basis whose boundary is
  the candidates' normal DOF (:func:`.dynamics.reduce`: their static shapes, the held tire's modes
  and their corrections), each compound's stiffness carrying its Prony series (the
  frequency-dependent laws of the FRFs, < 0.2 % from them over 0.1-2000 Hz), stepped by the
  generalised-alpha scheme of the cross-section tire
  (:class:`~roadnoise_utils.tire.cross_section.stepping.StepGroup`); each step solves the contact on
  the step's compliance (:class:`~roadnoise_utils.tire.active_set.StepContact`). The hub force is
  the tire's vertical momentum balance: the contact forces' vertical shares and the drum's
  curvature term's, less the rate of the vertical momentum.

The vertical share of the internal forces vanishes for any motion with the beads held: the
elements' forces balance, and the pressure's resultant on the inner surface is the pressure times
its vector area, which its bead edges fix. So the momentum balance gives the rim's reaction; the
quasi-static run checks it against the reaction itself. ``frozen`` keeps the loaded contact set
bilateral: the linear model of the FRFs, to compare with the frequency domain.

**The air cavity** (``air``, where the tire file couples it): at rest only its uniform pressure
acts, a stiffness :math:`\\rho c^2 V_0 V_0^T` added to the quasi-static compliance by Woodbury's
identity. In the dynamic runs the reduced basis carries the air's static loads
(:func:`.dynamics.reduce`) and each resonant plane-wave mode is a coordinate of its own, in the
causal form of :func:`~roadnoise_utils.tire.cavity.air_coordinates` (the FRFs' hysteretic air has
no causal impulse response; the causal form has its gain at each mode's own frequency, and on
the test mesh the two give :math:`H_{tot}` within 0.8 % of its largest value over 0-250 Hz, 7e-5
below 100 Hz). The hub force then gains the air's: a translation of the wheel changes each mode's
volume by :math:`e^T V_m` (seen from the fixed angles it shifts the section), so the pressures
push the wheel by :math:`\\sum_m (e^T V_m)\\,a_m` (the inner surface's share and the rim base's).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp
from threadpoolctl import threadpool_limits

from ... import guards
from ...road.cleat import point_heights
from ..active_set import StepContact, held_contact
from ..cavity import CavityCoupling, air_coordinates
from ..contact import ContactRun, check_frozen, time_steps
from ..cross_section.dynamics import Projected
from ..cross_section.stepping import SPECTRAL_RADIUS, GeneralizedAlpha, StepGroup, SteppedHarmonic, passive_part
from ..rubber import PronyBranches, prony_series
from ..symmetric_factor import SymmetricFactor
from . import dynamics, road_contact
from .statics import LoadedTire, StaticState

#: The candidates lie within this of the axle along the drum (m): a 15 mm cleat on the 1.25 m drum
#: meets the 165/65 R14 about 105 mm ahead.
HALF_LENGTH = 0.15
#: The candidates' loaded gap is below the cleat's height plus this (m); a step in which any other
#: tread node within :data:`HALF_LENGTH` penetrates the drum is refused (:func:`check_outside`).
MARGIN = 0.005
#: Active-set iterations allowed per contact solve.
MAX_ITERATIONS = 100
#: Band of the dynamic runs' reduced basis (Hz): its modes below twice it (:func:`.dynamics.reduce`).
F_MAX = 400.0


@dataclass(frozen=True, eq=False)
class CleatContact:
    """The tread nodes a cleat passage may reach on the loaded tire, and the cleat's heights under them.

    Attributes
    ----------
    nodes : ndarray of int (P,)
        The candidates (tread nodes).
    watched : ndarray of int (W,)
        Every tread node within :data:`HALF_LENGTH` of the axle (the candidates among them): none
        may penetrate the drum.
    candidate : ndarray of bool (W,)
        Which watched nodes are candidates.
    normals : ndarray (W, 2)
        The drum's outward normal through each watched node (``n_x``, ``n_z``).
    gap : ndarray (W,)
        Each watched node's distance from the drum at the loaded state (m; 0 in contact).
    static_force : ndarray (P,)
        The loaded state's force of the drum on each candidate along its normal (N).
    heights : ndarray (W, n_travel)
        The cleat's height under each watched node at each travel (m).
    """

    nodes: np.ndarray
    watched: np.ndarray
    candidate: np.ndarray
    normals: np.ndarray
    gap: np.ndarray
    static_force: np.ndarray
    heights: np.ndarray

    @property
    def in_contact(self) -> np.ndarray:
        """Which candidates the drum pushes at the loaded state."""
        return self.static_force > 0.0

    @property
    def candidate_heights(self) -> np.ndarray:
        return self.heights[self.candidate]


def drum_arcs(tire: LoadedTire, state: StaticState) -> np.ndarray:
    """Each tread node's position along the drum's surface (m, ahead positive: the drum's angle from the
    top times its radius), at the loaded state; (n_rings, n_columns) as the tread's rings and columns."""
    contact = road_contact.contact_of(tire, state)
    if state.road.kind != "drum":
        raise ValueError(f"state stands on the {state.road.kind} road: the cleat runs are on a drum")
    position = contact.positions(tire.tread, state.u)
    axis = state.road_top - state.road.drum_radius
    arc = state.road.drum_radius * np.arctan2(position[:, 0], position[:, 2] - axis)
    return arc.reshape(tire.mesh.theta.size, -1)


def cleat_contact(tire: LoadedTire, state: StaticState, profile, travel: np.ndarray) -> CleatContact:
    """:class:`CleatContact` of the loaded ``state`` on its drum for ``profile`` (callable of the road
    coordinate, m) at each ``travel`` (m, 0 = the profile's origin under the axle)."""
    arcs = drum_arcs(tire, state)
    n_rings = arcs.shape[0]
    ring = np.arange(n_rings)
    # a node's hat reaches its ring neighbours along its column, the one farther along the drum ahead
    after, before = arcs[(ring + 1) % n_rings], arcs[(ring - 1) % n_rings]
    ahead = np.maximum(after, before) - arcs
    behind = arcs - np.minimum(after, before)
    height = tire.mesh.coordinates[tire.tread, 2]
    below = (height < 0.5 * (height.max() + height.min())).reshape(arcs.shape)  # the drum's side of the axle
    below &= ~np.isin(3 * tire.tread + 2, tire.fixed).reshape(arcs.shape)  # the bead stations' outer nodes are held
    window = (np.abs(arcs) <= HALF_LENGTH) & below
    watched = tire.tread.reshape(arcs.shape)[window]
    heights = point_heights(arcs[window], behind[window], ahead[window], profile, travel)
    contact = road_contact.contact_of(tire, state)
    outside = below & ~window  # no tread node outside the window may come near the profile
    reach = point_heights(arcs[outside], behind[outside], ahead[outside], profile, travel).max(axis=1, initial=0.0)
    if np.any(contact.gaps_and_normals(tire.tread.reshape(arcs.shape)[outside], state.u)[0] < reach + MARGIN):
        raise ValueError(
            f"the profile would come within {MARGIN * 1e3:.0f} mm of tread nodes beyond {HALF_LENGTH * 1e3:.0f} mm "
            "of the axle along the drum, outside the cleat runs' window: valid profiles are lower or shorter"
        )
    gap, normals = contact.gaps_and_normals(watched, state.u)
    gap = np.where(np.isin(watched, state.contact), 0.0, np.maximum(gap, 0.0))
    candidate = gap < heights.max(axis=1) + MARGIN
    nodes = watched[candidate]
    force = np.zeros(nodes.size)
    at = np.isin(nodes, state.contact)
    reactions = state.reactions.reshape(-1, 3)[nodes[at]]
    force[at] = reactions[:, 0] * normals[candidate][at, 0] + reactions[:, 2] * normals[candidate][at, 1]
    if not np.all(np.isin(state.contact, nodes)):
        raise ValueError(
            f"the loaded footprint reaches beyond {HALF_LENGTH * 1e3:.0f} mm of the axle along the drum: "
            "a footprint too long for the cleat runs' window"
        )
    if np.count_nonzero(force > 0.0) != state.contact.size:
        raise RuntimeError("state: a contact node carries no force along the drum's normal (not a loaded equilibrium)")
    return CleatContact(nodes, watched, candidate, normals, gap, force, heights)


def _check_state(state: StaticState) -> None:
    if state.road.kind != "drum" or state.contact.size == 0:
        raise ValueError("state: the cleat runs start from the tire loaded on a drum (loaded_state on a drum case)")


def vertical_in_frame(n_dof: int, road: np.ndarray, normals: np.ndarray) -> np.ndarray:
    """A unit upward motion of every node in the frame of a linearisation whose road DOF are ``road``
    (n_dof,): ``(-n_x, n_z)`` in each road node's tangent and normal slots (``normals`` (P, 2)), 1 in
    every other node's ``z``."""
    e = np.zeros(n_dof)
    e[2::3] = 1.0
    e[road - 2], e[road] = -normals[:, 0], normals[:, 1]
    return e


@dataclass(frozen=True, eq=False)
class StaticCompliance:
    """The loaded tire's static response to forces along the candidates' normals, the rim held.

    Attributes
    ----------
    watched : ndarray (W, P)
        Motion of each watched node along its normal per unit force on each candidate (m/N).
    hub : ndarray (P,)
        Upward force on the hub (the rim's vertical reaction, reversed) per unit force on each candidate (-).
    curvature : ndarray (P,)
        The vertical share of the drum's curvature force per unit force on each candidate (-).
    """

    watched: np.ndarray
    hub: np.ndarray
    curvature: np.ndarray


def static_compliance(
    tire: LoadedTire, lin: dynamics.LinearisedTire, contact: CleatContact, air: CavityCoupling | None = None
) -> StaticCompliance:
    """:class:`StaticCompliance` from the tangent at rest of ``lin`` (linearised with the candidates as its
    road nodes): one symmetric factor and one solve per candidate. ``air``: the cavity, whose uniform
    pressure alone acts at rest (:math:`\\rho c^2 V_0 V_0^T`, by Woodbury's identity on the factor)."""
    rest = lin.stiffness(0.0).real.tocsr()
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    guards.check_memory(
        8.0 * free.size * contact.nodes.size, f"the compliance of {contact.nodes.size} tread nodes", "profile"
    )
    rows = np.searchsorted(free, lin.road)
    unit = np.zeros((free.size, rows.size))
    unit[rows, np.arange(rows.size)] = 1.0
    factor = SymmetricFactor(rest[free][:, free], require_definite=False)
    solved = factor.solve(unit)
    hub = -np.asarray(rest[lin.hub][:, free] @ solved).sum(axis=0)
    if air is not None:
        uniform = np.asarray(air.volume)[:, air.omegas == 0.0]  # (n_dof, 1): the compressibility
        rc2 = air.density * air.sound_speed**2
        spread = factor.solve(uniform[free])
        solved = solved - spread @ np.linalg.solve(np.eye(uniform.shape[1]) / rc2 + uniform[free].T @ spread,
                                                   uniform[free].T @ solved)  # fmt: skip
        hub = -np.asarray(rest[lin.hub][:, free] @ solved).sum(axis=0)
        hub -= rc2 * uniform[lin.hub].sum(axis=0) @ (uniform[free].T @ solved)
    e = vertical_in_frame(tire.n_dof, lin.road, contact.normals[contact.candidate])
    curvature = -(lin.curvature[free][:, free] @ e[free]) @ solved
    motion = np.zeros((contact.watched.size, rows.size))
    motion[contact.candidate] = solved[rows]
    other = contact.watched[~contact.candidate]  # global x and z, along the normal through each
    n = contact.normals[~contact.candidate]
    x_rows, z_rows = np.searchsorted(free, 3 * other), np.searchsorted(free, 3 * other + 2)
    motion[~contact.candidate] = n[:, :1] * solved[x_rows] + n[:, 1:] * solved[z_rows]
    return StaticCompliance(watched=motion, hub=hub, curvature=curvature)


def quasi_static_run(
    tire: LoadedTire,
    state: StaticState,
    profile,
    distance: tuple[float, float],
    step: float = 1.0e-3,
    air: CavityCoupling | None = None,
) -> ContactRun:
    """Quasi-static passage of ``profile`` over the loaded tire on its drum, one-sided contact, the hub held.

    ``distance``: the travel (m, 0 = the profile's origin under the axle), solved every ``step`` m;
    ``air``: the loaded state's cavity (:func:`.cavity.loaded_coupling`; at rest its uniform pressure alone).
    ``force_balance`` (over the load): the larger of the largest hub force while no node in contact
    stands on the profile (the loaded state itself must come back) and the largest difference
    between the rim's reaction and the external forces' vertical shares (the momentum balance the
    dynamic runs' hub force rests on, at rest).
    """
    d0, d1 = guards.interval("distance", distance)
    step = guards.real("step", step, 0.0, 0.01, lo_open=True, unit="m")
    _check_state(state)
    travel = np.arange(d0, d1 + 0.5 * step, step)
    contact = cleat_contact(tire, state, profile, travel)
    lin = dynamics.linearise(tire, state, contact.nodes)
    compliance = static_compliance(tire, lin, contact, air)
    reach = compliance.watched[contact.candidate]
    lam0, heights = contact.static_force, contact.candidate_heights
    base = reach @ lam0 - contact.gap[contact.candidate]
    vertical = contact.normals[contact.candidate, 1] + compliance.curvature
    active = contact.in_contact.copy()
    hub, points = np.zeros(travel.size), np.zeros(travel.size, int)
    on_profile = np.zeros(travel.size, bool)
    worst, most, balance = 0.0, 0, 0.0
    for k in range(travel.size):
        forces, active, iterations = held_contact(
            lambda cols: reach[:, cols], base + heights[:, k], active, np.zeros(active.size), MAX_ITERATIONS
        )
        change = forces - lam0
        hub[k] = compliance.hub @ change
        balance = max(balance, abs(vertical @ change - hub[k]))
        points[k], on_profile[k] = active.sum(), bool(np.any(active & (heights[:, k] > 0)))
        gap = contact.gap + compliance.watched @ change - contact.heights[:, k]
        check_outside(contact, gap, travel[k])
        gap[np.flatnonzero(contact.candidate)[active]] = 0.0
        worst, most = max(worst, float(-gap.min())), max(most, iterations)
    off = ~on_profile
    rest = float(np.max(np.abs(hub[off]))) if off.any() else 0.0
    return ContactRun.quasi_static(
        travel, d0, hub, points, on_profile, worst, max(rest, balance) / state.road_force, most
    )


@dataclass(frozen=True, eq=False)
class CleatModel:
    """The loaded tire reduced with the candidates as its boundary, made passive and mass-orthonormal.

    Attributes
    ----------
    entry : SteppedHarmonic
        The reduced model (:func:`~roadnoise_utils.tire.cross_section.stepping.passive_part`): its
        ``contact`` (k, P) the candidates' normal motions, its ``momentum`` (k,) the tire's vertical
        momentum per unit coordinate velocity (kg).
    watch : ndarray (W, k)
        Each watched node's motion along its normal per coordinate.
    curvature : ndarray (k,)
        The vertical share of the drum's curvature force per coordinate, reversed (N/m).
    laws : dict
        Each compound's modulus law.
    air, air_rate : ndarray (k,)
        The vertical force of the air's pressure on the inner surface and the rim's base per
        coordinate (N/m) and per coordinate velocity (N s/m); zero without the air cavity.
    """

    entry: SteppedHarmonic
    watch: np.ndarray
    curvature: np.ndarray
    laws: dict
    air: np.ndarray
    air_rate: np.ndarray


def cleat_model(
    tire: LoadedTire, state: StaticState, contact: CleatContact, f_max: float = F_MAX, air: CavityCoupling | None = None
) -> CleatModel:
    """:class:`CleatModel`: the tire linearised about ``state`` with the candidates as its road nodes,
    each moved along its normal with the drum still, on the Craig-Bampton basis of
    :func:`.dynamics.reduce` for 0-``f_max`` Hz, the hub's coordinate held.

    The pneumatic part joins the compound whose law scales it (``[pneumatic] compound``), as in the
    FRFs; the drum's curvature term is lossless. ``air``: the cavity of the loaded state
    (:func:`.cavity.loaded_coupling`), its resonant modes coordinates of their own in the causal
    form (:func:`~roadnoise_utils.tire.cavity.air_coordinates`: springs and dashpots), their
    pressures' vertical force on the wheel in :attr:`CleatModel.air`.
    """
    n_road = contact.nodes.size
    lin = dynamics.linearise(tire, state, contact.nodes)
    lin = replace(lin, road_vertical=np.ones(n_road), road_slide=sp.csc_matrix((tire.n_dof, n_road + 1)))
    reduced = dynamics.reduce(lin, f_max, keep_basis=True, cavity=air)
    e = vertical_in_frame(tire.n_dof, lin.road, contact.normals[contact.candidate])
    coordinates = None if air is None else air_coordinates(reduced.cavity, causal=True)
    n_air = 0 if coordinates is None else coordinates.size
    r = reduced.mass.shape[0]
    keep = np.delete(np.arange(r + n_air), n_road)  # the hub's coordinate, held

    def held(matrix: np.ndarray) -> np.ndarray:
        return np.pad(matrix, ((0, n_air), (0, n_air)))[np.ix_(keep, keep)]

    basis = np.pad(reduced.basis, ((0, 0), (0, n_air)))[:, keep]  # the air's coordinates move no node
    compounds = {name: held(part) for name, part in reduced.compounds.items()}
    gas, mass = held(reduced.curvature), held(reduced.mass)
    air_force, air_rate, damping = np.zeros(keep.size), np.zeros(keep.size), None
    if coordinates is not None:
        gas = gas + coordinates.stiffness[np.ix_(keep, keep)]
        mass[-n_air:, -n_air:] = np.diag(coordinates.mass)
        damping = coordinates.damping[np.ix_(keep, keep)]
        share = e @ air.volume  # e^T V: the pressures' vertical force on the wheel (a translation's volume changes)
        air_force, air_rate = (share @ coordinates.pressure)[keep], (share @ coordinates.pressure_rate)[keep]
    if lin.pneumatic_law is None:
        gas = gas + held(reduced.pneumatic)
    else:
        compounds[lin.pneumatic_law] = compounds[lin.pneumatic_law] + held(reduced.pneumatic)
    # the watched motions and the hub force's rows ride along as contact columns through the rotation
    hub_rows = np.stack([basis.T @ (lin.curvature @ e), air_force, air_rate], axis=1)
    columns = np.hstack([basis[lin.road].T, watched_motions(contact, basis, lin.road).T, hub_rows])
    projected = Projected(compounds, gas, mass, columns, basis.T @ (lin.mass @ e), damping=damping)
    passive, dropped = passive_part(projected, list(compounds))
    if dropped:
        guards.warn(
            f"{dropped} direction(s) of negative static stiffness left out of the stepped loaded tire "
            "(its tangent with the candidates free is not definite there)"
        )
    rotated = passive.contact
    passive = replace(passive, contact=rotated[:, :n_road])
    entry = SteppedHarmonic(1, passive, reduced.n_modes, dropped)  # n = 1: its momentum counts
    return CleatModel(entry, rotated[:, n_road:-3].T, rotated[:, -3], lin.laws, rotated[:, -2], rotated[:, -1])


def watched_motions(contact: CleatContact, basis: np.ndarray, road: np.ndarray) -> np.ndarray:
    """Each watched node's motion along the drum's normal through it per coordinate of ``basis`` (W, k): the
    candidates' road DOF (``road``, their normal in the contact's frame), the others' global ``x`` and ``z``."""
    other = contact.watched[~contact.candidate]
    n = contact.normals[~contact.candidate]
    watch = np.zeros((contact.watched.size, basis.shape[1]))
    watch[contact.candidate] = basis[road]
    watch[~contact.candidate] = n[:, :1] * basis[3 * other] + n[:, 1:] * basis[3 * other + 2]
    return watch


def dynamic_runs(
    tire: LoadedTire,
    state: StaticState,
    profile,
    speed: float,
    distance: tuple[float, float],
    dt: float | None = None,
    frozen: tuple[bool, ...] = (False, True),
    spectral_radius: float = SPECTRAL_RADIUS,
    air: CavityCoupling | None = None,
) -> list[ContactRun]:
    """Dynamic passages of ``profile`` at ``speed`` (m/s) over the loaded tire on its drum, hub held, one run
    per entry of ``frozen`` (True: the loaded contact set held bilateral), stepped together every ``dt`` s
    (default :data:`~roadnoise_utils.tire.contact.DT_MAX` or less, a quarter of the footprint's node
    spacing per step) from rest in the loaded state; ``air``: the loaded state's cavity (:func:`cleat_model`)."""
    speed = guards.real("speed", speed, 0.0, 100.0, lo_open=True, unit="m/s")
    _check_state(state)
    check_frozen(frozen)
    dt, travel = time_steps(_node_spacing(tire, state), speed, distance, dt)
    contact = cleat_contact(tire, state, profile, travel)
    model = cleat_model(tire, state, contact, air=air)
    scheme = GeneralizedAlpha(guards.real("spectral_radius", spectral_radius, 0.0, 1.0))
    branches = {name: PronyBranches(prony_series(model.laws[name]), dt) for name in model.entry.projected.compounds}
    runs = len(frozen)
    group = StepGroup([model.entry], dt, branches, scheme, runs)
    step_compliance = group.flexibility()[0]
    step_compliance = 0.5 * (step_compliance + step_compliance.T)
    lam0, heights = contact.static_force, contact.candidate_heights
    if np.any(contact.heights[:, 0] > contact.gap):
        raise ValueError(
            f"the profile already touches the tread at the first travel {travel[0]:.3f} m: valid range is a "
            "distance starting before the profile reaches the tire (the run starts from the loaded state at rest)"
        )
    base = step_compliance @ lam0 - contact.gap[contact.candidate]
    solvers = [StepContact(step_compliance, contact.in_contact, bool(f), MAX_ITERATIONS) for f in frozen]
    vertical = contact.normals[contact.candidate, 1]
    hub = np.zeros((runs, travel.size))
    points = np.zeros((runs, travel.size), int)
    points[:, 0] = int(contact.in_contact.sum())
    on_profile = np.zeros((runs, travel.size), bool)
    worst, most = np.zeros(runs), np.zeros(runs, int)
    forces = np.zeros((runs, lam0.size))
    candidates = np.flatnonzero(contact.candidate)
    with threadpool_limits(1, user_api="blas"):  # small products: threads only fight over the cores
        for k in range(1, travel.size):
            free = group.predict(dt, scheme)
            predicted = group.contact[0] @ free[0]  # (P, runs): the candidates' normal motions
            for r, solver in enumerate(solvers):
                forces[r], iterations = solver.solve(base + heights[:, k] - predicted[:, r])
                most[r] = max(most[r], iterations)
            change = (forces - lam0).T
            group.advance(free, change[None], dt, scheme)
            q = group.q[0]
            hub[:, k] = (vertical @ change + (model.air - model.curvature) @ q + model.air_rate @ group.velocity[0]
                         - group.momentum[0] @ group.unbalance[0])  # fmt: skip
            gaps = contact.gap[:, None] + model.watch @ q - contact.heights[:, k : k + 1]
            for r, solver in enumerate(solvers):
                points[r, k] = solver.active.sum()
                on_profile[r, k] = bool(np.any(solver.active & (heights[:, k] > 0)))
                if not solver.frozen:
                    gap = gaps[:, r].copy()
                    check_outside(contact, gap, travel[k])
                    gap[candidates[solver.active]] = 0.0
                    worst[r] = max(worst[r], float(-gap.min()))
    return [
        ContactRun.dynamic(travel, dt, hub[r], points[r], on_profile[r], speed, bool(frozen[r]), worst[r], most[r])
        for r in range(runs)
    ]


def _node_spacing(tire: LoadedTire, state: StaticState) -> float:
    """The smallest distance along the drum from a contact node to the next ring's node of its column (m)."""
    arcs = drum_arcs(tire, state)
    ring, column = np.nonzero(np.isin(tire.tread.reshape(arcs.shape), state.contact))
    return float(np.min(np.abs(arcs[(ring + 1) % arcs.shape[0], column] - arcs[ring, column])))


def check_outside(contact: CleatContact, gap: np.ndarray, travel: float) -> None:
    """Refuse a step in which a watched node that is not a candidate penetrates the drum (``gap`` (W,), m):
    the candidates' :data:`MARGIN` missed a node the tire's motion brings down."""
    outside = gap[~contact.candidate]
    if outside.size and outside.min() < 0.0:
        raise RuntimeError(
            f"at travel {travel:.4f} m a tread node left out of the contact candidates penetrates the drum by "
            f"{-outside.min() * 1e3:.3f} mm: the candidates' margin ({MARGIN * 1e3:.0f} mm) is too small for this run"
        )


def footprint_road_motion(tire: LoadedTire, state: StaticState, profile, travel: np.ndarray) -> np.ndarray:
    """The vertical road motion under each contact node of ``state`` (in its order) that raises the drum
    along the node's normal by the profile's height there, (P, n_travel) m: the inputs of the footprint
    FRFs (per unit vertical road motion) for the frozen contact."""
    _check_state(state)
    contact = cleat_contact(tire, state, profile, travel)
    where = {int(node): i for i, node in enumerate(contact.watched)}
    rows = np.array([where[int(node)] for node in state.contact])
    return contact.heights[rows] / contact.normals[rows, 1:]
