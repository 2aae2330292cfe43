"""One-sided contact of the cross-section tire over a cleat: quasi-static (paper Fig. 8's base curve) and dynamic.

The measured base curve of the paper's cleat test (850 N) is a quasi-static passage with the
hub held at its static height: the tread lifts off the drum around the cleat. On the
cross-section tire each step is the contact problem of :mod:`roadnoise_utils.tire.cross_section.static` with the
deflection held instead of the load: on the active set of contact points
:math:`C_{AA}\\,\\lambda_A = p_A`, with :math:`p` the penetration of the unloaded tread surface
(static rise plus the cleat's height under each point, averaged over the point's hat, as
:func:`.road.cleat.point_heights`), until no point in contact pulls and none out of contact
penetrates. The compliance :math:`C` is the harmonic sum of the static solve (every harmonic,
frictionless vertical points), computed once. Both runs use the contact grid extended to
:data:`HALF_LENGTH` ahead of and behind the axle: a 15 mm cleat meets the tread ~105 mm ahead.

The dynamic passage (the measured 30 km/h curve, :func:`section_dynamic_run`) steps the tire's
viscoelastic dynamics at the grid in time (:class:`roadnoise_utils.tire.cross_section.stepping.HarmonicStepper`:
every harmonic, generalised-alpha, Prony moduli); each step solves the same contact problem on
the step's compliance of the grid for the penetration of the predicted surface.

Checks of every run, from the solution itself: the largest penetration of any grid point out
of contact (from the displacement, not from the contact algebra) and, quasi-static, the hub
force while no point in contact stands on the profile against the static load (the
deflection-held solve against the load-held one).
"""

from __future__ import annotations

import numpy as np
from threadpoolctl import threadpool_limits

from ... import guards
from ...road.cleat import point_heights
from ..active_set import StepContact, held_contact
from ..contact import ContactRun, check_frozen, time_steps
from . import spec as cross_section
from .contact import extended_grid, harmonic_flexibility, vertical_compliance
from .static import SectionStaticState, SectionTire, check_contact_memory
from .stepping import HarmonicStepper, check_static_start

#: The cleat runs' contact grid reaches this far ahead of and behind the axle (m along the tread): a
#: 15 mm cleat on the 1.25 m drum meets the 165/65 R14 about 105 mm ahead, beyond the static grid.
HALF_LENGTH = 0.15
#: The dynamic run's contact candidates: grid points within this of the road at the profile's
#: highest (m); every step checks that no other point penetrates (``max_penetration``).
NEAR_MARGIN = 0.01
#: Active-set iterations allowed per step.
MAX_ITERATIONS = 100
#: Points farther than this below the road at the profile's highest are left out of the solves (m);
#: every step checks that none of them penetrates.
MARGIN = 0.005


def _check_tire(tire: SectionTire, static: SectionStaticState) -> None:
    if static.tire is not None and cross_section.to_dict(static.tire) != cross_section.to_dict(tire.spec):
        raise ValueError("static was solved for another tire than this one; solve the static state of this tire")


class _CleatSetup:
    """The contact grid extended ahead of and behind the footprint, the static state on it, the heights."""

    def __init__(self, tire: SectionTire, static: SectionStaticState, profile, travel: np.ndarray):
        grid, offset = extended_grid(tire.grid, HALF_LENGTH)
        check_contact_memory(grid, tire.harmonics)
        pad = ((0, 0), (offset, offset))
        self.grid = grid
        self.forces = np.pad(static.contact_force, pad)
        self.contact = np.pad(static.contact, pad).ravel()
        x, z = grid.xz()
        # penetration of the unloaded tread surface into the road at the static rise (m)
        self.base = (static.deflection - (z - z.min() + static.road.drop(x))).ravel()
        arc = np.repeat(grid.radius * grid.dtheta, grid.n_rows)  # points (column, row) in ravel order
        self.heights = point_heights(x.ravel(), arc, arc, profile, travel)
        edge = np.zeros((grid.n_cols, grid.n_rows), bool)
        edge[:, [0, -1]] = True
        self.edge = edge.ravel()

    def check_edge(self, active: np.ndarray, travel: float) -> None:
        """Refuse contact on the grid's first or last row (the road would reach beyond the grid)."""
        if self.edge[active].any():
            raise RuntimeError(
                f"contact reached the end of the contact grid at travel {travel:.3f} m "
                f"(grid +/- {self.grid.theta[-1] * self.grid.radius.max() * 1e3:.0f} mm): a profile too tall for it"
            )


def section_quasi_static_run(
    tire: SectionTire, static: SectionStaticState, profile, distance: tuple[float, float], step: float = 5.0e-4
) -> ContactRun:
    """Quasi-static passage of a road ``profile`` (callable of the road coordinate, m), one-sided contact.

    ``static`` is the tire loaded on the same road (its deflection is held); ``distance`` the
    travel (m, 0 = the profile's origin under the axle), solved every ``step`` m.
    """
    d0, d1 = guards.interval("distance", distance)
    step = guards.real("step", step, 0.0, 0.01, lo_open=True, unit="m")
    _check_tire(tire, static)
    travel = np.arange(d0, d1 + 0.5 * step, step)
    setup = _CleatSetup(tire, static, profile, travel)
    grid = setup.grid
    compliance = vertical_compliance(grid, harmonic_flexibility(tire.ops, grid.dofs, tire.harmonics))
    base, heights = setup.base, setup.heights
    # points that can reach the road: within MARGIN of it at the highest the profile puts them
    near = np.nonzero(base + heights.max(axis=1) > -MARGIN)[0]
    reach = compliance[np.ix_(near, near)]
    active = setup.contact[near]
    hub = np.zeros(travel.size)
    points = np.zeros(travel.size, int)
    on_profile = np.zeros(travel.size, bool)
    worst, most = 0.0, 0
    for k in range(travel.size):
        penetration = base + heights[:, k]
        forces, active, iterations = held_contact(
            lambda cols: reach[:, cols], penetration[near], active, np.zeros(near.size), MAX_ITERATIONS
        )
        hub[k] = forces.sum()
        points[k] = active.sum()
        on_profile[k] = bool(np.any(active & (heights[near, k] > 0)))
        setup.check_edge(near[active], travel[k])
        # every point of the grid, those left out included: none may penetrate
        gap = compliance[:, near[active]] @ forces[active] - penetration
        gap[near[active]] = 0.0
        worst = max(worst, float(-gap.min()))
        most = max(most, iterations)
    off = ~on_profile  # the profile carries nothing: the held deflection must carry the static load
    balance = float(np.max(np.abs(hub[off] - static.load)) / static.load) if off.any() else float("nan")
    return ContactRun.quasi_static(travel, d0, hub - static.load, points, on_profile, worst, balance, most)


def section_dynamic_run(
    tire: SectionTire,
    static: SectionStaticState,
    profile,
    speed: float,
    distance: tuple[float, float],
    dt: float | None = None,
    frozen: bool = False,
    reduced: list | None = None,
) -> ContactRun:
    """Dynamic passage of a road ``profile`` at ``speed`` (m/s), hub fixed, one-sided (or frozen) contact.

    The tire's dynamics at the contact grid come from :class:`roadnoise_utils.tire.cross_section.stepping.HarmonicStepper`
    (every harmonic, generalised-alpha, Prony moduli); each step solves the contact on the step's
    compliance of the grid as the quasi-static run does, starting from the static state at rest.
    ``frozen`` keeps every static contact point bilateral (no lift-off, no new contact): the
    linear model, to compare with the frequency domain. ``reduced``: the harmonics of
    :func:`roadnoise_utils.tire.cross_section.stepping.reduce_all` when already built.
    """
    return section_dynamic_runs(tire, static, profile, speed, distance, dt, (bool(frozen),), reduced)[0]


def section_dynamic_runs(
    tire: SectionTire,
    static: SectionStaticState,
    profile,
    speed: float,
    distance: tuple[float, float],
    dt: float | None = None,
    frozen: tuple[bool, ...] = (False, True),
    reduced: list | None = None,
) -> list[ContactRun]:
    """The passage of :func:`section_dynamic_run` with one run per entry of ``frozen``, stepped together.

    The runs share one :class:`roadnoise_utils.tire.cross_section.stepping.HarmonicStepper` of several runs: most of
    a step is reading the harmonics' operators, once for all runs, so the one-sided run and its
    frozen check together cost little more than one of them. Each run is the run
    :func:`section_dynamic_run` gives alone (the runs' arithmetic is independent).
    """
    speed = guards.real("speed", speed, 0.0, 100.0, lo_open=True, unit="m/s")
    _check_tire(tire, static)
    check_frozen(frozen)
    dt, travel = time_steps(tire.spec.mesh.contact_spacing, speed, distance, dt)
    n_steps, runs = travel.size, len(frozen)
    setup = _CleatSetup(tire, static, profile, travel)
    grid, base, heights = setup.grid, setup.base, setup.heights
    shape = (runs, grid.n_cols, grid.n_rows)
    stepper = HarmonicStepper(tire, dt, reduced, grid=grid, runs=runs)
    start = np.reshape(stepper.start(np.broadcast_to(setup.forces, shape)), (runs, -1))[0]
    check_static_start(static, start[setup.contact], base[setup.contact])
    touching = base + heights[:, 0] - start > 1e-9
    if np.any(touching & ~setup.contact) or np.any(heights[setup.contact, 0] != 0):
        raise ValueError(
            f"the profile already touches the tread at the first travel {travel[0]:.3f} m: valid range is a "
            "distance starting before the profile reaches the tire (the run starts from the static state at rest)"
        )
    # points that can reach the road: within NEAR_MARGIN of it at the highest the profile puts them
    near = np.nonzero(base + heights.max(axis=1) > -NEAR_MARGIN)[0]
    compliance = stepper.effective_compliance()[np.ix_(near, near)]
    solvers = [StepContact(compliance, setup.contact[near], bool(f), MAX_ITERATIONS) for f in frozen]
    hub = np.zeros((runs, n_steps))
    points = np.zeros((runs, n_steps), int)
    on_profile = np.zeros((runs, n_steps), bool)
    hub[:, 0], points[:, 0] = static.load, int(setup.contact.sum())
    worst, most = np.zeros(runs), np.zeros(runs, int)
    forces = np.zeros((runs, base.size))
    with threadpool_limits(1, user_api="blas"):  # small products: threads only fight over the cores
        for k in range(1, n_steps):
            free = np.reshape(stepper.predict(), (runs, -1))
            for r, solver in enumerate(solvers):
                forces[r, near], iterations = solver.solve(base[near] + heights[near, k] - free[r, near])
                most[r] = max(most[r], iterations)
            hub[:, k] = stepper.advance(forces.reshape(shape))
            moved = None if all(frozen) else np.reshape(stepper.displacement(), (runs, -1))
            for r, solver in enumerate(solvers):
                active = near[solver.active]
                points[r, k] = active.size
                on_profile[r, k] = bool(np.any(heights[active, k] > 0))
                setup.check_edge(active, travel[k])
                if not solver.frozen:  # every grid point, from the step's own displacement (not the step's compliance)
                    gap = base + heights[:, k] - moved[r]
                    gap[active] = 0.0
                    worst[r] = max(worst[r], float(gap.max()))
    return [
        ContactRun.dynamic(
            travel, dt, hub[r] - static.load, points[r], on_profile[r], speed, bool(frozen[r]), worst[r], most[r]
        )
        for r in range(runs)
    ]
