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
pulls is released. The active set is updated between Newton iterations (a primal-dual active
set: Hintermüller, Ito & Kunisch, SIAM J. Optim. 13, 2003); once it no longer changes, the
iterations are those of Newton's method on a fixed set of constraints and converge
quadratically.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

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
    history : list of list of float
        Per load step, the out-of-balance force of the free DOF after each Newton iteration,
        relative to the applied forces.
    """

    u: np.ndarray
    pressure: float
    road_lift: float = 0.0
    contact: np.ndarray = field(default_factory=lambda: np.zeros(0, int))
    reactions: np.ndarray | None = None
    history: list = field(default_factory=list)

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


def newton(
    tire: LoadedTire,
    u: np.ndarray,
    p: float,
    held: np.ndarray,
    held_values: np.ndarray,
    scale: float,
) -> tuple[np.ndarray, list[float]]:
    """Newton iterations to equilibrium with the DOF ``held`` at ``held_values``; returns ``u`` and the residual history."""
    u = u.copy()
    u[held] = held_values
    free = np.setdiff1d(np.arange(tire.n_dof), held)
    history = []
    for _ in range(MAX_ITERATIONS):
        r, k = residual_and_tangent(tire, u, p)
        size = np.linalg.norm(r[free]) / scale
        history.append(size)
        if size < TOLERANCE:
            return u, history
        step = np.zeros(tire.n_dof)
        step[free] = solve_tangent(k[free][:, free], -r[free])
        if np.abs(step).max() <= STEP_TOLERANCE * np.abs(u).max():
            return u + step, history
        u = _line_search(tire, u, step, r, p)
    raise RuntimeError(
        f"the static solve did not converge in {MAX_ITERATIONS} Newton iterations (out-of-balance "
        f"{history[-1]:.3g} of the load): take smaller load steps"
    )


def _line_search(tire: LoadedTire, u: np.ndarray, step: np.ndarray, r: np.ndarray, p: float) -> np.ndarray:
    """``u + a step`` with the largest ``a`` of 1, 1/2, 1/4... that lowers the potential enough (Armijo)."""
    slope = float(r @ step)
    start = potential(tire, u, p)
    # not a descent direction (an indefinite tangent), or a change of energy below the potential's
    # round-off (near equilibrium): the Newton step as it is
    if slope >= 0.0 or -slope < 1e-12 * (strain_energy(tire, u) + abs(start)):
        return u + step
    a = 1.0
    for _ in range(12):
        try:
            if potential(tire, u + a * step, p) <= start + 1e-4 * a * slope:
                return u + a * step
        except FloatingPointError:  # an inverted point: the step is far too long
            pass
        a *= 0.5
    return u + a * step


def inflate(tire: LoadedTire, p: float | None = None, steps: int = 1) -> StaticState:
    """Inflate the mounted tire to ``p`` (Pa; default the file's) in ``steps`` equal pressure steps."""
    p = tire.spec.operating.inflation_pressure if p is None else float(p)
    if not p > 0.0:
        raise ValueError(f"inflation pressure = {p!r} Pa: give a positive pressure")
    u = np.zeros(tire.n_dof)
    history = []
    for level in np.linspace(p / steps, p, steps):
        scale = np.linalg.norm(pressure.pressure_load(tire.mesh, tire.surface, u, level))
        u, steps_history = newton(tire, u, level, tire.fixed, np.zeros(tire.fixed.size), scale)
        history.append(steps_history)
    return StaticState(u=u, pressure=p, reactions=_reactions(tire, u, p, tire.fixed), history=history)


def _reactions(tire: LoadedTire, u: np.ndarray, p: float, held: np.ndarray) -> np.ndarray:
    """Forces of the supports on the tire at the ``held`` DOF: the out-of-balance force there."""
    r, _ = residual_and_tangent(tire, u, p)
    reactions = np.zeros(tire.n_dof)
    reactions[held] = r[held]
    return reactions


def tread_heights(tire: LoadedTire, u: np.ndarray) -> np.ndarray:
    """Height ``z`` (m) of every tread node displaced by ``u``."""
    return tire.mesh.coordinates[tire.tread, 2] + u[3 * tire.tread + 2]


def press_on_flat_road(
    tire: LoadedTire, inflated: StaticState, lift: float, steps: int = 4, start: StaticState | None = None
) -> StaticState:
    """The flat road raised ``lift`` (m) from touching the inflated tread, in ``steps`` equal steps; rim held.

    Each step's contact set is found by a primal-dual active set: tread nodes below the road are
    held on it, held nodes the road pulls down are released, until the set no longer changes.
    ``start``: a loaded state of the same inflation to continue from (its lift and contact set)
    instead of the inflated tire.
    """
    if not lift > 0.0:
        raise ValueError(f"lift = {lift!r} m: give a positive road displacement")
    touch = float(tread_heights(tire, inflated.u).min())
    begin = inflated if start is None else start
    u, p = begin.u.copy(), inflated.pressure
    history = list(begin.history)
    active = begin.contact.copy()
    for level in np.linspace(begin.road_lift + (lift - begin.road_lift) / steps, lift, steps):
        road = touch + level
        active = np.union1d(active, tire.tread[tread_heights(tire, u) < road])
        for _ in range(MAX_ACTIVE_SET_UPDATES):
            held = np.concatenate([tire.fixed, 3 * active + 2])
            values = np.concatenate([np.zeros(tire.fixed.size), road - tire.mesh.coordinates[active, 2]])
            scale = np.linalg.norm(pressure.pressure_load(tire.mesh, tire.surface, u, p))
            u, step_history = newton(tire, u, p, held, values, scale)
            r, _ = residual_and_tangent(tire, u, p)
            pulled = active[r[3 * active + 2] < 0.0]
            below = tire.tread[tread_heights(tire, u) < road - GAP_TOLERANCE * lift]
            below = np.setdiff1d(below, active)
            if not pulled.size and not below.size:
                break
            active = np.union1d(np.setdiff1d(active, pulled), below)
        else:
            raise RuntimeError(f"the contact set did not settle in {MAX_ACTIVE_SET_UPDATES} updates: take more steps")
        history.append(step_history)
    held = np.concatenate([tire.fixed, 3 * active + 2])
    return StaticState(
        u=u, pressure=p, road_lift=lift, contact=active, reactions=_reactions(tire, u, p, held), history=history
    )


def vertical_stiffness(tire: LoadedTire, state: StaticState) -> float:
    r"""Tangent vertical stiffness (N/m) of a loaded state: the road's force per road lift, contact set held.

    The condensed tangent: the road's DOF moved by one, the free DOF in equilibrium,
    :math:`K_v = \sum_{road} (K_{rr} + K_{rf} \Delta u_f)` with :math:`K_{ff}\Delta u_f = -K_{fr} 1`.
    """
    _, k = residual_and_tangent(tire, state.u, state.pressure)
    road = 3 * state.contact + 2
    free = np.setdiff1d(np.arange(tire.n_dof), np.concatenate([tire.fixed, road]))
    moved = np.asarray(k[free][:, road].sum(axis=1)).ravel()
    du = solve_tangent(k[free][:, free], -moved)
    return float(k[road][:, road].sum() + np.asarray(k[road][:, free] @ du).sum())
