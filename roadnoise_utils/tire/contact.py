"""One-sided contact of the FE tire on the drum, quasi-static and in time (beyond the paper).

The paper's RM chain is linear: every tread point of the static footprint stays tied to the
road. In the measured cleat test the 15 mm cleat is comparable to the ~27 mm deflection, and
the tread next to it lifts off the drum. Here the FE tire itself (not the RM chain) meets the
drum through one-sided tread springs:

* **Contact law.** A tread point ``i`` (belt node with its massless tread element of static
  stiffness :math:`k_i`) is pressed by the penetration of the road into its free tread
  surface; it carries :math:`f_i \\ge 0` and lifts off when the force would pull. Contact is
  vertical and frictionless, as in the static solve (:mod:`roadnoise_utils.tire.ring.static`); the
  paper's own check (and our notebook 02) finds the longitudinal footprint motion
  insignificant for the vertical hub force.
* **Quasi-static run** (:func:`quasi_static_run`): a sequence of contact solves on the
  static compliance condensed on the tread points while the cleat moves, hub held at the
  static deflection; exact force balance at every step.
* **Dynamic run** (:func:`dynamic_run`): implicit Newmark stepping (average acceleration,
  unconditionally stable, no numerical damping) of all belt DOF, hub fixed. The
  frequency-dependent moduli of every compound and layer (:mod:`roadnoise_utils.tire.rubber`)
  are represented by their Prony series: one auxiliary displacement per Maxwell branch,
  updated exactly for a displacement linear over the step. So the time-domain model is the
  *same* viscoelastic model as the frequency-domain FETvisco (to the Prony fit error, < 0.1 %
  over 1-1000 Hz, < 0.4 % down to 0.1 Hz), not a modal damping identified at one frequency; a lifted tread element
  relaxes through its own branches. Each step costs two banded solves and a small dense
  active-set solve on the tread points near the footprint (the dynamic compliance
  :math:`G = E^T K_{eff}^{-1} E` is factorised once).

With the contact frozen (every static contact point bilateral, no lift-off) the dynamic run is
linear and must equal the frequency-domain FE response (:func:`frozen_reference`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import guards

#: Largest road travel per time step, as a share of the contact-point spacing (refused beyond).
MAX_TRAVEL_PER_STEP = 0.5
#: Default time step (s): 40 steps per period at 250 Hz; the frozen run then matches the frequency
#: domain to 0.5 % RMS (twice the step: 1.9 %, the trapezoidal rule's period error).
DT_MAX = 1.0e-4
#: Most time steps a run may take (a very slow dynamic run is a quasi-static one).
MAX_STEPS = 200_000


@dataclass(frozen=True, eq=False)
class ContactRun:
    """A cleat passage with one-sided (or frozen) contact.

    Attributes
    ----------
    distance : ndarray
        Travel (m), 0 = the cleat's leading edge under the axle.
    t : ndarray
        Time (s); for a quasi-static run ``distance`` over a nominal 1 m/s.
    hub_force : ndarray
        Vertical hub force minus the static load (N), positive upward.
    contact_points : ndarray of int
        Tread points in contact at each step.
    on_profile : ndarray of bool
        Some tread point in contact stands on the raised profile (the cleat) at each step.
    speed : float
        Rolling speed (m/s); 0 for a quasi-static run.
    contact : str
        ``"one-sided"`` or ``"frozen"``.
    max_penetration : float
        Largest penetration of the road into a free tread surface out of contact (m), all steps,
        from the belt displacement of the step's own solve (not from the active-set algebra).
    force_balance : float
        Quasi-static: largest residual over the load (-), from a fresh solve of the belt under the
        contact forces: ``|hub reaction - sum of contact forces|`` and, at every point in contact,
        ``|k * penetration - force|``; dynamic: NaN.
    iterations : int
        Most active-set iterations any step needed.
    """

    distance: np.ndarray
    t: np.ndarray
    hub_force: np.ndarray
    contact_points: np.ndarray
    on_profile: np.ndarray
    speed: float
    contact: str
    max_penetration: float
    force_balance: float
    iterations: int

    @classmethod
    def quasi_static(
        cls,
        travel: np.ndarray,
        start: float,
        hub_force: np.ndarray,
        contact_points: np.ndarray,
        on_profile: np.ndarray,
        max_penetration: float,
        force_balance: float,
        iterations: int,
    ) -> ContactRun:
        """A quasi-static run of one-sided contact: ``t`` is the travel from ``start`` (m) over a nominal 1 m/s,
        ``hub_force`` the hub force increase over the static load (N)."""
        return cls(
            travel, travel - start, hub_force, contact_points, on_profile, 0.0, "one-sided",
            max_penetration, force_balance, iterations,
        )  # fmt: skip

    @classmethod
    def dynamic(
        cls,
        travel: np.ndarray,
        dt: float,
        hub_force: np.ndarray,
        contact_points: np.ndarray,
        on_profile: np.ndarray,
        speed: float,
        frozen: bool,
        max_penetration: float,
        iterations: int,
    ) -> ContactRun:
        """A dynamic run stepped every ``dt`` s at ``speed`` (m/s), one-sided or ``frozen`` contact
        (no force balance: NaN; a penetration below zero counts as none)."""
        return cls(
            travel, dt * np.arange(travel.size), hub_force, contact_points, on_profile, speed,
            "frozen" if frozen else "one-sided", max(float(max_penetration), 0.0), float("nan"), int(iterations),
        )  # fmt: skip

    @property
    def dt(self) -> float:
        """Time step (s)."""
        return float(self.t[1] - self.t[0])

    @property
    def peak_force(self) -> float:
        """Largest hub-force increase (N)."""
        return float(self.hub_force.max())


def check_travel_step(spacing: float, speed: float, dt: float) -> None:
    """Refuse a time step in which the road moves more than half the contact-point ``spacing`` (m)."""
    travel = speed * dt
    if travel > MAX_TRAVEL_PER_STEP * spacing:
        raise ValueError(
            f"dt = {dt:g} s moves the road {travel * 1e3:.2f} mm per step at {speed:g} m/s, against contact points "
            f"{spacing * 1e3:.1f} mm apart: valid range is dt <= {MAX_TRAVEL_PER_STEP * spacing / speed:.3g} s "
            "(a step too coarse for the contact)"
        )


def time_steps(
    spacing: float, speed: float, distance: tuple[float, float], dt: float | None
) -> tuple[float, np.ndarray]:
    """The time step (s) and the travel at each step (m) of a dynamic run, checked before any work.

    ``dt`` defaults to :data:`DT_MAX`, or less so that the road moves at most a quarter of the
    contact-point ``spacing`` (m) per step; shared by the runs of both tire models.
    """
    d0, d1 = guards.interval("distance", distance)
    dt = min(DT_MAX, 0.25 * spacing / speed) if dt is None else guards.real("dt", dt, 0.0, 0.01, lo_open=True, unit="s")
    check_travel_step(spacing, speed, dt)
    n_steps = int(np.floor((d1 - d0) / (speed * dt))) + 1
    check_steps(n_steps, speed, (d0, d1), dt)
    return dt, d0 + speed * dt * np.arange(n_steps)


def check_frozen(frozen: tuple[bool, ...]) -> None:
    """Refuse ``frozen`` unless it holds one or more booleans, one per run of a dynamic passage."""
    if not frozen or not all(isinstance(f, bool | np.bool_) for f in frozen):
        raise ValueError(f"frozen = {frozen!r}: give one or more booleans, one per run")


def check_steps(n_steps: int, speed: float, distance: tuple[float, float], dt: float) -> None:
    """Refuse a run of more than :data:`MAX_STEPS` time steps (a speed too low for the time step)."""
    if n_steps > MAX_STEPS:
        low = (distance[1] - distance[0]) / (MAX_STEPS * dt)
        raise ValueError(
            f"speed = {speed:g} m/s needs {n_steps} steps of dt = {dt:g} s over {distance[1] - distance[0]:g} m: "
            f"valid range is speed >= {low:.3g} m/s for this step (run the quasi-static solve for slower passages)"
        )
