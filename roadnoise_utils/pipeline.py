"""Stage functions with the on-disk cache: what a notebook calls to get an earlier stage.

Each function takes the tire (a name in ``data/tires`` or a :class:`TireSpec`) and the
stage's own options, and returns the stage result, computed or loaded from the cache
(:mod:`.cache`), so every notebook runs alone, in any order, on a fresh checkout.
"""

from __future__ import annotations

import numpy as np

from .cache import cached
from .fet import FETModel, build_fet
from .fitting import FitSet, fit_tasselli, lowest_order
from .frf import FRFResult, frf_visco
from .modal import ModalReduction, modal_reduction
from .modes import LoadedModes, loaded_modes
from .static import StaticState, make_road, solve_static
from .tire_spec import TireSpec, load_tire

#: Default frequency grid of the direct sweeps: 0-400 Hz every 1 Hz (paper: up to 250 Hz,
#: "easily improved to 400 Hz").
DEFAULT_FREQS = np.arange(0.0, 400.0 + 0.5, 1.0)


def tire_spec(tire: str | TireSpec) -> TireSpec:
    """A :class:`TireSpec` from a name/path or the spec itself."""
    return tire if isinstance(tire, TireSpec) else load_tire(tire)


def fet_model(tire: str | TireSpec) -> FETModel:
    """The assembled FET (fast; not cached)."""
    return build_fet(tire_spec(tire))


def _road_inputs(spec: TireSpec, road: str, load: float | None, drum_radius: float | None) -> dict:
    surface = make_road(road, drum_radius)
    return {
        "tire": spec,
        "road": surface.kind,
        "drum_radius": surface.drum_radius,
        "load": spec.operating.vertical_load if load is None else float(load),
    }


def static_state(
    tire: str | TireSpec, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> StaticState:
    """Cached :func:`.static.solve_static`."""
    spec = tire_spec(tire)
    inputs = _road_inputs(spec, road, load, drum_radius)
    return cached(
        "static",
        inputs,
        lambda: solve_static(build_fet(spec), road=road, load=inputs["load"], drum_radius=inputs["drum_radius"]),
    )


def visco_frf(
    tire: str | TireSpec,
    road: str = "flat",
    freqs: np.ndarray | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
    progress: bool = True,
) -> FRFResult:
    """Cached :func:`.frf.frf_visco` (default 0-400 Hz every 1 Hz)."""
    spec = tire_spec(tire)
    freqs = DEFAULT_FREQS if freqs is None else np.asarray(freqs, dtype=float)
    inputs = {**_road_inputs(spec, road, load, drum_radius), "freqs": freqs}
    static = static_state(spec, road, load, drum_radius)
    return cached("frf_visco", inputs, lambda: frf_visco(build_fet(spec), static, freqs, progress=progress))


def modes(
    tire: str | TireSpec,
    road: str = "flat",
    n_modes: int = 60,
    reference_frequency: float = 70.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> LoadedModes:
    """Cached :func:`.modes.loaded_modes`."""
    spec = tire_spec(tire)
    inputs = {
        **_road_inputs(spec, road, load, drum_radius),
        "n_modes": int(n_modes),
        "reference_frequency": float(reference_frequency),
    }
    static = static_state(spec, road, load, drum_radius)
    return cached(
        "modes", inputs, lambda: loaded_modes(build_fet(spec), static, int(n_modes), float(reference_frequency))
    )


def modal(
    tire: str | TireSpec,
    road: str = "flat",
    frozen: str = "complex",
    damping: str = "identified",
    reference_frequency: float | None = None,
    load: float | None = None,
    drum_radius: float | None = None,
) -> ModalReduction:
    """Cached :func:`.modal.modal_reduction` on the default direct sweep (0-400 Hz)."""
    spec = tire_spec(tire)
    inputs = {
        **_road_inputs(spec, road, load, drum_radius),
        "frozen": frozen,
        "damping": damping,
        "reference_frequency": reference_frequency,
    }
    static = static_state(spec, road, load, drum_radius)
    visco = visco_frf(spec, road, load=load, drum_radius=drum_radius, progress=False)
    return cached(
        "modal",
        inputs,
        lambda: modal_reduction(
            build_fet(spec),
            static,
            visco=visco,
            reference_frequency=reference_frequency,
            frozen=frozen,
            damping=damping,
        ),
    )


#: Relative RMS error every tassello's fit must meet when the order is chosen automatically.
FIT_TOLERANCE = 0.01


def _cached_fit(
    stage: str,
    frf_name: str,
    tire: str | TireSpec,
    road: str,
    n_poles: int | None,
    f_max: float,
    load: float | None,
    drum_radius: float | None,
) -> FitSet:
    """Cached rational fit of one direct FRF (``"H"`` or ``"G_H"``) of :func:`visco_frf`.

    ``n_poles=None`` takes the lowest order at which every fitted FRF is within
    :data:`FIT_TOLERANCE`.
    """
    spec = tire_spec(tire)
    inputs = {
        **_road_inputs(spec, road, load, drum_radius),
        "n_poles": n_poles,
        "f_max": float(f_max),
        "tolerance": FIT_TOLERANCE,
    }
    visco = visco_frf(spec, road, load=load, drum_radius=drum_radius, progress=False)

    def compute() -> FitSet:
        frf = getattr(visco, frf_name)
        if n_poles is None:
            return lowest_order(visco.freqs, frf, tolerance=FIT_TOLERANCE, f_max=f_max)
        return fit_tasselli(visco.freqs, frf, n_poles=n_poles, f_max=f_max)

    return cached(stage, inputs, compute)


def tassello_fits(
    tire: str | TireSpec,
    road: str = "flat",
    n_poles: int | None = None,
    f_max: float = 250.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> FitSet:
    """Cached rational fits of the direct local FRFs :math:`H_i` over 0-``f_max`` Hz.

    ``n_poles=None`` takes the lowest order at which every tassello is fitted within
    :data:`FIT_TOLERANCE` (see notebook 03 for why the direct FRFs and this order).
    """
    return _cached_fit("tassello_fits", "H", tire, road, n_poles, f_max, load, drum_radius)


def hub_fit(
    tire: str | TireSpec,
    road: str = "flat",
    n_poles: int | None = None,
    f_max: float = 250.0,
    load: float | None = None,
    drum_radius: float | None = None,
) -> FitSet:
    """Cached rational fit of the hub FRF :math:`G_H` (same order rule as :func:`tassello_fits`)."""
    return _cached_fit("hub_fit", "G_H", tire, road, n_poles, f_max, load, drum_radius)


def fixed_hub_tire(tire: str | TireSpec, road: str = "flat", n_poles: int | None = None):
    """The assembled fixed-hub state-space tire (Eq. 3-4) from the cached fits."""
    from .statespace import assemble_fixed_hub

    return assemble_fixed_hub(tassello_fits(tire, road, n_poles))


def cleat_fe(
    tire: str | TireSpec,
    speed: float,
    height: float | None = None,
    base: float | None = None,
    duration: float = 1.0,
) -> tuple:
    """Cached FE frequency-domain cleat response on the drum: ``(road, force)``, force band-limited to 250 Hz.

    The cleat defaults to the paper's (``data/conditions/cleat_test.toml``).
    """
    from .cleat import fe_cleat_response
    from .road import cleat_input

    spec = tire_spec(tire)
    inputs = {
        **_road_inputs(spec, "drum", None, None),
        "speed": float(speed),
        "height": height,
        "base": base,
        "duration": float(duration),
    }
    static = static_state(spec, "drum")

    def compute():
        road = cleat_input(static, speed, height=height, base=base)
        return road, fe_cleat_response(build_fet(spec), static, road, duration=duration)

    return cached("cleat_fe", inputs, compute)
