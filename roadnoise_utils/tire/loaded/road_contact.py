"""Frictionless one-sided contact of the tread with the flat road or a drum, in the statics' Newton iterations.

A tread node in contact stays on the surface and slides freely along it: its displacement along
the surface's normal is held (at the surface), the two along it are free. On the flat road the
normal is vertical and the held DOF is the node's own ``z``. On a drum of radius ``R`` (its axis
along ``y``, under the axle) the normal at a node runs from the axis through the node, so each
contact node's ``x``/``z`` pair is turned into its tangent and normal DOF (:class:`RoadContact`'s
frame, built at every iteration), and the tangent gains the constraint's curvature: with the
node's contact force ``lambda`` along the normal, the Hessian of the Lagrangian
:math:`\\Pi - \\lambda (\\rho - R)` adds :math:`-\\lambda / R` along the tangent (Wriggers,
*Computational Contact Mechanics*, 2006, ch. 4: the convex drum lets a pressed node slide off
more easily than a flat road). With it Newton's iterations stay quadratic on the drum.

The active set is primal-dual (:mod:`.statics`): a free node inside the surface is held, a held
node the surface pulls is released.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ... import guards
from ..surface import RoadSurface
from ..symmetric_factor import SymmetricFactor
from . import pressure
from .statics import (
    FLAT_ROAD,
    GAP_TOLERANCE,
    LoadedTire,
    LocalSystem,
    Rim,
    StaticState,
    admissible,
    newton,
    residual_and_tangent,
    solve_tangent,
)


class TireBottoms(ValueError):
    """The road would reach the rim: the lift asked for is more than the tire's section can give."""


def tread_heights(tire: LoadedTire, u: np.ndarray) -> np.ndarray:
    """Height ``z`` (m) of every tread node displaced by ``u``."""
    return tire.mesh.coordinates[tire.tread, 2] + u[3 * tire.tread + 2]


class RoadContact:
    """The rim held and the tread's ``active`` nodes held on ``road`` (top at height ``top``, m).

    Implements :class:`.statics.Supports`: the frame, the held DOF and their moves, the contact
    forces' curvature term, and the primal-dual update of the active set.
    """

    def __init__(self, tire: LoadedTire, road: RoadSurface, top: float, gap_tolerance: float, active: np.ndarray):
        self.tire, self.road, self.top, self.gap_tolerance = tire, road, top, gap_tolerance
        self.active = np.asarray(active, int)

    def positions(self, nodes: np.ndarray, u: np.ndarray) -> np.ndarray:
        """Deformed positions (m) of ``nodes``."""
        return self.tire.mesh.coordinates[nodes] + u.reshape(-1, 3)[nodes]

    def gaps_and_normals(self, nodes: np.ndarray, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distance of each node outside the surface (m, negative inside) and the surface's outward
        unit normal through it (``(n_x, n_z)`` per node)."""
        x = self.positions(nodes, u)
        if self.road.kind == "flat":
            return x[:, 2] - self.top, np.tile([0.0, 1.0], (nodes.size, 1))
        axis = self.top - self.road.drum_radius
        radial = np.stack([x[:, 0], x[:, 2] - axis], axis=1)
        distance = np.hypot(radial[:, 0], radial[:, 1])
        return distance - self.road.drum_radius, radial / distance[:, None]

    def frame(self, normals: np.ndarray) -> sp.csr_matrix | None:
        """``T`` with global = ``T`` local: each active node's ``x``/``z`` slots hold its tangent and normal
        DOF (``None`` on the flat road: the global axes)."""
        if self.road.kind == "flat":
            return None
        n_dof, nodes = self.tire.n_dof, self.active
        n_x, n_z = normals[:, 0], normals[:, 1]
        rows = [np.setdiff1d(np.arange(n_dof), np.concatenate([3 * nodes, 3 * nodes + 2]))]
        cols, vals = [rows[0]], [np.ones(rows[0].size)]
        # tangent t = (n_z, -n_x) in the x-z plane goes to the x slot, the normal to the z slot
        for row, col, val in (
            (3 * nodes, 3 * nodes, n_z),
            (3 * nodes + 2, 3 * nodes, -n_x),
            (3 * nodes, 3 * nodes + 2, n_x),
            (3 * nodes + 2, 3 * nodes + 2, n_z),
        ):
            rows.append(row), cols.append(col), vals.append(val)
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), (n_dof, n_dof))

    def local(self, u: np.ndarray, r: np.ndarray, k: sp.csr_matrix) -> LocalSystem:
        tire, nodes = self.tire, self.active
        gaps, normals = self.gaps_and_normals(nodes, u)
        held = np.concatenate([tire.fixed, 3 * nodes + 2])
        moves = np.concatenate([-u[tire.fixed], -gaps])
        frame = self.frame(normals)
        if frame is None:
            return LocalSystem(frame=None, held=held, moves=moves, residual=r, tangent=k)
        residual = frame.T @ r
        force = residual[3 * nodes + 2]  # each node's contact force along the normal (N)
        curvature = sp.csr_matrix(
            (-force / self.road.drum_radius, (3 * nodes, 3 * nodes)), shape=(tire.n_dof, tire.n_dof)
        )
        return LocalSystem(
            frame=frame, held=held, moves=moves, residual=residual, tangent=(frame.T @ k @ frame + curvature).tocsr()
        )

    def update(self, u: np.ndarray, system: LocalSystem) -> bool:
        """Release the held nodes the road pulls, hold the free ones inside it; whether any changed."""
        pulled = self.active[system.residual[3 * self.active + 2] < 0.0]
        gaps, _ = self.gaps_and_normals(self.tire.tread, u)
        inside = np.setdiff1d(self.tire.tread[gaps < -self.gap_tolerance], self.active)
        if not pulled.size and not inside.size:
            return False
        self.active = np.union1d(np.setdiff1d(self.active, pulled), inside)
        return True


def contact_of(tire: LoadedTire, state: StaticState) -> RoadContact:
    """The road contact of a loaded ``state`` (its road, top and contact set)."""
    if state.contact.size == 0:
        raise ValueError("state: the tire touches no road (give a loaded state: road_contact.press_on_road)")
    return RoadContact(tire, state.road, state.road_top, 0.0, state.contact)


def local_tangent(tire: LoadedTire, state: StaticState) -> LocalSystem:
    """The tangent of ``state`` in its contact's frame, with the contact forces' curvature term (the rim's
    alone before loading)."""
    r, k = residual_and_tangent(tire, state.u, state.pressure)
    supports = Rim(tire) if state.contact.size == 0 else contact_of(tire, state)
    return supports.local(state.u, r, k)


def press_on_road(
    tire: LoadedTire,
    inflated: StaticState,
    lift: float,
    road: RoadSurface = FLAT_ROAD,
    steps: int = 4,
    start: StaticState | None = None,
    check_stability: bool = True,
    guess: np.ndarray | None = None,
) -> StaticState:
    """The road raised ``lift`` (m) from touching the inflated tread, in ``steps`` equal steps; rim held.

    ``road``: the flat road or a drum (its top under the axle). Each step's contact set is found
    by the primal-dual active set, until it no longer changes. The final state's stability is
    checked (:func:`is_stable`; ``check_stability=False``: not, ``stable`` is ``None``, for a state
    on the way to another); a saddle gets a :class:`~roadnoise_utils.guards.RoadnoiseWarning`.
    ``start``: a loaded state of the same inflation and road to continue from (its lift and
    contact set) instead of the inflated tire. ``guess``: with one step, displacements near the state
    sought to start Newton's iterations from instead of ``start``'s, the tread nodes inside the road
    there held from the first iteration (a load sweep's extrapolation of its last two states,
    :mod:`.loading`); ignored where it inverts the mesh.
    """
    lift = guards.real("lift", lift, 0.0, lo_open=True, unit="m")
    steps = guards.integer("steps", steps, 1)
    if not isinstance(road, RoadSurface):
        raise TypeError(f"road: a RoadSurface (make_road('flat') or make_road('drum', R)), got {road!r}")
    touch = float(tread_heights(tire, inflated.u).min())
    rim = float(tire.mesh.coordinates[tire.mesh.bead_nodes, 2].min()) - touch  # the rim's lowest point above the road
    if lift >= rim:
        raise TireBottoms(
            f"lift = {lift!r} m: valid range is (0, {rim:.4g}) m; the road would reach the rim (the tire bottoms)"
        )
    if start is not None and start.pressure != inflated.pressure:
        raise ValueError(f"start is a state at {start.pressure:g} Pa, the inflated tire at {inflated.pressure:g} Pa")
    if (
        start is not None
        and start.contact.size
        and (start.road.kind, start.road.drum_radius)
        != (
            road.kind,
            road.drum_radius,
        )
    ):
        raise ValueError(f"start stands on the {start.road.kind} road, not on the {road.kind} road given")
    begin = inflated if start is None else start
    u, p = begin.u.copy(), inflated.pressure
    if guess is not None:
        guess = np.asarray(guess, dtype=float)
        if steps != 1 or guess.shape != u.shape or not np.all(np.isfinite(guess)):
            raise ValueError(
                f"guess: finite displacements of shape {u.shape} (m), with steps = 1; got shape {guess.shape}"
            )
        if admissible(tire, guess):
            u = guess.copy()
    history = list(begin.history)
    active = begin.contact.copy()
    for level in np.linspace(begin.road_lift + (lift - begin.road_lift) / steps, lift, steps):
        contact = RoadContact(tire, road, touch + level, GAP_TOLERANCE * lift, active)
        gaps, _ = contact.gaps_and_normals(tire.tread, u)
        contact.active = np.union1d(active, tire.tread[gaps < 0.0])
        scale = np.linalg.norm(pressure.pressure_load(tire.mesh, tire.surface, u, p))
        u, step_history, system = newton(tire, u, p, contact, scale)
        history.append(step_history)
        active = contact.active
    state = StaticState(
        u=u,
        pressure=p,
        road_lift=lift,
        contact=active,
        reactions=system.reactions(),
        history=history,
        road=road,
        road_top=touch + lift,
    )
    if not check_stability:
        return state
    state.stable = is_stable(tire, state, system)
    if not state.stable:
        guards.warn(
            f"the loaded state at a lift of {lift * 1e3:.3g} mm ({state.road_force:.0f} N) is a saddle of the "
            "potential, not a minimum: its tangent has a negative direction (e.g. the cord plies compressed in "
            "the footprint buckling between the nodes), so its stiffness and footprint are those of an "
            "equilibrium the tire would leave; lower the load"
        )
    return state


def _free(system: LocalSystem) -> np.ndarray:
    return np.setdiff1d(np.arange(system.residual.size), system.held)


def is_stable(tire: LoadedTire, state: StaticState, system: LocalSystem | None = None) -> bool:
    """Whether ``state`` is a minimum of the potential, the rim and the contact nodes' normal DOF held.

    Newton's method finds any stationary point; a saddle is an equilibrium the tire would leave
    (e.g. the cord plies compressed in the footprint buckling). The tangent of the free DOF (in the
    contact's frame, with its curvature term) is positive definite at a minimum: every pivot of its
    symmetric factor is positive (:class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor`). ``system``: the last Newton iteration's, if at hand.
    """
    system = local_tangent(tire, state) if system is None else system
    free = _free(system)
    try:
        SymmetricFactor(system.tangent[free][:, free])
    except np.linalg.LinAlgError:
        return False
    return True


def vertical_stiffness(tire: LoadedTire, state: StaticState) -> float:
    r"""Tangent vertical stiffness (N/m) of a loaded state, the contact set held: the rim's vertical
    reaction per unit upward rim motion, the road held (the road's force per unit road lift, by the
    invariance of tire and road under a rigid motion).

    The rim's vertical DOF moved up by one (``m``), the free DOF follow in equilibrium,
    :math:`K_{ff}\Delta u_f = -K_{fh} m`, in the contact's frame (the drum's normals and curvature
    term included); :math:`K_v = \sum_{rim} (K_{rh} m + K_{rf}\Delta u_f)`.
    """
    system = local_tangent(tire, state)
    free, k = _free(system), system.tangent
    rim = tire.fixed[tire.fixed % 3 == 2]
    lifted = np.asarray(k[free][:, rim].sum(axis=1)).ravel()
    du = solve_tangent(k[free][:, free], -lifted)
    return float(k[rim][:, rim].sum() + np.sum(k[rim][:, free] @ du))
