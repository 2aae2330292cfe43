"""The measured cleat test with one-sided contact: the FE tire itself on the drum (beyond the paper).

The paper compares its linear RM chain with a drum test (*Validation of the Model for Fixed
Hub*, Fig. 8-9): 850 N measured quasi-static against 1200 N simulated, a dynamic peak about
2.2 times the quasi-static one at 30 km/h. In that test the tread next to the 15 mm cleat lifts
off the drum, which no linear model can do. Here the FE tire (not the RM chain) runs the test
with one-sided tread contact (:mod:`roadnoise_utils.tire.contact`), on a mesh refined
along the circumference (``[one_sided] n_elements`` of ``data/conditions/cleat_test.toml``),
and is compared with the *measured* values; the linear chain stays compared with the paper's
*simulation* (:mod:`~roadnoise_utils.experiments.cleat`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import pandas as pd

from .. import guards
from ..analysis import damped_components, force_peaks, relative_rms_error
from ..repro import stages
from ..repro.stages import Tire
from ..response.band_limit import band_limited
from ..rm.simulation import modal_sections
from ..tire.contact import ContactRun
from ..tire.model import ContactSetup, Footprint, ModelSpec, tire_model
from .cleat import (
    DECAY_COMPONENTS,
    PAPER_TIRE,
    CleatConditions,
    cleat_conditions,
    cleat_numbers,
    in_band,
    run_cleat,
)
from .conditions import load_conditions, resolve
from .passage import RECORD

#: Largest mesh the one-sided runs accept (elements around the circumference).
MAX_ELEMENTS = 2400
#: Vanishing-speed runs of :func:`convergence`: (speed in m/s, time step in s). 0.1 m/s is the
#: paper's base-curve speed (0.36 km/h, *Validation of the Model for Fixed Hub*); 0.03 m/s is
#: slower still. The steps keep about 0.5 mm and 0.3 mm of travel per step.
SLOW_RUNS = ((0.1, 5e-3), (0.03, 1e-2))


@dataclass(frozen=True)
class OneSidedConditions:
    """The one-sided runs' conditions, every default resolved.

    Attributes
    ----------
    cleat : CleatConditions
        Drum, cleat and speeds (shared with the linear test).
    n_elements : int
        Elements around the circumference of the refined tire.
    distance : (float, float)
        Travel of the dynamic and quasi-static runs (m), starting before the cleat touches.
    quasi_static_step : float
        Travel between quasi-static contact solves (m).
    sweep_kmh : tuple of float
        Speeds of the peak-against-speed sweep (km/h).
    sweep_distance : (float, float)
        Travel of each sweep run (m).
    """

    cleat: CleatConditions
    n_elements: int
    distance: tuple[float, float]
    quasi_static_step: float
    sweep_kmh: tuple[float, ...]
    sweep_distance: tuple[float, float]


def one_sided_conditions(
    cleat: CleatConditions | None = None,
    n_elements: int | None = None,
    distance: tuple[float, float] | None = None,
    sweep_kmh: tuple[float, ...] | None = None,
) -> OneSidedConditions:
    """``[one_sided]`` of ``data/conditions/cleat_test.toml`` (read once), any value given here overriding it."""
    table = load_conditions("cleat_test")
    given = resolve(
        table, "one_sided", n_elements=n_elements, distance=distance, sweep_kmh=sweep_kmh,
        quasi_static_step=None, sweep_distance=None,
    )  # fmt: skip
    speeds = tuple(
        guards.real("sweep_kmh", v, 0.0, 360.0, lo_open=True, unit="km/h") for v in np.atleast_1d(given["sweep_kmh"])
    )
    if not speeds:
        raise ValueError("sweep_kmh = (): give at least one speed (km/h), e.g. (30.0, 60.0)")
    return OneSidedConditions(
        cleat=cleat_conditions() if cleat is None else cleat,
        n_elements=guards.integer("n_elements", given["n_elements"], 100, MAX_ELEMENTS),
        distance=guards.interval("distance", given["distance"]),
        quasi_static_step=guards.real(
            "quasi_static_step", given["quasi_static_step"], 0.0, 0.01, lo_open=True, unit="m"
        ),
        sweep_kmh=speeds,
        sweep_distance=guards.interval("sweep_distance", given["sweep_distance"]),
    )


@dataclass(frozen=True, eq=False)
class OneSidedCleatTest:
    """The cleat test with one-sided contact: the refined tire on the drum and both runs.

    Attributes
    ----------
    tire : spec
        The validated tire file the runs used (the ring's with its refined mesh).
    conditions : OneSidedConditions
        The resolved conditions.
    static : Footprint
        The tire loaded on the drum.
    quasi_static, dynamic : ContactRun
        The base curve (contact solves) and the run at the dynamic speed (time stepping; on the
        cross-section tire band-limited to 250 Hz: :class:`~roadnoise_utils.tire.model.ContactSetup`).
    peaks : pandas.DataFrame
        The two largest peaks of the dynamic run while the cleat touches the tire.
    decay : pandas.DataFrame
        Damped components of the free decay after the cleat has left (largest first).
    """

    tire: Any
    conditions: OneSidedConditions
    static: Footprint
    quasi_static: ContactRun
    dynamic: ContactRun
    peaks: pd.DataFrame
    decay: pd.DataFrame

    @property
    def ratio(self) -> float:
        """Dynamic over quasi-static peak (-)."""
        return self.dynamic.peak_force / self.quasi_static.peak_force

    def to_frame(self) -> pd.DataFrame:
        """Key numbers, one row per quantity (paper units)."""
        kmh = self.conditions.cleat.dynamic_kmh
        rows = {
            **cleat_numbers(self.quasi_static.peak_force, self.dynamic.peak_force, kmh, self.decay),
            "contact points, static": self.static.contact_points,
            "contact points, fewest (quasi-static)": int(self.quasi_static.contact_points.min()),
            f"contact points, fewest ({self.conditions.cleat.dynamic_kmh:.0f} km/h)": int(
                self.dynamic.contact_points.min()
            ),
        }
        return pd.DataFrame({"one-sided contact": rows}).rename_axis("quantity")


def refined_tire(tire: Tire, n_elements: int) -> ModelSpec:
    """The ring tire with ``n_elements`` around the circumference (everything else unchanged)."""
    return tire_model(tire).refined(n_elements).spec


def _run(setup: ContactSetup, test: OneSidedConditions, speed: float, distance, frozen: bool = False) -> ContactRun:
    c = test.cleat
    return stages.one_sided_run(
        setup.model, speed, c.height, c.base, c.shape, c.drum_radius, distance,
        frozen=frozen, step=setup.quasi_static_step, dt=setup.dt,
    )  # fmt: skip


def in_model_band(setup: ContactSetup, run: ContactRun) -> ContactRun:
    """The run with its hub force band-limited to the model's compared band (zero phase, over a
    :data:`RECORD` s record), or as stepped where the model compares it raw."""
    if setup.band is None:
        return run
    n_fft = max(run.t.size, int(round(RECORD / run.dt)))
    return replace(run, hub_force=band_limited(run.hub_force, run.dt, setup.band, n_fft=n_fft))


def one_sided_cleat_test(tire: Tire = PAPER_TIRE, *, conditions: OneSidedConditions | None = None) -> OneSidedCleatTest:
    """The cleat test with one-sided contact: quasi-static contact solves and the dynamic run (cached),
    as the tire's model runs it (:meth:`~roadnoise_utils.tire.model.TireModel.one_sided_setup`)."""
    test = one_sided_conditions() if conditions is None else conditions
    setup = tire_model(tire).one_sided_setup(test)
    static = setup.model.load(setup.model.case("drum", drum_radius=test.cleat.drum_radius))
    quasi = _run(setup, test, 0.0, setup.quasi_static_distance)
    dynamic = in_model_band(setup, _run(setup, test, test.cleat.dynamic_speed, test.distance))
    return OneSidedCleatTest(setup.model.spec, test, static, quasi, dynamic, *peaks_and_decay(dynamic))


@dataclass(frozen=True)
class Convergence:
    """How the one-sided runs converge in mesh, time step and speed (every run a cached stage).

    Attributes
    ----------
    quasi_static_peaks : dict of int to float
        Quasi-static peak (N) per mesh (elements around the circumference): the tire file's
        mesh, then the refined one of the test.
    dynamic_peaks : dict of int to float
        Peak at the dynamic speed (N) on the same two meshes.
    step_peaks : dict of float to float
        Peak at the dynamic speed (N) on the tire file's mesh per time step (s): the model's
        step, then half of it.
    slow_peaks : dict of float to float
        Peak (N) per vanishing speed (m/s, :data:`SLOW_RUNS`) on the tire file's mesh over the
        sweep's travel.
    slow_quasi_static : float
        The quasi-static peak over that travel on that mesh (N): what the slow runs tend to.
    """

    quasi_static_peaks: dict[int, float]
    dynamic_peaks: dict[int, float]
    step_peaks: dict[float, float]
    slow_peaks: dict[float, float]
    slow_quasi_static: float


def convergence(
    tire: Tire = PAPER_TIRE, *, conditions: OneSidedConditions | None = None, slow_runs=SLOW_RUNS
) -> Convergence:
    """The one-sided cleat test on the tire file's mesh and the refined one, at the model's time
    step and half of it, and at vanishing speeds against the quasi-static run.

    The dynamic run on the refined mesh is the test's own (:func:`one_sided_cleat_test`); the
    other runs are the ring tire's stages at their default steps. Raises
    :class:`~roadnoise_utils.tire.model.NotApplicable` for a model that cannot be refined.
    """
    test = one_sided_conditions() if conditions is None else conditions
    c = test.cleat
    drum = (c.height, c.base, c.shape, c.drum_radius)
    coarse = stages.load_tire(tire)
    quasi = {
        n: stages.one_sided_run(refined_tire(tire, n), 0.0, *drum, test.distance).peak_force
        for n in (coarse.mesh.n_elements, test.n_elements)
    }
    dynamic = stages.one_sided_run(coarse, c.dynamic_speed, *drum, test.distance)
    half = stages.one_sided_run(coarse, c.dynamic_speed, *drum, test.distance, dt=0.5 * dynamic.dt)
    refined_dynamic = one_sided_cleat_test(tire, conditions=test).dynamic
    slow = {
        speed: stages.one_sided_run(coarse, speed, *drum, test.sweep_distance, dt=dt).peak_force
        for speed, dt in slow_runs
    }
    return Convergence(
        quasi_static_peaks=quasi,
        dynamic_peaks={coarse.mesh.n_elements: dynamic.peak_force, test.n_elements: refined_dynamic.peak_force},
        step_peaks={dynamic.dt: dynamic.peak_force, half.dt: half.peak_force},
        slow_peaks=slow,
        slow_quasi_static=stages.one_sided_run(coarse, 0.0, *drum, test.sweep_distance).peak_force,
    )


def raw_dynamic(tire: Tire = PAPER_TIRE, *, conditions: OneSidedConditions | None = None) -> ContactRun:
    """The dynamic one-sided run as stepped (not band-limited)."""
    test = one_sided_conditions() if conditions is None else conditions
    return _run(tire_model(tire).one_sided_setup(test), test, test.cleat.dynamic_speed, test.distance)


def peaks_and_decay(run: ContactRun) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Peaks while the cleat touches the tire, and the free decay after it has left the tread."""
    touching = np.nonzero(run.on_profile)[0]
    last = run.distance[touching[-1]] if touching.size else run.distance[0]
    peaks = force_peaks(run.distance, run.hub_force, n=2, window=(run.distance[0], last))
    free = run.distance > last + 0.01
    if free.sum() < 4 * DECAY_COMPONENTS:
        raise ValueError(f"distance ends {run.distance[-1]:.3f} m, the cleat leaves at {last:.3f} m: too little decay")
    decay = in_band(damped_components(run.hub_force[free], run.dt, n_components=DECAY_COMPONENTS), 250.0)
    return peaks, decay


def speed_sweep(tire: Tire = PAPER_TIRE, *, conditions: OneSidedConditions | None = None) -> pd.DataFrame:
    """Peak hub force against speed: the linear RM chain (paper's method) and one-sided contact (N)."""
    test = one_sided_conditions() if conditions is None else conditions
    c = test.cleat
    model = tire_model(tire)
    drum = {"road": "drum", "drum_radius": c.drum_radius}
    sections = modal_sections(stages.assemble_fixed_hub(model, **drum))
    static = stages.solve_static(model, **drum)
    setup = model.one_sided_setup(test)
    rows = {}
    for kmh in test.sweep_kmh:
        linear = run_cleat(sections, static, kmh / 3.6, c.height, c.base, c.shape, test.sweep_distance, dynamic=False)
        contact = in_model_band(setup, _run(setup, test, kmh / 3.6, test.sweep_distance))
        rows[kmh] = {
            "linear chain (N)": linear.peak_force,
            "one-sided contact (N)": contact.peak_force,
            "contact points, fewest": int(contact.contact_points.min()),
        }
    return pd.DataFrame(rows).T.rename_axis("speed (km/h)")


@dataclass(frozen=True, eq=False)
class FrozenCheck:
    """The dynamic run with contact frozen against the frequency-domain FE response (same point inputs).

    Attributes
    ----------
    run : ContactRun
        The frozen time-stepped run.
    time_domain, frequency_domain : ndarray
        Hub force (N), both band-limited to 250 Hz the same way.
    window : ndarray of bool
        Samples compared (the passage and the start of the decay; the end of a record cut in
        mid-decay is smeared by the band-limiting).
    """

    run: ContactRun
    time_domain: np.ndarray
    frequency_domain: np.ndarray
    window: np.ndarray

    @property
    def peak_difference(self) -> float:
        """Time-domain peak over frequency-domain peak, minus one (-)."""
        return float(self.time_domain.max() / self.frequency_domain.max() - 1.0)

    @property
    def rms_difference(self) -> float:
        """Relative RMS difference over :attr:`window` (-)."""
        return relative_rms_error(self.time_domain[self.window], self.frequency_domain[self.window])


def frozen_check(
    tire: Tire = PAPER_TIRE, *, conditions: OneSidedConditions | None = None, duration: float = 1.0
) -> FrozenCheck:
    """Run the dynamic cleat passage with the contact frozen and compare it with the FE frequency domain.

    On the tire's own mesh. The frequency-domain reference
    (:meth:`~roadnoise_utils.tire.model.TireModel.frozen_reference`: the FE solve of the ring, the
    footprint FRFs of the cross-section) sees the same hat-averaged heights under every contact
    point; both are band-limited the same way.
    """
    duration = guards.real("duration", duration, 0.0, 60.0, lo_open=True, unit="s")
    test = one_sided_conditions() if conditions is None else conditions
    c = test.cleat
    model = tire_model(tire)
    setup = ContactSetup(model, test.distance, test.quasi_static_step, model.contact_dt, None)
    run = _run(setup, test, c.dynamic_speed, test.distance, frozen=True)
    case = model.case("drum", drum_radius=c.drum_radius)
    time_domain, reference = model.frozen_reference(case, run, (c.height, c.base, c.shape), duration)
    window = run.distance <= 0.3
    return FrozenCheck(run, time_domain, reference, window)
