"""Large-deformation statics of the loaded tire: inflation, then the road pressed against it.

Equilibrium is the stationary point of the total potential energy

.. math:: \\Pi(u) = \\int W(E(u))\\,dV_0 - p\\,V(u),

the layers' strain energy (:mod:`.material`) less the work of the follower pressure on the
cavity volume (:mod:`.pressure`), the beads held on the rim. Newton's method solves
:math:`\\nabla\\Pi = 0` with the consistent tangent (material, geometric and pressure load
stiffness) and a backtracking line search on :math:`\\Pi` (Armijo), so a step never raises the
energy (Wriggers, *Nonlinear Finite Element Methods*, 2008, ch. 5).

Contact with the flat road is frictionless and one-sided on the tread surface's nodes: a node
below the road is held on it (its vertical displacement prescribed), a held node that the road
pulls is released. The active set is updated inside Newton's iterations once the out-of-balance
force is small (a primal-dual active set: Hintermüller, Ito & Kunisch, SIAM J. Optim. 13, 2003);
once it no longer changes, the iterations are those of Newton's method on a fixed set of
constraints and converge quadratically. Newly held nodes reach the road by a predictor, the
free DOF following by the tangent, so a road step of millimetres does not distort the elements at
the footprint's edge alone; no step is accepted that inverts a point of the mesh.

Each Newton iteration solves the tangent of the free DOF by a banded Cholesky factor
(:class:`~roadnoise_utils.tire.banded.BandedCholesky`), about two rings of nodes wide.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ... import guards
from ..banded import BandedCholesky
from ..cross_section.geometry import section_mesh
from ..cross_section.spec import CrossSectionSpec
from . import material, pressure, solid
from .mesh import SolidMesh, sweep

#: Newton stops when the out-of-balance force is below this fraction of the applied forces, or
#: when its correction moves no node by more than :data:`STEP_TOLERANCE` of the largest
#: displacement (the round-off floor: the internal forces are sums of ply stresses many times
#: the net force, e.g. in the steel belts).
TOLERANCE = 1e-9
STEP_TOLERANCE = 1e-11
#: Newton iterations allowed per load step.
MAX_ITERATIONS = 30
#: Updates of the contact set allowed per load step.
MAX_ACTIVE_SET_UPDATES = 20
#: The contact set is updated once the out-of-balance force is below this fraction of the applied forces.
ACTIVE_SET_TOLERANCE = 1e-3
#: A free tread node joins the contact set when below the road by more than this fraction of the lift.
GAP_TOLERANCE = 1e-9


@dataclass(frozen=True, eq=False)
class LoadedTire:
    """A tire file's cross-section swept into solids: what every static and dynamic solve needs.

    Attributes
    ----------
    spec : CrossSectionSpec
    mesh : SolidMesh
    groups : list of solid.ElementGroup
        The stiffness's integration points.
    surface : pressure.InnerSurface
    fixed : ndarray of int
        DOF held on the rim (every DOF of the bead stations).
    tread : ndarray of int
        Nodes of the tread surface (candidates for contact).
    """

    spec: CrossSectionSpec
    mesh: SolidMesh
    groups: list
    surface: pressure.InnerSurface
    fixed: np.ndarray
    tread: np.ndarray

    @property
    def n_dof(self) -> int:
        return self.mesh.n_dof


def build_loaded_tire(spec: CrossSectionSpec, arcs: np.ndarray) -> LoadedTire:
    """Sweep the tire file's cross-section (its own mesh settings) through ``arcs`` (rad, see :func:`.mesh.graded_arcs`)."""
    section, _ = section_mesh(spec)
    mesh = sweep(section, arcs)
    n_elements = mesh.elements.shape[0]
    guards.check_memory(  # the tangent's assembly: row, column and value of every element entry, then CSR
        n_elements * 81**2 * 8.0 * 4, f"the tangent of {n_elements} solid elements", "arcs"
    )
    rings = np.arange(mesh.theta.size)
    outer = section.node(np.arange(section.n_stations), section.n_rows - 1)
    return LoadedTire(
        spec=spec,
        mesh=mesh,
        groups=solid.element_groups(mesh, spec),
        surface=pressure.inner_surface(mesh),
        fixed=np.unique((3 * mesh.bead_nodes[:, None] + np.arange(3)).ravel()),
        tread=np.ravel(mesh.node(rings[:, None], outer[None, :])),
    )


def strain_energy(tire: LoadedTire, u: np.ndarray) -> float:
    """Strain energy (J) of the displacement ``u``."""
    total = 0.0
    for group in tire.groups:
        green = solid.green_strain(solid.deformation_gradient(group, u))
        total += float(np.sum(material.energy(green, group.materials) * group.volume))
    return total


def potential(tire: LoadedTire, u: np.ndarray, p: float) -> float:
    """Total potential energy (J): strain energy less the pressure's work ``p V``."""
    return strain_energy(tire, u) - p * pressure.cavity_volume(tire.mesh, tire.surface, u)


def residual_and_tangent(tire: LoadedTire, u: np.ndarray, p: float) -> tuple[np.ndarray, sp.csr_matrix]:
    """Out-of-balance force :math:`\\nabla\\Pi` (N) and its derivative (N/m) at ``u``, pressure ``p`` (Pa)."""
    force, k = solid.assemble(tire.groups, u, tire.n_dof)
    load = pressure.pressure_load(tire.mesh, tire.surface, u, p)
    k = k - pressure.pressure_stiffness(tire.mesh, tire.surface, u, p)
    return force - load, k.tocsr()


@dataclass
class StaticState:
    """An equilibrium of the loaded tire.

    Attributes
    ----------
    u : ndarray (n_dof,)
        Displacement (m).
    pressure : float
        Pa.
    road_lift : float
        How far the road was raised from touching the undeformed tread (m); 0 before loading.
    contact : ndarray of int
        Tread nodes held on the road.
    reactions : ndarray (n_dof,)
        Forces of the rim and the road on the tire (N): minus the out-of-balance force at the
        held DOF, zero elsewhere.
    history : list of list of list of float
        Per load step and per contact set (one for inflation), the out-of-balance force of the
        free DOF at each Newton iteration, relative to the applied forces.
    stable : bool or None
        Whether the state is a minimum of the potential with its supports and contact set held
        (:func:`is_stable`); ``None`` when not checked.
    """

    u: np.ndarray
    pressure: float
    road_lift: float = 0.0
    contact: np.ndarray = field(default_factory=lambda: np.zeros(0, int))
    reactions: np.ndarray | None = None
    history: list = field(default_factory=list)
    stable: bool | None = None

    @property
    def road_force(self) -> float:
        """Vertical force of the road on the tire (N, upward positive): the load carried."""
        return float(self.reactions[3 * self.contact + 2].sum()) if self.contact.size else 0.0


def solve_tangent(matrix: sp.spmatrix, rhs: np.ndarray) -> np.ndarray:
    """``matrix``:math:`^{-1}` ``rhs`` for a symmetric tangent of the free DOF.

    The tangent of a stable state is positive definite: a banded Cholesky factor after reverse
    Cuthill-McKee (:class:`~roadnoise_utils.tire.banded.BandedCholesky`; the closed circumference's
    band is about two rings of nodes wide). A tangent that is not (an intermediate Newton state,
    the pressure's load stiffness ahead of the pre-stress it builds) falls back to SuperLU.
    """
    try:
        return BandedCholesky(matrix).solve(rhs)
    except np.linalg.LinAlgError:
        return spla.spsolve(sp.csc_matrix(matrix), rhs)


def held_dof(tire: LoadedTire, contact: np.ndarray) -> np.ndarray:
    """DOF held in a loaded state: every DOF of the rim's nodes, the vertical DOF of the ``contact`` nodes."""
    return np.concatenate([tire.fixed, 3 * np.asarray(contact, int) + 2])


def is_stable(tire: LoadedTire, state: StaticState, tangent: sp.spmatrix | None = None) -> bool:
    """Whether ``state`` is a minimum of the potential, the rim and the contact nodes' heights held.

    Newton's method finds any stationary point; a saddle is an equilibrium the tire would leave
    (e.g. the cord plies compressed in the footprint buckling). The tangent of the free DOF is
    positive definite at a minimum: its Cholesky factor exists. ``tangent``: the tangent at
    ``state`` if already assembled (the last Newton iteration's), else it is assembled here.
    """
    k = residual_and_tangent(tire, state.u, state.pressure)[1] if tangent is None else sp.csr_matrix(tangent)
    free = np.setdiff1d(np.arange(tire.n_dof), held_dof(tire, state.contact))
    try:
        BandedCholesky(k[free][:, free])
    except np.linalg.LinAlgError:
        return False
    return True


def newton(
    tire: LoadedTire,
    u: np.ndarray,
    p: float,
    held: np.ndarray,
    held_values: np.ndarray,
    scale: float,
    update: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray] | None] | None = None,
) -> tuple[np.ndarray, list[list[float]]]:
    """Newton iterations to equilibrium with the DOF ``held`` at ``held_values``.

    An iteration that moves held DOF to new values moves the free ones by the tangent at ``u``
    (a predictor: imposed on the held DOF alone, a road step of millimetres distorts the
    elements at the footprint's edge into a state whose tangent is indefinite). ``update(u, r)``,
    called once the out-of-balance force ``r`` is below :data:`ACTIVE_SET_TOLERANCE`, gives new
    held DOF and values (the contact set) or ``None`` to keep them; the iterations end at
    equilibrium with the set unchanged, so once it settles they are Newton's on fixed constraints.

    Returns
    -------
    u : ndarray
        The equilibrium (m).
    history : list of list of float
        The out-of-balance force of the free DOF relative to ``scale`` at each iteration, one list
        per held set (a new list when ``update`` changes it).
    tangent : scipy.sparse.csr_matrix
        The tangent at ``u`` (N/m), all DOF: the last iteration's.
    """
    u = u.copy()
    free = np.setdiff1d(np.arange(tire.n_dof), held)
    moved = np.asarray(held_values, float) - u[held]
    history, updates, tiny_step = [[]], 0, False
    for _ in range(MAX_ITERATIONS):
        r, k = residual_and_tangent(tire, u, p)
        size = np.linalg.norm(r[free]) / scale
        history[-1].append(size)
        converged = tiny_step or size < TOLERANCE
        if update is not None and not moved.any() and size < ACTIVE_SET_TOLERANCE:
            changed = update(u, r)
            if changed is not None:
                updates += 1
                if updates > MAX_ACTIVE_SET_UPDATES:
                    raise RuntimeError(
                        f"the contact set did not settle in {MAX_ACTIVE_SET_UPDATES} updates: take more load steps"
                    )
                held, held_values = changed
                free = np.setdiff1d(np.arange(tire.n_dof), held)
                moved = np.asarray(held_values, float) - u[held]
                converged = tiny_step = False
                history.append([])
        if converged and not moved.any():
            return u, history, k
        step = np.zeros(tire.n_dof)
        k_free = k[free]
        if moved.any():
            step[held] = moved
            step[free] = solve_tangent(k_free[:, free], -r[free] - k_free[:, held] @ moved)
            part = _admissible_part(tire, u, step)
            u, moved = u + part * step, (1.0 - part) * moved
            continue
        step[free] = solve_tangent(k_free[:, free], -r[free])
        tiny_step = np.abs(step).max() <= STEP_TOLERANCE * np.abs(u).max()
        u = u + step if tiny_step else _line_search(tire, u, step, r, p)
    raise RuntimeError(
        f"the static solve did not converge in {MAX_ITERATIONS} Newton iterations (out-of-balance "
        f"{size:.3g} of the load): take smaller load steps"
    )


def _admissible_part(tire: LoadedTire, u: np.ndarray, step: np.ndarray) -> float:
    """The largest of 1, 1/2, 1/4... of ``step`` that inverts no point of the mesh."""
    part = 1.0
    for _ in range(12):
        try:
            for group in tire.groups:
                solid.deformation_gradient(group, u + part * step)
            return part
        except FloatingPointError:
            part *= 0.5
    raise FloatingPointError("the road's step inverts the mesh however it is divided: take smaller load steps")


def _line_search(tire: LoadedTire, u: np.ndarray, step: np.ndarray, r: np.ndarray, p: float) -> np.ndarray:
    """``u + a step`` with the largest ``a`` of 1, 1/2, 1/4... that lowers the potential enough (Armijo)."""
    slope = float(r @ step)
    start = potential(tire, u, p)
    # not a descent direction (an indefinite tangent), or a change of energy below the potential's
    # round-off (near equilibrium): the Newton step, shortened only where it would invert the mesh
    if slope >= 0.0 or -slope < 1e-12 * (strain_energy(tire, u) + abs(start)):
        return u + _admissible_part(tire, u, step) * step
    a = 1.0
    for _ in range(12):
        try:
            if potential(tire, u + a * step, p) <= start + 1e-4 * a * slope:
                return u + a * step
        except FloatingPointError:  # an inverted point: the step is far too long
            pass
        a *= 0.5
    return u + _admissible_part(tire, u, a * step) * a * step


def inflate(tire: LoadedTire, p: float | None = None, steps: int = 1) -> StaticState:
    """Inflate the mounted tire to ``p`` (Pa; default the file's) in ``steps`` equal pressure steps."""
    p = tire.spec.operating.inflation_pressure if p is None else float(p)
    if not p > 0.0:
        raise ValueError(f"inflation pressure = {p!r} Pa: give a positive pressure")
    steps = guards.integer("steps", steps, 1)
    u = np.zeros(tire.n_dof)
    history = []
    for level in np.linspace(p / steps, p, steps):
        scale = np.linalg.norm(pressure.pressure_load(tire.mesh, tire.surface, u, level))
        u, steps_history, _ = newton(tire, u, level, tire.fixed, np.zeros(tire.fixed.size), scale)
        history.append(steps_history)
    return StaticState(u=u, pressure=p, reactions=_reactions(tire, u, p, tire.fixed), history=history)


def _reactions(tire: LoadedTire, u: np.ndarray, p: float, held: np.ndarray) -> np.ndarray:
    """Forces of the supports on the tire at the ``held`` DOF: the out-of-balance force there."""
    r = solid.internal_force(tire.groups, u, tire.n_dof) - pressure.pressure_load(tire.mesh, tire.surface, u, p)
    reactions = np.zeros(tire.n_dof)
    reactions[held] = r[held]
    return reactions


def tread_heights(tire: LoadedTire, u: np.ndarray) -> np.ndarray:
    """Height ``z`` (m) of every tread node displaced by ``u``."""
    return tire.mesh.coordinates[tire.tread, 2] + u[3 * tire.tread + 2]


class _RoadContact:
    """The tread nodes held on a flat road at height ``road`` (m), and their primal-dual update."""

    def __init__(self, tire: LoadedTire, road: float, gap_tolerance: float, active: np.ndarray):
        self.tire, self.road, self.gap_tolerance, self.active = tire, road, gap_tolerance, active

    def constraints(self) -> tuple[np.ndarray, np.ndarray]:
        """Held DOF (the rim's, the contact nodes' vertical) and their displacements (m)."""
        tire = self.tire
        held = held_dof(tire, self.active)
        heights = self.road - tire.mesh.coordinates[self.active, 2]
        return held, np.concatenate([np.zeros(tire.fixed.size), heights])

    def update(self, u: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        """Release the held nodes the road pulls, hold the free ones below it; ``None`` if none."""
        pulled = self.active[r[3 * self.active + 2] < 0.0]
        below = self.tire.tread[tread_heights(self.tire, u) < self.road - self.gap_tolerance]
        below = np.setdiff1d(below, self.active)
        if not pulled.size and not below.size:
            return None
        self.active = np.union1d(np.setdiff1d(self.active, pulled), below)
        return self.constraints()


def press_on_flat_road(
    tire: LoadedTire, inflated: StaticState, lift: float, steps: int = 4, start: StaticState | None = None
) -> StaticState:
    """The flat road raised ``lift`` (m) from touching the inflated tread, in ``steps`` equal steps; rim held.

    Each step's contact set is found by a primal-dual active set: tread nodes below the road are
    held on it, held nodes the road pulls down are released, until the set no longer changes.
    The final state's stability is checked (:func:`is_stable`); a saddle gets a
    :class:`~roadnoise_utils.guards.RoadnoiseWarning`.
    ``start``: a loaded state of the same inflation to continue from (its lift and contact set)
    instead of the inflated tire.
    """
    lift = guards.real("lift", lift, 0.0, lo_open=True, unit="m")
    steps = guards.integer("steps", steps, 1)
    touch = float(tread_heights(tire, inflated.u).min())
    rim = float(tire.mesh.coordinates[tire.mesh.bead_nodes, 2].min()) - touch  # the rim's lowest point above the road
    if lift >= rim:
        raise ValueError(
            f"lift = {lift!r} m: valid range is (0, {rim:.4g}) m; the road would reach the rim (the tire bottoms)"
        )
    if start is not None and start.pressure != inflated.pressure:
        raise ValueError(f"start is a state at {start.pressure:g} Pa, the inflated tire at {inflated.pressure:g} Pa")
    begin = inflated if start is None else start
    u, p = begin.u.copy(), inflated.pressure
    history = list(begin.history)
    active = begin.contact.copy()
    for level in np.linspace(begin.road_lift + (lift - begin.road_lift) / steps, lift, steps):
        road = touch + level
        active = np.union1d(active, tire.tread[tread_heights(tire, u) < road])
        contact = _RoadContact(tire, road, GAP_TOLERANCE * lift, active)
        scale = np.linalg.norm(pressure.pressure_load(tire.mesh, tire.surface, u, p))
        u, step_history, tangent = newton(tire, u, p, *contact.constraints(), scale, update=contact.update)
        history.append(step_history)
        active = contact.active
    held = held_dof(tire, active)
    state = StaticState(
        u=u, pressure=p, road_lift=lift, contact=active, reactions=_reactions(tire, u, p, held), history=history
    )
    state.stable = is_stable(tire, state, tangent)
    if not state.stable:
        guards.warn(
            f"the loaded state at a lift of {lift * 1e3:.3g} mm ({state.road_force:.0f} N) is a saddle of the "
            "potential, not a minimum: its tangent has a negative direction (e.g. the cord plies compressed in "
            "the footprint buckling between the nodes), so its stiffness and footprint are those of an "
            "equilibrium the tire would leave; lower the load"
        )
    return state


def vertical_stiffness(tire: LoadedTire, state: StaticState) -> float:
    r"""Tangent vertical stiffness (N/m) of a loaded state: the road's force per road lift, contact set held.

    The condensed tangent: the road's DOF moved by one, the free DOF in equilibrium,
    :math:`K_v = \sum_{road} (K_{rr} + K_{rf} \Delta u_f)` with :math:`K_{ff}\Delta u_f = -K_{fr} 1`.
    """
    _, k = residual_and_tangent(tire, state.u, state.pressure)
    road = 3 * state.contact + 2
    free = np.setdiff1d(np.arange(tire.n_dof), held_dof(tire, state.contact))
    moved = np.asarray(k[free][:, road].sum(axis=1)).ravel()
    du = solve_tangent(k[free][:, free], -moved)
    return float(k[road][:, road].sum() + np.asarray(k[road][:, free] @ du).sum())
