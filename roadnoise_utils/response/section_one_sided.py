"""One-sided contact of the cross-section tire over a cleat, quasi-static (paper Fig. 8's base curve).

The measured base curve of the paper's cleat test (850 N) is a quasi-static passage with the
hub held at its static height: the tread lifts off the drum around the cleat. On the
cross-section tire each step is the contact problem of :mod:`.tire.section_static` with the
deflection held instead of the load: on the active set of contact points
:math:`C_{AA}\\,\\lambda_A = p_A`, with :math:`p` the penetration of the unloaded tread surface
(static rise plus the cleat's height under each point, averaged over the point's hat, as
:func:`.road.cleat.point_heights`), until no point in contact pulls and none out of contact
penetrates. The compliance :math:`C` is the harmonic sum of the static solve (every harmonic,
frictionless vertical points), computed once.

Checks of every run, from the solution itself: the hub force while no point in contact stands
on the profile equals the static load (the deflection-held solve against the load-held one),
and the largest penetration of any grid point out of contact.

The dynamic passage with one-sided contact (the measured 30 km/h curve) needs the tire's
viscoelastic dynamics in the time domain at the contact points, which this model does not have
yet (the ring model's Newmark with the Prony form, :mod:`.one_sided`).
"""

from __future__ import annotations

import numpy as np

from .. import guards
from ..road.cleat import point_heights
from ..tire import cross_section
from ..tire.active_set import held_contact
from ..tire.section_contact import harmonic_flexibility, vertical_compliance
from ..tire.section_static import SectionStaticState, SectionTire, check_contact_memory
from .one_sided import ContactRun

#: Active-set iterations allowed per step.
MAX_ITERATIONS = 100
#: Points farther than this below the road at the profile's highest are left out of the solves (m);
#: every step checks that none of them penetrates.
MARGIN = 0.005


def section_quasi_static_run(
    tire: SectionTire, static: SectionStaticState, profile, distance: tuple[float, float], step: float = 5.0e-4
) -> ContactRun:
    """Quasi-static passage of a road ``profile`` (callable of the road coordinate, m), one-sided contact.

    ``static`` is the tire loaded on the same road (its deflection is held); ``distance`` the
    travel (m, 0 = the profile's origin under the axle), solved every ``step`` m.
    """
    d0, d1 = guards.interval("distance", distance)
    step = guards.real("step", step, 0.0, 0.01, lo_open=True, unit="m")
    if static.tire is not None and cross_section.to_dict(static.tire) != cross_section.to_dict(tire.spec):
        raise ValueError("static was solved for another tire than this one; solve the static state of this tire")
    grid = tire.grid
    check_contact_memory(grid, tire.harmonics)
    compliance = vertical_compliance(grid, harmonic_flexibility(tire.ops, grid.dofs, tire.harmonics))
    x, z = grid.xz()
    base = static.deflection - (z - z.min() + static.road.drop(x)).ravel()
    arc = np.repeat(grid.radius * grid.dtheta, grid.n_rows)  # points (column, row) in ravel order
    travel = np.arange(d0, d1 + 0.5 * step, step)
    heights = point_heights(x.ravel(), arc, arc, profile, travel)
    # points that can reach the road: within MARGIN of it at the highest the profile puts them
    near = np.nonzero(base + heights.max(axis=1) > -MARGIN)[0]
    reach = compliance[np.ix_(near, near)]
    active = static.contact.ravel()[near]
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
        # every point of the grid, those left out included: none may penetrate
        gap = compliance[:, near[active]] @ forces[active] - penetration
        gap[near[active]] = 0.0
        worst = max(worst, float(-gap.min()))
        most = max(most, iterations)
    off = ~on_profile  # the profile carries nothing: the held deflection must carry the static load
    balance = float(np.max(np.abs(hub[off] - static.load)) / static.load) if off.any() else float("nan")
    return ContactRun(
        distance=travel,
        t=travel - d0,
        hub_force=hub - static.load,
        contact_points=points,
        on_profile=on_profile,
        speed=0.0,
        contact="one-sided",
        max_penetration=worst,
        force_balance=balance,
        iterations=most,
    )
