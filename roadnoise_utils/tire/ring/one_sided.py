"""One-sided contact of the ring FE tire, quasi-static and in time (beyond the paper)."""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from threadpoolctl import threadpool_limits

from ... import guards
from ...road.cleat import point_heights
from ..active_set import held_contact
from ..banded import BandedCholesky
from ..contact import ContactRun, time_steps
from ..rubber import PronyBranches, SharedPronyStates, prony_series
from .mechanics import UZ, FETModel
from .static import StaticState, check_same_tire, contact_problem

#: Tread points further than this outside the static footprint are not contact candidates (m): a 15 mm
#: cleat on the 1.25 m drum first touches the 165/65 R14 about 40 mm ahead of its footprint.
CANDIDATE_MARGIN = 0.10


#: Columns of the dynamic compliance solved at once.
COLUMN_BATCH = 128


#: Active-set iterations allowed per step.
MAX_ITERATIONS = 100


def _candidates(fet: FETModel, static: StaticState, margin: float) -> tuple[np.ndarray, np.ndarray]:
    """(strip, node) of the tread points within ``margin`` (m) of the static footprint, lower half."""
    mesh = fet.mesh
    tx, _ = mesh.tread_xz()
    x = static.tasselli.node_x
    lower = np.cos(mesh.theta)[None, :] > 0.5
    near = (tx >= x.min() - margin) & (tx <= x.max() + margin) & lower
    return np.nonzero(near)


def _outermost(strip: np.ndarray, node: np.ndarray, n_elements: int) -> np.ndarray:
    """Mask of the first and last candidate of each strip (contact there means the margin is too small)."""
    angle = np.angle(np.exp(2j * np.pi * node / n_elements))
    edge = np.zeros(strip.size, bool)
    for j in np.unique(strip):
        mine = np.nonzero(strip == j)[0]
        edge[mine[np.argmin(angle[mine])]] = edge[mine[np.argmax(angle[mine])]] = True
    return edge


def _tributaries(fet: FETModel, strip: np.ndarray, node: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """x of tread points and their distances to the previous and next point of their strip (m)."""
    tx, _ = fet.mesh.tread_xz()
    ne = fet.mesh.n_elements
    x = tx[strip, node]
    return x, x - tx[strip, (node - 1) % ne], tx[strip, (node + 1) % ne] - x


def contact_spacing(fet: FETModel) -> float:
    """Distance between neighbouring tread points along the tread surface (m)."""
    return fet.mesh.arc_length * fet.spec.geometry.outer_radius / fet.spec.geometry.belt_radius


def quasi_static_run(
    fet: FETModel, static: StaticState, profile, distance: tuple[float, float], step: float = 5.0e-4
) -> ContactRun:
    """Quasi-static passage of a road ``profile`` (callable of the road coordinate, m) with one-sided contact.

    The hub stays at the static deflection; at each travel (every ``step`` m over ``distance``)
    the active set of tread points in contact is solved exactly on the static compliance
    (:class:`roadnoise_utils.tire.ring.static.ContactProblem`).
    """
    check_same_tire(fet, static)
    d0, d1 = guards.interval("distance", distance)
    step = guards.real("step", step, 0.0, 0.01, lo_open=True, unit="m")
    problem = contact_problem(fet, static.road)
    n_el = fet.mesh.n_elements
    strip, node = problem.candidates // n_el, problem.candidates % n_el
    x, dx_minus, dx_plus = _tributaries(fet, strip, node)
    travel = np.arange(d0, d1 + 0.5 * step, step)
    heights = point_heights(x, dx_minus, dx_plus, profile, travel)
    # penetration of the unloaded tread surfaces at the static rise, before the belt moves
    base = static.deflection - problem.gap0
    hub_row = fet.K(0.0, storage_only=True)[fet.mesh.hub_dofs[1]].toarray().ravel()[problem.free]
    active = base > 0
    forces = np.zeros((travel.size,))
    points = np.zeros(travel.size, int)
    on_profile = np.zeros(travel.size, bool)
    balance, worst, most = 0.0, 0.0, 0
    for k in range(travel.size):
        f, active, iterations = held_contact(
            problem.compliance, base + heights[:, k], active, 1.0 / problem.stiffness_tread, MAX_ITERATIONS
        )
        forces[k] = f.sum()
        points[k] = active.sum()
        on_profile[k] = bool(np.any(active & (heights[:, k] > 0)))
        # independent check: a fresh solve of the belt under these forces
        loads = np.zeros(problem.free.size)
        loads[problem.candidate_dofs] = f
        u = problem.lu.solve(loads)
        balance = max(balance, abs(-hub_row @ u - f.sum()) / static.load)
        pen = base + heights[:, k] - u[problem.candidate_dofs]  # penetration of the unloaded tread surface
        worst = max(worst, float(pen[~active].max(initial=0.0)))
        balance = max(
            balance,
            float(np.max(np.abs(pen[active] * problem.stiffness_tread[active] - f[active]), initial=0.0)) / static.load,
        )
        most = max(most, iterations)
    return ContactRun.quasi_static(travel, d0, forces - static.load, points, on_profile, worst, balance, most)


def dynamic_run(
    fet: FETModel,
    static: StaticState,
    profile,
    speed: float,
    distance: tuple[float, float],
    dt: float | None = None,
    frozen: bool = False,
    margin: float = CANDIDATE_MARGIN,
) -> ContactRun:
    """Dynamic passage of a road ``profile`` at ``speed`` (m/s), hub fixed, one-sided (or frozen) contact.

    Parameters
    ----------
    fet, static : FETModel, StaticState
        The tire and its static state on the drum (the run starts from it at rest).
    profile : callable
        Road height (m) against the road coordinate (m), e.g.
        :func:`roadnoise_utils.road.cleat.cleat_profile`.
    speed : float
        Rolling speed (m/s).
    distance : (float, float)
        Travel range (m), 0 = the profile's origin under the axle.
    dt : float, optional
        Time step (s); default :data:`DT_MAX`, or less so that the road moves at most a quarter
        of the contact-point spacing per step.
    frozen : bool
        Keep every static contact point bilateral (no lift-off, no new contact): the linear model.
    margin : float
        Candidate tread points reach this far outside the static footprint (m).
    """
    check_same_tire(fet, static)
    speed = guards.real("speed", speed, 0.0, 100.0, lo_open=True, unit="m/s")
    margin = guards.real("margin", margin, 0.0, 0.5, lo_open=True, unit="m")
    dt, travel = time_steps(contact_spacing(fet), speed, distance, dt)
    model = _DynamicModel(fet, static, dt, margin)
    heights = point_heights(model.x, model.dx_minus, model.dx_plus, profile, travel)
    with threadpool_limits(1, user_api="blas"):  # small dense solves: threads only fight over the cores
        return model.run(travel, heights, speed, frozen)


class _DynamicModel:
    """Newmark matrices, Prony branches and the dynamic compliance of the candidate tread points."""

    def __init__(self, fet: FETModel, static: StaticState, dt: float, margin: float):
        mesh = fet.mesh
        self.fet, self.static, self.dt = fet, static, dt
        free = np.setdiff1d(np.arange(fet.n_dof), mesh.hub_dofs)
        hub = mesh.hub_dofs[1]

        def restrict(k):
            return k[free][:, free].tocsc()

        self.M = restrict(fet.M)
        self.K_elastic = restrict(fet.K_elastic)
        self.K_parts = {name: restrict(k) for name, k in fet.K_compound.items()}
        self.hub_elastic = fet.K_elastic[hub].toarray().ravel()[free]
        self.hub_parts = {name: k[hub].toarray().ravel()[free] for name, k in fet.K_compound.items()}
        self.branches = {name: PronyBranches(prony_series(fet.laws[name]), dt) for name in [*self.K_parts, "tread"]}
        k_eff = (4.0 / dt**2) * self.M + self.K_elastic
        for name, k in self.K_parts.items():
            k_eff = k_eff + self.branches[name].factor * k
        self.lu = BandedCholesky(k_eff)
        strip, node = _candidates(fet, static, margin)
        guards.check_memory(
            8.0 * (strip.size**2 + free.size * COLUMN_BATCH),
            f"the dynamic compliance of {strip.size} tread points",
            "margin",
        )
        self.strip, self.node, self.margin = strip, node, margin
        self.edge = _outermost(strip, node, fet.mesh.n_elements)
        self.x, self.dx_minus, self.dx_plus = _tributaries(fet, strip, node)
        self.dofs = np.searchsorted(free, mesh.dof(strip, node, UZ))
        self.G = np.empty((strip.size, strip.size))  # belt uz at candidates per unit upward force (m/N)
        for start in range(0, strip.size, COLUMN_BATCH):
            cols = np.arange(start, min(start + COLUMN_BATCH, strip.size))
            loads = np.zeros((free.size, cols.size))
            loads[self.dofs[cols], np.arange(cols.size)] = 1.0
            self.G[:, cols] = self.lu.solve(loads)[self.dofs]
        self.G = 0.5 * (self.G + self.G.T)
        self.k_tread = fet.tread_normal[strip, node]
        _, tz = mesh.tread_xz()
        self.surface = tz[strip, node]  # unloaded tread surface height (m)
        self.road = static.road_height[strip, node]  # drum surface under each point at the static rise (m)
        if np.any(np.isnan(self.road)):
            raise RuntimeError("a candidate tread point lies outside the static contact problem's candidate zone")
        self.u_static = static.displacement[free]
        self.in_contact = static.contact[strip, node]
        if self.in_contact.sum() != static.contact.sum():
            raise RuntimeError("the candidate tread points do not cover the static footprint")

    def _hub_force(self, u: np.ndarray, states: SharedPronyStates) -> float:
        force = self.hub_elastic @ u
        for name, row in self.hub_parts.items():
            force += row @ (u + states.extra(name, u))
        return -float(force)

    def run(self, travel: np.ndarray, heights: np.ndarray, speed: float, frozen: bool) -> ContactRun:
        dt, n = self.dt, travel.size
        u = self.u_static.copy()
        vel, acc = np.zeros_like(u), np.zeros_like(u)
        states = SharedPronyStates({name: self.branches[name] for name in self.K_parts}, u.size)
        history = states.start(u)  # one state per relaxation time, shared by the compounds
        tread = self.branches["tread"]
        compression = np.where(self.in_contact, self.road - self.surface - u[self.dofs], 0.0)
        tread_states = np.tile(compression, (tread.weights.size, 1))
        kappa = self.k_tread * tread.factor
        static_force = self._hub_force(u, states)
        active = self.in_contact.copy()
        force = np.zeros(n)
        points = np.zeros(n, int)
        on_profile = np.zeros(n, bool)
        worst, most = 0.0, 0
        force[0], points[0] = 0.0, int(active.sum())
        touching = self.road + heights[:, 0] - self.surface - u[self.dofs] - compression > 0
        if np.any(touching & ~self.in_contact) or np.any(heights[self.in_contact, 0] != 0):
            raise ValueError(
                f"the profile already touches the tread at the first travel {travel[0]:.3f} m: valid range is a "
                "distance starting before the profile reaches the tire (the run starts from the static state at rest)"
            )
        for step in range(1, n):
            rhs = self.M @ ((4.0 / dt**2) * u + (4.0 / dt) * vel + acc)
            for name, k in self.K_parts.items():
                rhs += k @ history[name]
            u_free = self.lu.solve(rhs)
            free_surface = tread.history(tread_states, compression) / tread.factor
            pen = self.road + heights[:, step] - self.surface - u_free[self.dofs] - free_surface
            f, active, iterations = self._contact(pen, kappa, active, frozen)
            rhs[self.dofs] += f
            u_new = self.lu.solve(rhs)
            new_compression = np.where(active, pen + free_surface - self.G[:, active] @ f[active], free_surface)
            acc_new = (4.0 / dt**2) * (u_new - u) - (4.0 / dt) * vel - acc
            vel = vel + 0.5 * dt * (acc + acc_new)
            states.update_in_place(u, u_new, history)  # and the next step's history
            tread_states = tread.update(tread_states, compression, new_compression)
            u, acc, compression = u_new, acc_new, new_compression
            force[step] = self._hub_force(u, states) - static_force
            points[step] = int(active.sum())
            on_profile[step] = bool(np.any(active & (heights[:, step] > 0)))
            if active[self.edge].any():
                raise RuntimeError(
                    f"contact reached the outermost candidate tread points at travel {travel[step]:.3f} m: "
                    f"valid range is a wider margin (margin > {self.margin:g} m)"
                )
            if not frozen:  # from the step's own solve, independent of the condensed compliance
                gap = self.road + heights[:, step] - self.surface - u[self.dofs] - compression
                worst = max(worst, float(gap[~active].max(initial=0.0)))
            most = max(most, iterations)
        return ContactRun.dynamic(travel, dt, force, points, on_profile, speed, frozen, worst, most)

    def _contact(
        self, pen: np.ndarray, kappa: np.ndarray, active: np.ndarray, frozen: bool
    ) -> tuple[np.ndarray, np.ndarray, int]:
        """Forces of the active set for the penetrations ``pen`` into the free tread surfaces (m)."""
        for iteration in range(1, MAX_ITERATIONS + 1):
            idx = np.nonzero(active)[0]
            f = np.zeros(active.size)
            if idx.size:
                matrix = self.G[np.ix_(idx, idx)]
                matrix[np.diag_indices(idx.size)] += 1.0 / kappa[idx]
                f[idx] = sla.cho_solve(sla.cho_factor(matrix, check_finite=False), pen[idx], check_finite=False)
            if frozen:
                return f, active, iteration
            remaining = pen - self.G[:, idx] @ f[idx]
            new = np.where(active, f > 0, remaining > 0)
            if np.array_equal(new, active):
                return f, active, iteration
            active = new
        raise RuntimeError(f"dynamic contact did not converge in {MAX_ITERATIONS} active-set iterations")
