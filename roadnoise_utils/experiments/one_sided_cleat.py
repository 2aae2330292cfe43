"""The measured cleat test with one-sided contact: the FE tire itself on the drum (beyond the paper).

The paper compares its linear RM chain with a drum test (*Validation of the Model for Fixed
Hub*, Fig. 8-9): 850 N measured quasi-static against 1200 N simulated, a dynamic peak about
2.2 times the quasi-static one at 30 km/h. In that test the tread next to the 15 mm cleat lifts
off the drum, which no linear model can do. Here the FE tire (not the RM chain) runs the test
with one-sided tread contact (:mod:`roadnoise_utils.response.one_sided`), on a mesh refined
along the circumference (``[one_sided] n_elements`` of ``data/conditions/cleat_test.toml``),
and is compared with the *measured* values; the linear chain stays compared with the paper's
*simulation* (:mod:`.cleat`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .. import guards
from ..analysis import damped_components, force_peaks, relative_rms_error
from ..repro import stages
from ..response.fe_reference import band_limited, fe_point_response
from ..response.one_sided import ContactRun
from ..rm.simulation import modal_sections
from ..road.cleat import cleat_profile, point_heights
from ..tire.cross_section.spec import CrossSectionSpec
from ..tire.section_static import SectionStaticState
from ..tire.spec import TireSpec
from ..tire.static import DEFLECTION_LIMIT, StaticState
from .cleat import DECAY_COMPONENTS, PAPER_TIRE, CleatConditions, cleat_conditions, in_band, run_cleat
from .conditions import load_conditions, resolve

#: Largest mesh the one-sided runs accept (elements around the circumference).
MAX_ELEMENTS = 2400


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
    tire : TireSpec or CrossSectionSpec
        The tire (the ring with the refined mesh).
    conditions : OneSidedConditions
        The resolved conditions.
    static : StaticState or SectionStaticState
        The tire loaded on the drum.
    quasi_static, dynamic : ContactRun
        The base curve (contact solves) and the run at the dynamic speed (time stepping; on the
        cross-section tire band-limited to 250 Hz, :mod:`.section_contact`).
    peaks : pandas.DataFrame
        The two largest peaks of the dynamic run while the cleat touches the tire.
    decay : pandas.DataFrame
        Damped components of the free decay after the cleat has left (largest first).
    """

    tire: TireSpec | CrossSectionSpec
    conditions: OneSidedConditions
    static: StaticState | SectionStaticState
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
        rows = {
            "quasi-static peak (N)": self.quasi_static.peak_force,
            f"peak at {self.conditions.cleat.dynamic_kmh:.0f} km/h (N)": self.dynamic.peak_force,
            "dynamic / quasi-static": self.ratio,
            "decay: leading component (Hz)": float(self.decay["frequency (Hz)"].iloc[0]),
            "decay: its damping ratio": float(self.decay["damping ratio"].iloc[0]),
            "contact points, static": int(self.static.contact.sum()),
            "contact points, fewest (quasi-static)": int(self.quasi_static.contact_points.min()),
            f"contact points, fewest ({self.conditions.cleat.dynamic_kmh:.0f} km/h)": int(
                self.dynamic.contact_points.min()
            ),
        }
        return pd.DataFrame({"one-sided contact": rows}).rename_axis("quantity")


def refined_tire(tire: str | TireSpec, n_elements: int) -> TireSpec:
    """The tire with ``n_elements`` around the circumference (everything else unchanged)."""
    spec = stages.load_tire(tire)
    if spec.mesh.n_elements == n_elements:
        return spec
    return spec.replace(**{"mesh.n_elements": n_elements}, name=f"{spec.name} ({n_elements} elements)")


def check_cleat_height(static: StaticState, height: float) -> None:
    """Refuse a cleat the tire cannot envelop; warn when it is taller than the static deflection.

    Over the cleat the tire deflects by its static deflection plus the cleat height; past
    :data:`~roadnoise_utils.tire.static.DEFLECTION_LIMIT` of the section height it would
    bottom on the rim, which the model does not know.
    """
    g = static.tire.geometry
    section = g.section_width * g.aspect_ratio
    room = DEFLECTION_LIMIT * section - static.deflection
    if height > room:
        raise ValueError(
            f"cleat height = {height * 1e3:.1f} mm: valid range is <= {room * 1e3:.1f} mm, what the tire can envelop "
            f"over its {static.deflection * 1e3:.1f} mm static deflection ({DEFLECTION_LIMIT:.0%} of the "
            f"{section * 1e3:.0f} mm section height in all)"
        )
    if height > static.deflection:
        guards.warn(
            f"cleat height = {height * 1e3:.1f} mm exceeds the static deflection ({static.deflection * 1e3:.1f} mm): "
            "the whole footprint lifts off the drum over the cleat",
            stacklevel=3,
        )


def _run(spec: TireSpec, test: OneSidedConditions, speed: float, distance, frozen: bool = False) -> ContactRun:
    c = test.cleat
    return stages.one_sided_run(
        spec, speed, c.height, c.base, c.shape, c.drum_radius, distance, frozen=frozen, step=test.quasi_static_step
    )


def one_sided_cleat_test(
    tire: str | TireSpec = PAPER_TIRE, *, conditions: OneSidedConditions | None = None
) -> OneSidedCleatTest:
    """The cleat test with one-sided contact: quasi-static contact solves and the dynamic run (cached)."""
    test = one_sided_conditions() if conditions is None else conditions
    spec = refined_tire(tire, test.n_elements)
    static = stages.solve_static(spec, "drum", drum_radius=test.cleat.drum_radius)
    check_cleat_height(static, test.cleat.height)
    quasi = _run(spec, test, 0.0, test.distance)
    dynamic = _run(spec, test, test.cleat.dynamic_speed, test.distance)
    return OneSidedCleatTest(spec, test, static, quasi, dynamic, *peaks_and_decay(dynamic))


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


def speed_sweep(tire: str | TireSpec = PAPER_TIRE, *, conditions: OneSidedConditions | None = None) -> pd.DataFrame:
    """Peak hub force against speed: the linear RM chain (paper's method) and one-sided contact (N)."""
    test = one_sided_conditions() if conditions is None else conditions
    c = test.cleat
    spec = stages.load_tire(tire)
    drum = {"road": "drum", "drum_radius": c.drum_radius}
    sections = modal_sections(stages.assemble_fixed_hub(spec, **drum))
    static = stages.solve_static(spec, **drum)
    refined = refined_tire(spec, test.n_elements)
    rows = {}
    for kmh in test.sweep_kmh:
        linear = run_cleat(sections, static, kmh / 3.6, c.height, c.base, c.shape, test.sweep_distance, dynamic=False)
        contact = _run(refined, test, kmh / 3.6, test.sweep_distance)
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
    tire: str | TireSpec = PAPER_TIRE, *, conditions: OneSidedConditions | None = None, duration: float = 1.0
) -> FrozenCheck:
    """Run the dynamic cleat passage with the contact frozen and compare it with the FE frequency domain.

    On the tire's own mesh. The frequency-domain reference
    (:func:`roadnoise_utils.response.fe_reference.fe_point_response`, footprint sliding freely
    as the frictionless contact) sees the same hat-averaged heights under every contact point.
    """
    test = one_sided_conditions() if conditions is None else conditions
    c = test.cleat
    spec = stages.load_tire(tire)
    static = stages.solve_static(spec, "drum", drum_radius=c.drum_radius)
    run = _run(spec, test, c.dynamic_speed, test.distance, frozen=True)
    t = static.tasselli
    heights = point_heights(
        t.node_x, t.node_dx_minus, t.node_dx_plus, cleat_profile(c.height, c.base, c.shape), run.distance
    )
    fet = stages.build_fet(spec)
    reference = fe_point_response(fet, static, heights, run.dt, duration=duration, stick=False)
    time_domain = band_limited(run.hub_force, run.dt, n_fft=max(run.t.size, int(round(duration / run.dt))))
    window = run.distance <= 0.3
    return FrozenCheck(run, time_domain, reference, window)
