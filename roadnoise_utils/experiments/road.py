"""The paper's outdoor road test: textures at 120 km/h flowing through the footprint (paper Fig. 11-14).

Paper, *Simulations with the Moving Hub System*: the 195/65 R15 car at 120 km/h on a rough and a
smooth texture (whose spectra the paper does not give: ours are ISO 8608 classes extended into
the megatexture band, ``data/roads``). :func:`road_test_conditions` reads
``data/conditions/road_test.toml`` once and resolves every default; :func:`road_test` builds
the tassello inputs of each texture for a tire (notebook 06), which the quarter car
(:mod:`~roadnoise_utils.experiments.corner`, notebook 07) is driven by.
"""

from __future__ import annotations

from dataclasses import dataclass

from .. import guards
from ..repro import stages
from ..road.input import RoadInput, contact_tracks, texture_input, texture_length
from ..road.textures import RoadSpectrum, load_texture
from ..tire.model import Footprint, ModelSpec
from .conditions import load_conditions, resolve


@dataclass(frozen=True)
class RoadTestConditions:
    """The road test, every default resolved.

    Attributes
    ----------
    speed_kmh : float
        Driving speed (km/h, as the paper gives it).
    textures : tuple of str
        Road texture files (``data/roads``).
    duration : float
        Simulated time per run (s).
    seed : int
        Seed of the random road phases.
    sample_rate : float
        Samples per second (Hz).
    """

    speed_kmh: float
    textures: tuple[str, ...]
    duration: float
    seed: int
    sample_rate: float

    @property
    def speed(self) -> float:
        """Driving speed (m/s)."""
        return self.speed_kmh / 3.6

    def spectra(self) -> dict[str, RoadSpectrum]:
        """The spectrum of each texture (``data/roads/<texture>.toml``)."""
        return {name: load_texture(name) for name in self.textures}


def road_test_conditions(
    speed_kmh: float | None = None,
    textures: list[str] | tuple[str, ...] | None = None,
    duration: float | None = None,
    seed: int | None = None,
    sample_rate: float | None = None,
) -> RoadTestConditions:
    """The paper's road test (``data/conditions/road_test.toml``, read once), any value given here overriding it."""
    values = resolve(
        load_conditions("road_test"),
        speed_kmh=speed_kmh,
        textures=textures,
        duration=duration,
        seed=seed,
        sample_rate=sample_rate,
    )
    names = values["textures"]
    if isinstance(names, str) or not isinstance(names, (list, tuple)) or not names:
        raise ValueError(f"textures = {names!r}: give a non-empty list of texture names, e.g. ['rough']")
    if not all(isinstance(n, str) for n in names):
        raise ValueError(f"textures = {names!r}: every texture is a name in data/roads or a path")
    for name in names:  # a misspelt texture is named here, not when the road is generated
        try:
            load_texture(name)
        except (ValueError, FileNotFoundError) as error:
            raise ValueError(f"textures = {names!r}: {error}") from None
    return RoadTestConditions(
        speed_kmh=guards.real("speed_kmh", values["speed_kmh"], 0.0, 360.0, lo_open=True, unit="km/h"),
        textures=tuple(names),
        duration=guards.real("duration", values["duration"], 0.0, lo_open=True, unit="s"),
        seed=guards.seed(values["seed"]),
        sample_rate=guards.real("sample_rate", values["sample_rate"], 0.0, lo_open=True, unit="Hz"),
    )


@dataclass(frozen=True, eq=False)
class RoadTest:
    """Tassello inputs of each texture of the road test for one tire.

    Attributes
    ----------
    tire : ModelSpec
        The tire.
    conditions : RoadTestConditions
        The resolved test.
    static : Footprint
        The tire loaded on the flat road.
    spectra : dict of str to RoadSpectrum
        Each texture's spectrum.
    inputs : dict of str to RoadInput
        Each texture's tassello displacements.
    lateral : bool
        Whether the roads are 3D (one coherent track per belt strip) or uniform across the width.
    """

    tire: ModelSpec
    conditions: RoadTestConditions
    static: Footprint
    spectra: dict[str, RoadSpectrum]
    inputs: dict[str, RoadInput]
    lateral: bool


def texture_run(static: Footprint, spectrum: RoadSpectrum, conditions: RoadTestConditions, lateral: bool) -> RoadInput:
    """The tassello inputs of one texture under the test's speed, duration, seed and sample rate.

    The generated road comes from the stage cache (:func:`roadnoise_utils.repro.stages.texture_road`):
    every chapter and the claims drive over the same roads, generated once.
    """
    travel = conditions.duration * conditions.speed
    tracks = contact_tracks(static) if lateral else None
    road = stages.texture_road(spectrum, texture_length(spectrum, travel), conditions.seed, tracks)
    return texture_input(
        static,
        spectrum,
        conditions.speed,
        conditions.duration,
        conditions.seed,
        lateral=lateral,
        sample_rate=conditions.sample_rate,
        road=road,
    )


def road_test(
    tire: str | ModelSpec = "195_65R15", conditions: RoadTestConditions | None = None, lateral: bool = True
) -> RoadTest:
    """The road test's inputs on a tire: each texture flowing through its flat-road footprint."""
    spec = stages.load_tire(tire)
    test = road_test_conditions() if conditions is None else conditions
    static = stages.solve_static(spec)
    spectra = test.spectra()
    inputs = {name: texture_run(static, spectrum, test, lateral) for name, spectrum in spectra.items()}
    return RoadTest(spec, test, static, spectra, inputs, lateral)
