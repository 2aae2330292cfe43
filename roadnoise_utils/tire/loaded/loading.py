"""The inflated tire loaded to a vertical load: road steps up to the load, then the lift that carries it.

The road contact (:mod:`.road_contact`) presses the road a given lift into the tire; a load case
gives a force. :func:`load_on_road` raises the road in steps of ``road_step`` until the road's force
passes the load (a step the Newton iterations do not follow is halved, at most
:data:`STEP_HALVINGS` times, the next step doubled back; near the load, a step no longer than
the state's secant stiffness asks for, so that the first state past the load is close to it; where
such a step falls short, the tire softening, plain steps again), then finds the lift that carries it
exactly by Brent's method, which keeps the root bracketed. Each solve keeps the contact set of the
nearest equilibrium and starts Newton's iterations on the line through two known ones (a road step
beyond the last two states, extrapolated; a landing between the bracket's, interpolated), with the
tread nodes inside the road there held from the first iteration: on the 165/65 R14's production mesh
54 and 79 iterations to its load on the flat road and the drum instead of 67 and 103 from the nearest
state alone, to the same equilibrium (lifts equal to 1e-12). A load the tire cannot carry before the
road reaches the rim, a step the Newton iterations cannot follow even halved and a lift that will not
settle are refused by name.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from ... import guards
from ..surface import RoadSurface
from . import road_contact
from .statics import FLAT_ROAD, LoadedTire, StaticState

#: The road's force must equal the load to this fraction (0.5 uN at 4.5 kN): below the footprint's force
#: balance of 1e-9, above the Newton iterations' round-off (the hub and the road agree to ~1e-10).
LOAD_TOLERANCE = 1e-10
#: Iterations of Brent's method allowed to land on the load once it is bracketed.
MAX_LANDING_ITERATIONS = 20
#: Times a road step the Newton iterations do not follow is halved before the load case is refused.
STEP_HALVINGS = 2
#: A step from a state carrying part of the load is at most this times the lift its secant stiffness (force over
#: lift from touching) asks for: a tire's force grows faster than its lift, so the secant's lift passes the load
#: a little and brackets it closely.
SECANT_OVERSHOOT = 1.1


def load_on_road(
    tire: LoadedTire,
    inflated: StaticState,
    load: float,
    road_step: float,
    road: RoadSurface = FLAT_ROAD,
    start: StaticState | None = None,
) -> StaticState:
    """The inflated tire pressed on ``road`` (the flat road or a drum) until the road carries ``load`` (N).

    Parameters
    ----------
    tire, inflated
        The tire and its inflated state (:func:`.statics.inflate`).
    load : float
        Vertical load (N), within :data:`roadnoise_utils.guards.LOAD_RANGE`.
    road_step : float
        Road lift per load step (m): the steps the Newton iterations follow (halved where they do not).
    road : RoadSurface
        The flat road (default) or a drum.
    start : StaticState, optional
        A state of the same tire, inflation and road carrying less than ``load`` to continue from
        (a load sweep: :func:`load_sweep`); default the inflated tire.

    Returns
    -------
    StaticState
        The equilibrium whose road force is ``load`` to :data:`LOAD_TOLERANCE`; its ``stable``
        says whether it is a minimum of the potential (a saddle is warned of by the statics).

    Raises
    ------
    ValueError
        ``load`` outside its range or more than the tire carries before the road reaches the rim
        (the message gives the most it carried); ``road_step`` not positive or too long for the
        Newton iterations to follow.
    """
    load = guards.real("load", load, *guards.LOAD_RANGE, unit="N")
    road_step = guards.real("road_step", road_step, 0.0, 0.05, lo_open=True, unit="m")
    below, above = (inflated if start is None else start), None
    if below.road_force >= load:
        raise ValueError(
            f"start carries {below.road_force:.0f} N, not less than load = {load:g} N: give a lighter start"
        )
    step, failures, secant, previous = road_step, 0, True, None
    while above is None:
        secant_step = _secant_step(below, load) if secant else float("inf")
        by_secant = secant_step < step
        step = min(step, secant_step)
        lift = below.road_lift + step
        try:
            state = _pressed(tire, inflated, lift, below, load, road_step, road, _between(previous, below, lift))
        except _NotFollowed:
            failures += 1
            if failures > STEP_HALVINGS:
                raise
            step /= 2.0
            continue
        failures, step = 0, min(road_step, 2.0 * step)
        if state.road_force >= load:
            above = state
        else:
            previous, below = below, state
            if by_secant:  # the secant's step fell short (the tire softens here): road steps from now on
                secant, step = False, road_step
    return _land(tire, inflated, load, below, above, road_step, road)


def load_sweep(
    tire: LoadedTire,
    inflated: StaticState,
    loads: list[float],
    road_step: float,
    road: RoadSurface = FLAT_ROAD,
    start: StaticState | None = None,
) -> list[StaticState]:
    """The tire at each of ``loads`` (N, increasing) on ``road``, each loading continuing from the last
    state (:func:`load_on_road`): one pass of road steps for the whole load-deflection curve, from the
    inflated tire or from ``start`` (a state carrying less than the first load: a sweep continued)."""
    loads = increasing_loads(loads)
    states: list[StaticState] = []
    for load in loads:
        states.append(load_on_road(tire, inflated, load, road_step, road, start=states[-1] if states else start))
    return states


def increasing_loads(loads) -> list[float]:
    """``loads`` as floats (N), each within :data:`roadnoise_utils.guards.LOAD_RANGE`, one or more, strictly
    increasing: a load sweep's loads, refused by name otherwise."""
    loads = [guards.real("loads", load, *guards.LOAD_RANGE, unit="N") for load in loads]
    if not loads or any(b <= a for a, b in zip(loads, loads[1:])):
        raise ValueError(f"loads = {loads}: give one or more strictly increasing loads (N)")
    return loads


def _pressed(
    tire: LoadedTire,
    inflated: StaticState,
    lift: float,
    start: StaticState,
    load: float,
    road_step: float,
    road: RoadSurface,
    guess: np.ndarray | None = None,
) -> StaticState:
    """One road position from ``start`` (Newton from ``guess`` where given); the statics' errors restated in
    terms of the load case."""
    try:  # only the final state's stability is checked
        return road_contact.press_on_road(
            tire, inflated, lift, road, steps=1, start=start, check_stability=False, guess=guess
        )
    except road_contact.TireBottoms:
        raise ValueError(
            f"load = {load:g} N: the tire carries at most {start.road_force:.0f} N before the road reaches the rim "
            f"at {inflated.pressure / 1e5:g} bar (a lift of {start.road_lift * 1e3:.1f} mm): lower the load or raise "
            "the inflation pressure"
        ) from None
    except (RuntimeError, FloatingPointError) as exc:
        raise _NotFollowed(
            f"road_step = {road_step:g} m: the static solve did not follow the road from {start.road_lift * 1e3:.2f} "
            f"to {lift * 1e3:.2f} mm ({exc}); give a shorter road step"
        ) from None


def _between(a: StaticState | None, b: StaticState, lift: float) -> np.ndarray | None:
    """The displacements at ``lift`` on the line through states ``a`` and ``b`` (interpolated between them,
    extrapolated beyond ``b``): Newton's start for a road position near both; None without ``a``."""
    if a is None or a.road_lift == b.road_lift:
        return None
    share = (lift - a.road_lift) / (b.road_lift - a.road_lift)
    return a.u + share * (b.u - a.u)


def _secant_step(state: StaticState, load: float) -> float:
    """The lift (m) from ``state`` to ``load`` at ``state``'s secant stiffness, times :data:`SECANT_OVERSHOOT`
    (infinite from the inflated tire, which carries nothing)."""
    if state.road_force <= 0.0 or state.road_lift <= 0.0:
        return float("inf")
    return SECANT_OVERSHOOT * (load - state.road_force) * state.road_lift / state.road_force


class _NotFollowed(ValueError):
    """A road step the static solve did not follow (the message names ``road_step``)."""


class _Landed(Exception):
    """Raised inside Brent's iterations once a state carries the load (no need to shrink the bracket further)."""


def _land(
    tire: LoadedTire,
    inflated: StaticState,
    load: float,
    below: StaticState,
    above: StaticState,
    road_step: float,
    road: RoadSurface,
) -> StaticState:
    """The state between the bracket ``below``/``above`` whose road force is ``load``: Brent's method on
    the lift (:func:`scipy.optimize.brentq`), each solve starting from the nearest equilibrium found,
    stopped as soon as a state carries the load to :data:`LOAD_TOLERANCE`."""
    states = {below.road_lift: below, above.road_lift: above}

    def miss(lift: float) -> float:
        if lift not in states:
            nearest = states[min(states, key=lambda known: abs(known - lift))]
            lower = states[max(known for known in states if known < lift)]
            upper = states[min(known for known in states if known > lift)]
            states[lift] = _pressed(tire, inflated, lift, nearest, load, road_step, road, _between(lower, upper, lift))
        value = states[lift].road_force - load
        if abs(value) <= LOAD_TOLERANCE * load:
            raise _Landed
        return value

    try:
        brentq(miss, below.road_lift, above.road_lift, xtol=1e-15, maxiter=MAX_LANDING_ITERATIONS)
    except (_Landed, RuntimeError):  # landed; or out of iterations, refused below
        pass
    best = min(states.values(), key=lambda state: abs(state.road_force - load))
    if abs(best.road_force - load) > LOAD_TOLERANCE * load:
        raise ValueError(
            f"load = {load:g} N: the road's force did not settle on the load within {LOAD_TOLERANCE:g} in "
            f"{MAX_LANDING_ITERATIONS} iterations (closest {best.road_force:.6f} N): the contact set is changing "
            "at this load; give a shorter road_step"
        )
    return _final(tire, best, load)


def _final(tire: LoadedTire, state: StaticState, load: float) -> StaticState:
    """The landed state, its stability checked, warned of if it is a saddle of the potential."""
    state.stable = road_contact.is_stable(tire, state)
    if not state.stable:
        guards.warn(
            f"the loaded state at {load:.0f} N is a saddle of the potential, not a minimum: its tangent has a "
            "negative direction (e.g. the cord plies compressed in the footprint buckling between the nodes), so "
            "its stiffness and footprint are those of an equilibrium the tire would leave; lower the load"
        )
    return state
