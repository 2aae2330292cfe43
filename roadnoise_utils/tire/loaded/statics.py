"""Large-deformation statics of the loaded tire: the potential, its Newton iterations on the supports, inflation.

Equilibrium is the stationary point of the total potential energy

.. math:: \\Pi(u) = \\int W(E(u))\\,dV_0 - p\\,V(u),

the layers' strain energy (:mod:`.material`) less the work of the follower pressure on the
cavity volume (:mod:`.pressure`), the beads held on the rim. Newton's method solves
:math:`\\nabla\\Pi = 0` with the consistent tangent (material, geometric and pressure load
stiffness) and a backtracking line search on :math:`\\Pi` (Armijo), so a step never raises the
energy (Wriggers, *Nonlinear Finite Element Methods*, 2008, ch. 5).

What holds the tire is a :class:`Supports`: the rim alone (:class:`Rim`, the inflation) or the rim
and a road (:class:`.road_contact.RoadContact`: frictionless one-sided contact with the flat road or
a drum, its active set updated inside Newton's iterations once the out-of-balance force is small).
A support may hold a DOF along a direction of its own (a drum's normal): each iteration is solved
in the supports' frame (:class:`LocalSystem`). Held DOF that must move to meet their constraints
move by a predictor, the free DOF following by the tangent, so a road step of millimetres does not
distort the elements at the footprint's edge alone; no step is accepted that inverts a point of
the mesh. Once the held set no longer changes, the iterations are Newton's on fixed constraints
and converge quadratically.

Each Newton iteration solves the tangent of the free DOF by its sparse symmetric factor
(:class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
import scipy.sparse as sp

from ... import guards
from ..cross_section.geometry import section_mesh
from ..cross_section.spec import CrossSectionSpec
from ..surface import RoadSurface
from ..symmetric_factor import SymmetricFactor
from . import material, pressure, solid
from .mesh import SolidMesh, sweep

#: The road of a state not yet loaded.
FLAT_ROAD = RoadSurface("flat")
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
#: The contact set is updated once the out-of-balance force is below this fraction of the applied forces:
#: early, so that the nodes a road step brings in join while Newton is still converging (on the production
#: mesh's drum loading 95 iterations at 1e-1 or at every iteration, 109 at 1e-3, the same state to 2e-14 m).
ACTIVE_SET_TOLERANCE = 1e-1
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

    @property
    def rim_vertical(self) -> np.ndarray:
        """The vertical DOF of the rim's nodes (the beads held on the rim): they move with the hub, as one."""
        return 3 * np.unique(self.fixed // 3) + 2


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
        How far the road was raised from touching the inflated tread (m); 0 before loading.
    contact : ndarray of int
        Tread nodes held on the road.
    reactions : ndarray (n_dof,)
        Forces of the rim and the road on the tire (N, global axes): the out-of-balance force at
        the held DOF, zero elsewhere (on a drum a contact node's force is along the drum's normal).
    history : list of list of list of float
        Per load step and per contact set (one for inflation), the out-of-balance force of the
        free DOF at each Newton iteration, relative to the applied forces.
    stable : bool or None
        Whether the state is a minimum of the potential with its supports and contact set held
        (:func:`.road_contact.is_stable`); ``None`` when not checked.
    road : RoadSurface
        The flat road or the drum it stands on.
    road_top : float
        Height of the road's highest point (m; a drum's top, under the axle); NaN before loading.
    """

    u: np.ndarray
    pressure: float
    road_lift: float = 0.0
    contact: np.ndarray = field(default_factory=lambda: np.zeros(0, int))
    reactions: np.ndarray | None = None
    history: list = field(default_factory=list)
    stable: bool | None = None
    road: RoadSurface = FLAT_ROAD
    road_top: float = float("nan")

    @property
    def road_force(self) -> float:
        """Vertical force of the road on the tire (N, upward positive): the load carried."""
        return float(self.reactions[3 * self.contact + 2].sum()) if self.contact.size else 0.0


def solve_tangent(matrix: sp.spmatrix, rhs: np.ndarray) -> np.ndarray:
    """``matrix``:math:`^{-1}` ``rhs`` for a symmetric tangent of the free DOF, definite or not (an
    intermediate Newton state, the pressure's load stiffness ahead of the pre-stress it builds):
    :class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor`."""
    return SymmetricFactor(matrix, require_definite=False).solve(rhs)


@dataclass(frozen=True, eq=False)
class LocalSystem:
    """The Newton system of one iteration in the supports' frame.

    A support may hold a DOF along a direction of its own (the drum's normal at a contact node): the
    global DOF ``u = T ũ`` (``frame`` ``T``, orthogonal; ``None``: the global axes), the held local DOF
    move by ``moves``, and the tangent holds the constraints' curvature (the Hessian of the Lagrangian).

    Attributes
    ----------
    frame : csr_matrix or None
    held : ndarray of int
        Held local DOF.
    moves : ndarray
        How far each held DOF must move to meet its constraint (m).
    residual : ndarray
        Out-of-balance force in the frame (N).
    tangent : csr_matrix
        Tangent in the frame (N/m).
    """

    frame: sp.csr_matrix | None
    held: np.ndarray
    moves: np.ndarray
    residual: np.ndarray
    tangent: sp.csr_matrix

    def to_global(self, local: np.ndarray) -> np.ndarray:
        return local if self.frame is None else self.frame @ local

    def reactions(self) -> np.ndarray:
        """Forces of the supports on the tire (N, global): the out-of-balance force at the held DOF."""
        held = np.zeros(self.residual.size)
        held[self.held] = self.residual[self.held]
        return self.to_global(held)


class Supports(Protocol):
    """What holds the tire in a static solve: the rim alone, or the rim and a road (:mod:`.road_contact`)."""

    def local(self, u: np.ndarray, r: np.ndarray, k: sp.csr_matrix) -> LocalSystem:
        """The Newton system at ``u`` (out-of-balance ``r``, tangent ``k``, global) in the supports' frame."""

    def update(self, u: np.ndarray, system: LocalSystem) -> bool:
        """Change the held set (the contact set) at a near-equilibrium ``u``; whether it changed."""


class Rim:
    """The beads held on the rim: every DOF of the bead stations at zero displacement."""

    def __init__(self, tire: LoadedTire):
        self.fixed = tire.fixed

    def local(self, u: np.ndarray, r: np.ndarray, k: sp.csr_matrix) -> LocalSystem:
        return LocalSystem(frame=None, held=self.fixed, moves=-u[self.fixed], residual=r, tangent=k)

    def update(self, u: np.ndarray, system: LocalSystem) -> bool:
        return False


def newton(
    tire: LoadedTire, u: np.ndarray, p: float, supports: Supports, scale: float
) -> tuple[np.ndarray, list[list[float]], LocalSystem]:
    """Newton iterations to equilibrium with the ``supports``' DOF held.

    An iteration that moves held DOF to meet their constraints moves the free ones by the tangent
    at ``u`` (a predictor: imposed on the held DOF alone, a road step of millimetres distorts the
    elements at the footprint's edge into a state whose tangent is indefinite). ``supports.update``,
    called once the out-of-balance force is below :data:`ACTIVE_SET_TOLERANCE` and the constraints
    are met, may change the held set (the contact set); the iterations end at equilibrium with the
    set unchanged, so once it settles they are Newton's on fixed constraints.

    Returns
    -------
    u : ndarray
        The equilibrium (m).
    history : list of list of float
        The out-of-balance force of the free DOF relative to ``scale`` at each iteration, one list
        per held set (a new list when ``update`` changes it).
    system : LocalSystem
        The last iteration's system (its tangent and the supports' reactions at ``u``).
    """
    u = u.copy()
    history, updates, tiny_step = [[]], 0, False
    for _ in range(MAX_ITERATIONS):
        r, k = residual_and_tangent(tire, u, p)
        system = supports.local(u, r, k)
        free = np.setdiff1d(np.arange(tire.n_dof), system.held)
        size = np.linalg.norm(system.residual[free]) / scale
        history[-1].append(size)
        converged = tiny_step or size < TOLERANCE
        moving = _moving(system, u)
        if not moving and size < ACTIVE_SET_TOLERANCE and supports.update(u, system):
            updates += 1
            if updates > MAX_ACTIVE_SET_UPDATES:
                raise RuntimeError(
                    f"the contact set did not settle in {MAX_ACTIVE_SET_UPDATES} updates: take more load steps"
                )
            system = supports.local(u, r, k)
            free = np.setdiff1d(np.arange(tire.n_dof), system.held)
            moving, converged, tiny_step = _moving(system, u), False, False
            history.append([])
        if converged and not moving:
            return u, history, system
        step = np.zeros(tire.n_dof)
        k_free = system.tangent[free]
        if moving:
            step[system.held] = system.moves
            step[free] = solve_tangent(k_free[:, free], -system.residual[free] - k_free[:, system.held] @ system.moves)
            step = system.to_global(step)
            u = u + _admissible_part(tire, u, step) * step
            continue
        step[free] = solve_tangent(k_free[:, free], -system.residual[free])
        step = system.to_global(step)
        tiny_step = np.abs(step).max() <= STEP_TOLERANCE * np.abs(u).max()
        u = u + step if tiny_step else _line_search(tire, u, step, r, p)
    raise RuntimeError(
        f"the static solve did not converge in {MAX_ITERATIONS} Newton iterations (out-of-balance "
        f"{size:.3g} of the load): take smaller load steps"
    )


def _moving(system: LocalSystem, u: np.ndarray) -> bool:
    """Whether a held DOF must still move to meet its constraint (beyond the round-off of ``u``)."""
    return bool(system.moves.size and np.abs(system.moves).max() > STEP_TOLERANCE * np.abs(u).max())


def admissible(tire: LoadedTire, u: np.ndarray) -> bool:
    """Whether the displacements ``u`` invert no point of the mesh (``det F > 0`` everywhere)."""
    try:
        for group in tire.groups:
            solid.deformation_gradient(group, u)
    except FloatingPointError:
        return False
    return True


def _admissible_part(tire: LoadedTire, u: np.ndarray, step: np.ndarray) -> float:
    """The largest of 1, 1/2, 1/4... of ``step`` that inverts no point of the mesh."""
    part = 1.0
    for _ in range(12):
        if admissible(tire, u + part * step):
            return part
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
        u, steps_history, system = newton(tire, u, level, Rim(tire), scale)
        history.append(steps_history)
    return StaticState(u=u, pressure=p, reactions=system.reactions(), history=history)
