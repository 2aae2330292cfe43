"""The cleat test on the drum with the hub fixed (paper stage 8, Fig. 8-9).

Paper, *Validation of the Model for Fixed Hub*: 165/65 R14, 4J rim, 2.3 bar, 4512 N, drum
R = 1.25 m, triangular cleat 15 mm base x 15 mm high, a quasi-static run ("base curve") and
one at 30 km/h ("dynamic curve"). Reported: two force peaks while the cleat crosses the
footprint; measured dynamic peak about 2.2 times the quasi-static one; simulated quasi-static
peak 1200 N against 850 N measured; the simulated dynamic peak "very close to the measured
one"; after the cleat has left, a decay dominated by the 80 Hz first vertical mode
(``data/paper/claims.toml`` keeps these numbers with their source).

:func:`cleat_conditions` reads ``data/conditions/cleat_test.toml`` once and resolves every
default; :func:`cleat_test` runs the RM chain (fitted state-space tire,
:func:`roadnoise_utils.rm.simulation.simulate`) and, on request, the same passage straight
from the viscoelastic FE model in the frequency domain (no modal reduction, no fitting,
:func:`roadnoise_utils.tire.ring.fe_reference.fe_cleat_response`; :mod:`.passage`).
"""

from __future__ import annotations

from dataclasses import dataclass

import control
import numpy as np
import pandas as pd

from .. import guards
from ..analysis import damped_components, force_peaks
from ..repro import stages
from ..repro.cache import cached
from ..repro.stages import Tire
from ..rm.simulation import ModalSections, SimulationResult, modal_sections, simulate
from ..road.cleat import cleat_input, cleat_profile
from ..road.input import BAND, RoadInput
from ..tire.model import Footprint, ModelSpec, tire_model
from .conditions import load_conditions, resolve
from .passage import FEComparison, fe_passage, rm_cleat_response, simulated_in_band

#: The paper's tire for this test.
PAPER_TIRE = "165_65R14"
#: Cleat shapes (:func:`roadnoise_utils.road.cleat.cleat_profile`).
CLEAT_SHAPES = ("triangle", "rectangle", "half-sine")
#: Fastest speed accepted (km/h): a test drum or a road car; more is a unit slip.
MAX_SPEED_KMH = 360.0


@dataclass(frozen=True)
class CleatConditions:
    """The cleat test's conditions, every default resolved (SI units but speeds in km/h, as the paper gives them).

    Attributes
    ----------
    drum_radius : float
        Drum radius (m).
    shape : str
        Cleat shape (:func:`roadnoise_utils.road.cleat.cleat_profile`).
    height, base : float
        Cleat height and length along the road (m).
    dynamic_kmh, quasi_static_kmh : float
        Speeds of the dynamic and the quasi-static ("base curve") runs (km/h).
    quasi_static_distance, dynamic_distance : (float, float)
        Travel simulated in each run (m; 0 = the cleat's leading edge under the axle).
    fe_distance : (float, float)
        Travel of the FE reference comparison (m).
    fe_duration : float
        Record both methods of the comparison see, padded with a flat road (s).
    """

    drum_radius: float
    shape: str
    height: float
    base: float
    dynamic_kmh: float
    quasi_static_kmh: float
    quasi_static_distance: tuple[float, float]
    dynamic_distance: tuple[float, float]
    fe_distance: tuple[float, float]
    fe_duration: float

    @property
    def dynamic_speed(self) -> float:
        """Speed of the dynamic run (m/s)."""
        return self.dynamic_kmh / 3.6

    @property
    def quasi_static_speed(self) -> float:
        """Speed of the quasi-static run (m/s)."""
        return self.quasi_static_kmh / 3.6

    def describe(self) -> str:
        """One line: the cleat and the drum."""
        return (
            f"{self.shape} cleat, base {self.base * 1e3:.0f} mm, height {self.height * 1e3:.0f} mm, "
            f"on a drum of R = {self.drum_radius:.2f} m"
        )


def cleat_conditions(
    height: float | None = None,
    base: float | None = None,
    shape: str | None = None,
    dynamic_kmh: float | None = None,
    quasi_static_kmh: float | None = None,
    drum_radius: float | None = None,
) -> CleatConditions:
    """The paper's cleat test (``data/conditions/cleat_test.toml``, read once), any value given here overriding it."""
    table = load_conditions("cleat_test")
    cleat = resolve(table, "cleat", height=height, base=base, shape=shape)
    speeds = resolve(table, "speeds", dynamic_kmh=dynamic_kmh, quasi_static_kmh=quasi_static_kmh)
    runs = resolve(table, "runs", quasi_static_distance=None, dynamic_distance=None, fe_distance=None, fe_duration=None)
    if cleat["shape"] not in CLEAT_SHAPES:
        raise ValueError(f"shape = {cleat['shape']!r}: valid values are {list(CLEAT_SHAPES)}")
    return CleatConditions(
        drum_radius=guards.real(
            "drum_radius", resolve(table, "drum", radius=drum_radius)["radius"], 0.3, 20.0, lo_open=True, unit="m"
        ),
        shape=cleat["shape"],
        height=guards.real("height", cleat["height"], 0.0, 0.1, lo_open=True, unit="m"),
        base=guards.real("base", cleat["base"], 0.0, 0.5, lo_open=True, unit="m"),
        dynamic_kmh=guards.real("dynamic_kmh", speeds["dynamic_kmh"], 0.0, MAX_SPEED_KMH, lo_open=True, unit="km/h"),
        quasi_static_kmh=guards.real(
            "quasi_static_kmh", speeds["quasi_static_kmh"], 0.0, MAX_SPEED_KMH, lo_open=True, unit="km/h"
        ),
        quasi_static_distance=guards.interval("quasi_static_distance", runs["quasi_static_distance"]),
        dynamic_distance=guards.interval("dynamic_distance", runs["dynamic_distance"]),
        fe_distance=guards.interval("fe_distance", runs["fe_distance"]),
        fe_duration=guards.real("fe_duration", runs["fe_duration"], 0.0, 60.0, lo_open=True, unit="s"),
    )


@dataclass(frozen=True, eq=False)
class CleatRun:
    """One cleat passage: the road input, the hub force and what we read from it.

    Attributes
    ----------
    result : SimulationResult
        Hub force history (N) against distance travelled (m) in the fit's band
        (:func:`.passage.simulated_in_band`): the chain's answer, which the peaks are read from.
    peaks : pandas.DataFrame
        The two largest force peaks (distance, force).
    decay : pandas.DataFrame or None
        Damped components of the free decay after the cleat has left the footprint (largest
        first), or ``None`` for a quasi-static run.
    stepped : SimulationResult
        The hub force as simulated, before the band limit.
    """

    result: SimulationResult
    peaks: pd.DataFrame
    decay: pd.DataFrame | None
    stepped: SimulationResult

    @property
    def peak_force(self) -> float:
        """Largest hub force in the fit's band (N)."""
        return float(self.result.force.max())


@dataclass(frozen=True, eq=False)
class CleatTest:
    """The cleat test of one tire: conditions, the tire on the drum, both runs and the FE check.

    Attributes
    ----------
    tire : ModelSpec
        The tire.
    conditions : CleatConditions
        The resolved test conditions.
    static : Footprint
        The tire loaded on the drum.
    system : control.StateSpace
        The fixed-hub state-space tire fitted on the drum footprint (Eq. 3-4).
    sections : ModalSections
        Its decomposition, as :func:`roadnoise_utils.rm.simulation.simulate` runs it.
    quasi_static, dynamic : CleatRun
        The base-curve and the dynamic run.
    fe_reference : FEComparison or None
        The dynamic passage from the FE model and from the RM chain, if asked for.
    """

    tire: ModelSpec
    conditions: CleatConditions
    static: Footprint
    system: control.StateSpace
    sections: ModalSections
    quasi_static: CleatRun
    dynamic: CleatRun
    fe_reference: FEComparison | None

    @property
    def ratio(self) -> float:
        """Dynamic over quasi-static peak force (-); the paper measured about 2.2."""
        return self.dynamic.peak_force / self.quasi_static.peak_force

    def to_frame(self) -> pd.DataFrame:
        """The test's key numbers, one row per quantity, in the paper's units."""
        rows = cleat_numbers(
            self.quasi_static.peak_force, self.dynamic.peak_force, self.conditions.dynamic_kmh, self.dynamic.decay
        )
        return pd.DataFrame({"ours": rows}).rename_axis("quantity")


def cleat_numbers(quasi_static_peak: float, dynamic_peak: float, dynamic_kmh: float, decay: pd.DataFrame) -> dict:
    """A cleat test's key numbers (N, -, Hz): the two peaks, their ratio and the leading decay component."""
    return {
        "quasi-static peak (N)": quasi_static_peak,
        f"peak at {dynamic_kmh:.0f} km/h (N)": dynamic_peak,
        "dynamic / quasi-static": dynamic_peak / quasi_static_peak,
        "decay: leading component (Hz)": float(decay["frequency (Hz)"].iloc[0]),
        "decay: its damping ratio": float(decay["damping ratio"].iloc[0]),
    }


def footprint_entry(static: Footprint) -> float:
    """Distance travelled (m) at which a feature's leading edge reaches the footprint kernels."""
    t = static.tasselli
    return float(-np.max(t.node_x + t.node_dx_plus))


def footprint_exit(static: Footprint, base: float) -> float:
    """Distance travelled (m) at which a feature of length ``base`` (m) has left the footprint kernels."""
    t = static.tasselli
    return float(base - np.min(t.node_x - t.node_dx_minus))


#: Free decay a dynamic run must record after the cleat has left (s): about five periods at 80 Hz.
DECAY_DURATION = 0.06
#: Damped components extracted from the free decay.
DECAY_COMPONENTS = 6


def analyse_run(
    result: SimulationResult,
    in_band_result: SimulationResult,
    static: Footprint,
    base: float,
    dynamic: bool,
    band: float = BAND,
) -> CleatRun:
    """Peaks while the cleat crosses the footprint and, for a dynamic run, the free-decay components.

    ``result`` is the force as stepped, ``in_band_result`` the same in the fit's band
    (:func:`.passage.simulated_in_band`). The peaks are read in the band. The decay's components are found
    in the force as stepped (a filtered record would ring where it ends), and those above the
    model's band (0-``band`` Hz) are dropped, with a :class:`~roadnoise_utils.guards.RoadnoiseWarning`
    when they carry more than 1 % of the largest amplitude. A record shorter than
    :data:`DECAY_DURATION` after the cleat has left gives a warning (its damping ratios are not
    reliable); one too short to analyse is refused, naming the distance it needs.
    """
    crossing = (footprint_entry(static), footprint_exit(static, base))
    peaks = force_peaks(result.distance, in_band_result.force, n=2, window=crossing)
    decay = None
    if dynamic:
        start = footprint_exit(static, base) + 0.01
        free = result.distance > start
        dt = float(result.t[1] - result.t[0])
        needed = max(4 * DECAY_COMPONENTS, int(DECAY_DURATION / dt))
        where = f"distance ends {result.distance[-1]:.3f} m, the cleat ({base * 1e3:.0f} mm) has left at {start:.3f} m"
        if free.sum() < 4 * DECAY_COMPONENTS:
            raise ValueError(
                f"{where}: too little free decay to analyse; valid range is distance[1] >= "
                f"{start + needed * result.road.speed * dt:.3f} m at this speed"
            )
        if free.sum() < needed:
            guards.warn(
                f"{where}: {free.sum() * dt * 1e3:.0f} ms of free decay, under {DECAY_DURATION * 1e3:.0f} ms; its damping "
                f"ratios are unreliable (distance[1] >= {start + needed * result.road.speed * dt:.3f} m gives enough)"
            )
        decay = in_band(damped_components(result.force[free], dt, n_components=DECAY_COMPONENTS), band)
    return CleatRun(result=in_band_result, peaks=peaks, decay=decay, stepped=result)


def in_band(components: pd.DataFrame, band: float) -> pd.DataFrame:
    """The components at or below ``band`` Hz; a warning names dropped ones that are not negligible."""
    above = components["frequency (Hz)"] > band
    large = above & (components["amplitude"] > 0.01 * components["amplitude"].max())
    if large.any():
        dropped = ", ".join(f"{f:.0f} Hz" for f in components.loc[large, "frequency (Hz)"])
        guards.warn(f"decay components above the {band:g} Hz band of the model dropped: {dropped}", stacklevel=4)
    kept = components[~above].reset_index(drop=True)
    kept.index = pd.Index(range(1, len(kept) + 1), name="component")
    return kept


def run_cleat(
    system: control.StateSpace | ModalSections,
    static: Footprint,
    speed: float,
    height: float,
    base: float,
    shape: str = "triangle",
    distance: tuple[float, float] = (-0.1, 0.5),
    dynamic: bool | None = None,
) -> CleatRun:
    """Simulate one cleat passage with the fixed-hub tire ``system`` and analyse it.

    ``speed`` in m/s, ``height``, ``base`` and ``distance`` in m (see
    :func:`roadnoise_utils.road.cleat.cleat_input`); ``dynamic`` (default: speed above 1 m/s)
    asks for the free-decay analysis.
    """
    road = cleat_input(static, speed, height, base, shape, distance)
    stepped, in_band_result = simulated_in_band(system, road)
    return analyse_run(stepped, in_band_result, static, base, speed > 1.0 if dynamic is None else dynamic)


def cleat_test(
    tire: str | ModelSpec = PAPER_TIRE,
    *,
    conditions: CleatConditions | None = None,
    n_poles: int | None = None,
    fe_reference: bool = False,
) -> CleatTest:
    """The paper's cleat test on a tire: both runs with the RM chain and, optionally, the FE check.

    Parameters
    ----------
    tire : str or ModelSpec
        A tire file name or path, or a spec.
    conditions : CleatConditions, optional
        The test; default :func:`cleat_conditions` (the paper's).
    n_poles : int, optional
        Poles per tassello; default the lowest order that fits every tassello within 1 %.
    fe_reference : bool
        Also compute the dynamic passage from the FE model (:func:`.passage.fe_passage`; cached after the first run).
    """
    spec = stages.load_tire(tire)
    test = cleat_conditions() if conditions is None else conditions
    drum = {"road": "drum", "drum_radius": test.drum_radius}
    static = stages.solve_static(spec, **drum)
    system = stages.assemble_fixed_hub(spec, n_poles=n_poles, **drum)
    sections = modal_sections(system)
    cleat = {"height": test.height, "base": test.base, "shape": test.shape}

    def runs() -> tuple[CleatRun, CleatRun]:
        quasi = run_cleat(
            sections, static, test.quasi_static_speed, **cleat, distance=test.quasi_static_distance, dynamic=False
        )
        decay_end = footprint_exit(static, test.base) + 0.01 + test.dynamic_speed * DECAY_DURATION
        dynamic_distance = (test.dynamic_distance[0], max(test.dynamic_distance[1], decay_end))
        dynamic = run_cleat(sections, static, test.dynamic_speed, **cleat, distance=dynamic_distance, dynamic=True)
        return quasi, dynamic

    # cached: the notebooks and the claims run the same test (the simulations cost ~1 s a tire)
    quasi, dynamic = cached(
        "cleat_runs",
        {"tire": spec, "conditions": test, "n_poles": n_poles},
        runs,
        runs=(run_cleat, analyse_run, simulated_in_band, simulate, cleat_input, *stages.frf_runs(spec)),
    )
    comparison = None
    if fe_reference:
        road, fe_force = fe_passage(spec, test, static)
        comparison = FEComparison(road, fe_force, rm_cleat_response(sections, road, duration=test.fe_duration))
    return CleatTest(spec, test, static, system, sections, quasi, dynamic, comparison)


def quasi_static_force(static_influence: np.ndarray, road: RoadInput) -> np.ndarray:
    """Hub force with no dynamics at all: :math:`\\sum_i H_i(0)\\,u_i` (N)."""
    return np.asarray(static_influence) @ road.u


def point_sampled_peak(
    static: Footprint,
    static_influence: np.ndarray,
    height: float,
    base: float,
    shape: str = "triangle",
    at: str = "nodes",
    resolution: float = 1e-4,
) -> float:
    """The quasi-static cleat peak :math:`\\max_X \\sum_i H_i(0)\\,u_i(X)` (N) with the cleat's height taken at points.

    ``at="nodes"``: each tassello's input the weighted mean of the cleat's height at its contact
    nodes (the road's value at each node, as an FE model's nodal displacements; :func:`cleat_input`
    averages it over each node's shape function instead); ``"centres"``: the height at each
    tassello's centre. The cleat (``height``, ``base`` in m, ``shape``) passes the footprint in
    steps of ``resolution`` (m). On a coarse footprint a narrow cleat is seen whole by one row of
    points, where the shape-function average spreads it over the row's neighbours.
    """
    if at not in ("nodes", "centres"):
        raise ValueError(f"at = {at!r}: valid values are 'nodes', 'centres'")
    resolution = guards.real("resolution", resolution, 0.0, 0.01, lo_open=True, unit="m")
    t = static.tasselli
    profile = cleat_profile(height, base, shape)
    x = t.node_x if at == "nodes" else t.centre_x
    travel = np.arange(-x.max() - resolution, base - x.min() + resolution, resolution)  # the cleat under every point
    heights = profile(x[:, None] + travel[None, :])  # a point at x meets road coordinate x + travel
    if at == "nodes":
        weights = np.zeros((t.n, x.size))
        weights[t.node_tassello, np.arange(x.size)] = t.node_weight
        heights = (weights / weights.sum(axis=1, keepdims=True)) @ heights
    return float((np.asarray(static_influence) @ heights).max())


def row_influence(static: Footprint, static_influence: np.ndarray) -> pd.DataFrame:
    """Static influence summed over each row of tasselli, with the row's position (leading row first)."""
    t = static.tasselli
    rows = np.unique(t.row)
    return pd.DataFrame(
        {
            "x centre (mm)": [1e3 * np.mean(t.centre_x[t.row == r]) for r in rows],
            "length (mm)": [1e3 * np.mean(t.length[t.row == r]) for r in rows],
            "H(0) of the row (N/mm)": [np.sum(static_influence[t.row == r]) / 1e3 for r in rows],
        },
        index=pd.Index(rows + 1, name="row"),
    )


def edge_share(rows: pd.DataFrame, per_end: int = 2) -> float:
    """The share of the footprint's static stiffness in its ``per_end`` outer rows at each end (the
    rows of :func:`row_influence`): where a cleat entering or leaving the footprint pushes."""
    h = rows["H(0) of the row (N/mm)"].to_numpy()
    if not 1 <= per_end <= h.size // 2:
        raise ValueError(f"per_end = {per_end}: valid range is 1 to {h.size // 2} (half of the {h.size} rows)")
    return float((h[:per_end].sum() + h[-per_end:].sum()) / h.sum())


def quasi_static_peak(
    tire: Tire, height: float, base: float, shape: str = "triangle", drum_radius: float = 1.25
) -> float:
    """Peak of :func:`quasi_static_force` for a cleat (N) on a drum of ``drum_radius`` (m), from the
    tire's static influences :math:`H_i(0)` (any model; its cached footprint and FRFs)."""
    model = tire_model(tire)
    case = model.case("drum", None, drum_radius)
    static = model.load(case)
    h0 = model.fixed_hub_frfs(case, np.array([0.0])).H[:, 0].real
    road = cleat_input(static, 0.1, height, base, shape, distance=(-0.08, 0.1))
    return float(quasi_static_force(h0, road).max())


def peak_sensitivity(
    tire: Tire,
    variants: dict[str, dict[str, float]],
    height: float,
    base: float,
    shape: str = "triangle",
    drum_radius: float = 1.25,
) -> pd.Series:
    """The quasi-static cleat peak (N, :func:`quasi_static_peak`) of a tire with each variant's overrides.

    ``variants``: name -> overrides of the tire file (dotted names -> values in SI units, as
    :meth:`TireModel.replace` takes them; ``{}`` the tire as it is). Which of a model's parameters
    could move the peak to a target, one change at a time, all else as calibrated.
    """
    model = tire_model(tire)
    peaks = {
        name: quasi_static_peak(model.replace(**change) if change else model, height, base, shape, drum_radius)
        for name, change in variants.items()
    }
    return pd.Series(peaks, name="quasi-static peak (N)")
