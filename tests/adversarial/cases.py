"""The adversarial cases: one bad argument, file or setting each, and what its message must name.

Each :class:`Case` spoils one parameter of a valid, fast call (:mod:`.inputs`): a wrong type, NaN or inf,
zero or a negative, empty, ragged, huge, a misspelt name, a boolean for a number or a string for a flag,
a file that is truncated, inconsistent or has a key the format does not know, a path that cannot be
written. The call must raise one of ``errors`` *before doing the work*, with a message holding every
string of ``names`` (the parameter, or the file and its key). :func:`verdict` sorts an outcome into
*clear* (that), *poor* (another exception, or a message that does not name the parameter), *silent*
(a result) and *wrong* (a result holding NaN or inf).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils import guards, parallel, settings
from roadnoise_utils.repro import paths

from .inputs import Inputs

NAN, INF = float("nan"), float("inf")


@dataclass(frozen=True)
class Case:
    """One bad input: ``call(inputs, tmp_path, monkeypatch)`` must raise one of ``errors`` naming ``names``."""

    id: str
    call: Callable[..., Any]
    names: tuple[str, ...]
    errors: tuple[type[BaseException], ...] = (ValueError, TypeError)
    needs: tuple[str, ...] = field(default=())  # "tmp" (a folder), "env" (a monkeypatch)


CASES: list[Case] = []


def case(id: str, names: str | Iterable[str], errors=(ValueError, TypeError)):
    """Register ``fn(inputs)`` (or ``fn(inputs, tmp)`` / ``fn(inputs, tmp, env)``) as a case."""

    def register(fn):
        wanted = (names,) if isinstance(names, str) else tuple(names)
        n_args = fn.__code__.co_argcount
        needs = ("tmp", "env")[: max(0, n_args - 1)]
        CASES.append(Case(id, fn, wanted, tuple(errors) if isinstance(errors, tuple) else (errors,), needs))
        return fn

    return register


def each(
    prefix: str, name: str, values: Iterable[Any], make: Callable[[Inputs, Any], Any], errors=(ValueError, TypeError)
):
    """One case per value of ``values`` for the parameter ``name`` of ``make(inputs, value)``."""
    for value in values:
        label = repr(value) if not isinstance(value, np.ndarray) else f"array{value.shape}"
        CASES.append(
            Case(
                f"{prefix}-{name}={label}",
                (lambda v: lambda i: make(i, v))(value),
                (name,),
                tuple(errors) if isinstance(errors, tuple) else (errors,),
            )
        )


#: Bad values of a positive real parameter, of a non-negative integer one, and of an on/off flag.
POSITIVE = (0.0, -1.0, NAN, INF, True, "8")
COUNT = (-1, 2.5, True, "8", NAN)
FLAG = ("yes", 1, None, "False")

# ---------------------------------------------------------------- fitting (paper Eq. 2-3)

each("vector_fit", "n_poles", (0, -2, 2.5, True, "8", 10_000), lambda i, v: ru.vector_fit(i.freqs, i.H[0], n_poles=v))
each("vector_fit", "iterations", (0, -1, 2.5, True, "8"), lambda i, v: ru.vector_fit(i.freqs, i.H[0], iterations=v))
each("vector_fit", "tolerance", POSITIVE, lambda i, v: ru.vector_fit(i.freqs, i.H[0], tolerance=v))
each("vector_fit", "enforce_dc", FLAG, lambda i, v: ru.vector_fit(i.freqs, i.H[0], enforce_dc=v))
each("vector_fit", "proportional", FLAG, lambda i, v: ru.vector_fit(i.freqs, i.H[0], proportional=v))
each(
    "vector_fit",
    "weight",
    ("heavy", np.full(251, NAN), -np.ones(251), np.zeros(251), np.ones(7), np.ones((2, 251))),
    lambda i, v: ru.vector_fit(i.freqs, i.H[0], weight=v),
)
each(
    "vector_fit",
    "freqs",
    (np.arange(5.0), np.full(251, NAN), np.arange(251.0)[::-1], np.array([]), "0-250"),
    lambda i, v: ru.vector_fit(v, i.H[0]),
)
each(
    "vector_fit",
    "frf",
    (np.full(251, NAN + 0j), np.ones(7), np.array([]), ["a"] * 251),
    lambda i, v: ru.vector_fit(i.freqs, v),
)

each("fit_tasselli", "n_poles", ("automatic", -2, 2.5, True, 0), lambda i, v: ru.fit_tasselli(i.freqs, i.H, n_poles=v))
each("fit_tasselli", "f_max", POSITIVE + (1e6,), lambda i, v: ru.fit_tasselli(i.freqs, i.H, f_max=v))
each("fit_tasselli", "iterations", (0, -1, 2.5, True), lambda i, v: ru.fit_tasselli(i.freqs, i.H, iterations=v))
each("fit_tasselli", "tolerance", (0.0, -1.0, NAN, "x"), lambda i, v: ru.fit_tasselli(i.freqs, i.H, tolerance=v))
each("fit_tasselli", "common_poles", FLAG, lambda i, v: ru.fit_tasselli(i.freqs, i.H, common_poles=v))
each("fit_tasselli", "enforce_dc", FLAG[:2], lambda i, v: ru.fit_tasselli(i.freqs, i.H, enforce_dc=v))
each("fit_tasselli", "proportional", FLAG[:2], lambda i, v: ru.fit_tasselli(i.freqs, i.H, proportional=v))
each(
    "fit_tasselli",
    "starting_poles",
    ("random", (), ("log", "log"), ("linear", 3), 42),
    lambda i, v: ru.fit_tasselli(i.freqs, i.H, starting_poles=v),
)


@case("fit_tasselli-proportional-with-common_poles", "proportional")
def _proportional_common(i):
    ru.fit_tasselli(i.freqs, i.H, common_poles=True, proportional=True)


@case("realize-proportional-fit", "proportional")
def _realize_improper(i):
    ru.realize(ru.vector_fit(i.freqs, i.H[0], proportional=True))


each(
    "fit_tasselli",
    "target_error",
    (0.0, -0.1, NAN, "1%"),
    lambda i, v: ru.fit_tasselli(i.freqs, i.H, n_poles="auto", target_error=v),
)
each(
    "fit_tasselli",
    "max_poles",
    (0, 2.5, True, -4),
    lambda i, v: ru.fit_tasselli(i.freqs, i.H, n_poles="auto", max_poles=v),
)
each(
    "fit_tasselli",
    "H",
    (np.ones((3, 7)), np.full((3, 251), NAN), np.ones((0, 251)), [[1.0] * 251, [1.0] * 250]),
    lambda i, v: ru.fit_tasselli(i.freqs, v),
)
each("fit_tasselli", "freqs", (np.zeros(251), np.arange(251.0) - 10.0), lambda i, v: ru.fit_tasselli(v, i.H))
each("fit_tasselli", "weight", ("heavy", np.zeros(251)), lambda i, v: ru.fit_tasselli(i.freqs, i.H, weight=v))

each("identify_modes", "f_max", (0.0, -1.0, NAN, "250"), lambda i, v: ru.identify_modes(i.freqs, i.H[0], f_max=v))
each("identify_modes", "min_ratio", (0.0, -1.0, NAN, "2"), lambda i, v: ru.identify_modes(i.freqs, i.H[0], min_ratio=v))
each("identify_modes", "frf", (np.ones(7), np.full(251, NAN)), lambda i, v: ru.identify_modes(i.freqs, v))

# ---------------------------------------------------------------- state space and simulation (Eq. 4-8)

each("realize", "fit", (42, None, "fit"), lambda i, v: ru.realize(v))
each("assemble_fixed_hub", "fits", ([], "fits", [42]), lambda i, v: ru.assemble_fixed_hub(v))
each("simulate", "system", ("tire", None, 3.0), lambda i, v: ru.simulate(v, i.road))
each("simulate", "road", (None, {"u": 1}, np.zeros((10, 3))), lambda i, v: ru.simulate(i.system, v))


@case("simulate-road.u=NaN", "u")
def _simulate_nan(i):
    u = i.road.u.copy()
    u[1, 5] = NAN
    return ru.simulate(i.system, ru.RoadInput(i.road.t, i.road.distance, u, i.road.speed, "nan"))


@case("simulate-road.u=too few tasselli", "u")
def _simulate_width(i):
    return ru.simulate(i.system, ru.RoadInput(i.road.t, i.road.distance, i.road.u[:2], i.road.speed, "narrow"))


@case("simulate-road.t=non-uniform", "time step")
def _simulate_steps(i):
    t = i.road.t.copy()
    t[50:] += 1e-5
    return ru.simulate(i.system, ru.RoadInput(t, i.road.distance, i.road.u, i.road.speed, "steps"))


each(
    "RoadInput", "speed", (0.0, -1.0, NAN, "10"), lambda i, v: ru.RoadInput(i.road.t, i.road.distance, i.road.u, v, "x")
)
each(
    "RoadInput",
    "u",
    (np.zeros((3, 7)), np.zeros(200), np.full((3, 200), "a"), np.zeros((3, 200)) + 1e-3j),
    lambda i, v: ru.RoadInput(i.road.t, i.road.distance, v, 10.0, "x"),
)

# ---------------------------------------------------------------- the road flowing through the footprint

each("cleat_input", "speed", POSITIVE, lambda i, v: ru.cleat_input(i.flat, v))
each("cleat_input", "height", (-0.01, NAN, INF, "0.015", True, 0.5), lambda i, v: ru.cleat_input(i.flat, 8.0, height=v))
each("cleat_input", "base", (0.0, -0.01, NAN, "0.015", 5.0), lambda i, v: ru.cleat_input(i.flat, 8.0, base=v))
each("cleat_input", "shape", ("square", 3, ""), lambda i, v: ru.cleat_input(i.flat, 8.0, shape=v))
each(
    "cleat_input",
    "distance",
    ((0.5, -0.1), (NAN, 0.5), "ab", (0.1,), (0.0, INF)),
    lambda i, v: ru.cleat_input(i.flat, 8.0, distance=v),
)
each("cleat_input", "sample_rate", (0.0, -1.0, NAN, "10k"), lambda i, v: ru.cleat_input(i.flat, 8.0, sample_rate=v))
each("cleat_profile", "height", (NAN, -1.0, "x"), lambda i, v: ru.road.cleat_profile(v, 0.015))
each("cleat_profile", "base", (0.0, NAN, "x"), lambda i, v: ru.road.cleat_profile(0.015, v))
each("cleat_profile", "shape", ("square", None), lambda i, v: ru.road.cleat_profile(0.015, 0.015, v))

each("profile_input", "speed", POSITIVE, lambda i, v: ru.road.profile_input(i.flat, i.profile.height, v, (0.5, 1.0)))
each(
    "profile_input",
    "distance",
    ((1.0, 0.5), (NAN, 1.0), (0.5,)),
    lambda i, v: ru.road.profile_input(i.flat, i.profile.height, 10.0, v),
)
each(
    "profile_input",
    "oversample",
    (0, -1, 2.5, True),
    lambda i, v: ru.road.profile_input(i.flat, i.profile.height, 10.0, (0.5, 1.0), oversample=v),
)
each(
    "profile_input",
    "sample_rate",
    (0.0, NAN, "x"),
    lambda i, v: ru.road.profile_input(i.flat, i.profile.height, 10.0, (0.5, 1.0), sample_rate=v),
)
each(
    "profile_input",
    "profile",
    (None, "rough", 3.0, np.zeros(5)),
    lambda i, v: ru.road.profile_input(i.flat, v, 10.0, (0.5, 1.0)),
)

each(
    "road_hub_force",
    "speed",
    (0.0, NAN, "10"),
    lambda i, v: ru.rm.road_hub_force(i.footprint_system, i.flat, i.profile, v, (0.5, 1.0)),
)
each(
    "road_hub_force",
    "distance",
    ((1.0, 0.5), "ab"),
    lambda i, v: ru.rm.road_hub_force(i.footprint_system, i.flat, i.profile, 10.0, v),
)
each(
    "road_hub_force",
    "oversample",
    (0, 2.5),
    lambda i, v: ru.rm.road_hub_force(i.footprint_system, i.flat, i.profile, 10.0, (0.5, 1.0), oversample=v),
)
each(
    "road_hub_force",
    "system",
    ("tire", None),
    lambda i, v: ru.rm.road_hub_force(v, i.flat, i.profile, 10.0, (0.5, 1.0)),
)

each(
    "generate_profile",
    "length",
    POSITIVE[:5],
    lambda i, v: ru.road.generate_profile(ru.road.load_texture("rough"), v, 0.005, seed=1),
)
each(
    "generate_profile",
    "step",
    (0.0, -0.01, NAN, 10.0),
    lambda i, v: ru.road.generate_profile(ru.road.load_texture("rough"), 60.0, v, seed=1),
)
each(
    "generate_profile",
    "seed",
    (-1, 2.5, "1", True, NAN),
    lambda i, v: ru.road.generate_profile(ru.road.load_texture("rough"), 60.0, 0.005, seed=v),
)
each(
    "load_texture",
    "texture",
    ("no_such_texture", 42),
    lambda i, v: ru.road.load_texture(v),
    (ValueError, TypeError, FileNotFoundError),
)

# ---------------------------------------------------------------- the FE tire

each("solve_static", "road", ("gravel", 3, None), lambda i, v: ru.solve_static(i.fet, road=v))
each("solve_static", "load", (-5.0, INF, True), lambda i, v: ru.solve_static(i.fet, load=v))
each(
    "solve_static",
    "drum_radius",
    (0.0, -1.0, NAN, "1.25"),
    lambda i, v: ru.solve_static(i.fet, road="drum", drum_radius=v),
)
each("solve_static", "fet", ("165_65R14x", 42), lambda i, v: ru.solve_static(v))
each(
    "load_deflection",
    "loads",
    (np.array([]), np.array([NAN]), np.array([-100.0]), ["1000"]),
    lambda i, v: ru.load_deflection(i.fet, v),
)
each("loaded_modes", "n_modes", (0, -1, 2.5, True), lambda i, v: ru.loaded_modes(i.fet, i.flat, n_modes=v))
each(
    "loaded_modes",
    "reference_frequency",
    (-1.0, NAN, INF, "70"),
    lambda i, v: ru.loaded_modes(i.fet, i.flat, reference_frequency=v),
)
each("ring_frequencies", "n", (-1, 2.5, "x"), lambda i, v: ru.ring_frequencies(v, ru.ring_parameters(i.spec)))
each("ring_check", "n_max", (-1, 2.5, "8", True), lambda i, v: ru.ring_check(i.spec, n_max=v))
each("ring_check", "n_elements", (3, -1, 2.5), lambda i, v: ru.ring_check(i.spec, n_elements=v))
each(
    "frf_visco",
    "freqs",
    (np.array([]), np.array([NAN, 1.0]), np.array([-5.0, 1.0]), np.array([1e5])),
    lambda i, v: ru.frf_visco(i.fet, i.flat, v, progress=False),
)
each("frf_visco", "progress", ("no", 1), lambda i, v: ru.frf_visco(i.fet, i.flat, np.array([1.0]), progress=v))
each("modal_reduction", "frozen", ("liquid", 3), lambda i, v: ru.modal_reduction(i.fet, i.flat, frozen=v))
each("modal_reduction", "damping", ("lots",), lambda i, v: ru.modal_reduction(i.fet, i.flat, damping=v))
each("modal_reduction", "f_band", (0.0, NAN, -250.0), lambda i, v: ru.modal_reduction(i.fet, i.flat, f_band=v))
each("tire spec", "n_elements", (2.5, -4, "260"), lambda i, v: i.spec.replace(**{"mesh.n_elements": v}))
each(
    "tire spec",
    "inflation_pressure",
    (NAN, -2e5, "2 bar"),
    lambda i, v: i.spec.replace(**{"operating.inflation_pressure": v}),
)
each(
    "tire spec",
    "no_such.key",
    (1.0,),
    lambda i, v: i.spec.replace(**{"no_such.key": v}),
    (ValueError, TypeError, KeyError),
)
each(
    "load_tire",
    "tire",
    ("no_such_tire", 42, None, ""),
    lambda i, v: ru.load_tire(v),
    (ValueError, TypeError, FileNotFoundError),
)
each(
    "tire_model",
    "tire",
    ("no_such_tire", 42, None),
    lambda i, v: ru.tire_model(v),
    (ValueError, TypeError, FileNotFoundError),
)

# ---------------------------------------------------------------- experiments and their conditions

for _name in ("height", "base", "dynamic_kmh", "quasi_static_kmh", "drum_radius"):
    each(
        "cleat_conditions",
        _name,
        (NAN, -1.0, "x"),
        (lambda n: lambda i, v: ru.experiments.cleat_conditions(**{n: v}))(_name),
    )
each("cleat_conditions", "shape", ("square",), lambda i, v: ru.experiments.cleat_conditions(shape=v))
each(
    "one_sided_conditions",
    "n_elements",
    (0, 2.5, "300", True),
    lambda i, v: ru.experiments.one_sided_conditions(n_elements=v),
)
each(
    "one_sided_conditions",
    "distance",
    ((0.5, -0.1), "ab"),
    lambda i, v: ru.experiments.one_sided_conditions(distance=v),
)
each(
    "one_sided_conditions",
    "sweep_kmh",
    ((), (-5.0,), "30", (NAN,)),
    lambda i, v: ru.experiments.one_sided_conditions(sweep_kmh=v),
)
each(
    "road_test_conditions",
    "speed_kmh",
    (0.0, NAN, -1.0, "120"),
    lambda i, v: ru.experiments.road_test_conditions(speed_kmh=v),
)
each(
    "road_test_conditions",
    "textures",
    ("rough", ["no_such_texture"], [], [3]),
    lambda i, v: ru.experiments.road_test_conditions(textures=v),
)
each(
    "road_test_conditions",
    "duration",
    (0.0, -1.0, NAN, "10"),
    lambda i, v: ru.experiments.road_test_conditions(duration=v),
)
each("road_test_conditions", "seed", (-1, 2.5, "1", True), lambda i, v: ru.experiments.road_test_conditions(seed=v))
each(
    "road_test_conditions",
    "sample_rate",
    (0.0, NAN, -1.0, "9.6k"),
    lambda i, v: ru.experiments.road_test_conditions(sample_rate=v),
)
for _name in ("mass", "stiffness", "damping"):
    each(
        "suspension_conditions",
        _name,
        (NAN, -1.0, "x", True),
        (lambda n: lambda i, v: ru.experiments.suspension_conditions(**{n: v}))(_name),
    )
each(
    "sample",
    "ranges",
    ({"operating.vertical_load": (5000.0, 3000.0)}, {}, {"operating.vertical_load": (NAN, 1.0)}),
    lambda i, v: ru.experiments.sample(v, 4),
)
each(
    "sample",
    "n",
    (0, -1, 2.5, "4"),
    lambda i, v: ru.experiments.sample({"operating.vertical_load": (3000.0, 5000.0)}, v),
)
each(
    "sample",
    "seed",
    (-1, 2.5, "0"),
    lambda i, v: ru.experiments.sample({"operating.vertical_load": (3000.0, 5000.0)}, 4, seed=v),
)
_GRID = {"operating.vertical_load": [3000.0, 4000.0]}
each("sweep", "outputs", ("nope", [], ["K_v", "nope"]), lambda i, v: ru.experiments.sweep(_GRID, v, progress=False))
each("sweep", "errors", ("ignore-all", 3), lambda i, v: ru.experiments.sweep(_GRID, errors=v, progress=False))
each("sweep", "n_workers", (0, -1, 2.5, "2"), lambda i, v: ru.experiments.sweep(_GRID, n_workers=v, progress=False))
each("sweep", "scheduler", ("threads-please", 3), lambda i, v: ru.experiments.sweep(_GRID, scheduler=v, progress=False))
each(
    "sweep",
    "parameters",
    ({}, {"operating.vertical_load": []}, "load"),
    lambda i, v: ru.experiments.sweep(v, progress=False),
)
each(
    "sweep",
    "operating.vertical_load",
    ([NAN], ["4000"]),
    lambda i, v: ru.experiments.sweep({"operating.vertical_load": v}, progress=False),
)
each("sweep", "no_such.key", ([1.0],), lambda i, v: ru.experiments.sweep({"no_such.key": v}, progress=False))
each("sweep", "progress", ("no",), lambda i, v: ru.experiments.sweep(_GRID, progress=v))
each("sweep", "cache", ("off",), lambda i, v: ru.experiments.sweep(_GRID, cache=v, progress=False))
each(
    "band_extension", "bands", ((), (-250.0,), (250.0, NAN), "400"), lambda i, v: ru.experiments.band_extension(bands=v)
)
each("cleat_test", "n_poles", (0, 2.5, "8", True), lambda i, v: ru.experiments.cleat_test(n_poles=v))
each(
    "cleat_test",
    "tire",
    ("no_such_tire", 42),
    lambda i, v: ru.experiments.cleat_test(v),
    (ValueError, TypeError, FileNotFoundError),
)
each("frozen_check", "duration", (0.0, -1.0, NAN, "1"), lambda i, v: ru.experiments.frozen_check(duration=v))
each(
    "moving_hub_check",
    "freqs",
    (np.array([]), np.array([NAN, 5.0]), np.array([-1.0, 5.0])),
    lambda i, v: ru.experiments.moving_hub_check(freqs=v),
)
each(
    "corner_setup",
    "vehicle",
    ("no_such_car", 42),
    lambda i, v: ru.experiments.corner_setup(v),
    (ValueError, TypeError, FileNotFoundError),
)
each("applicable", "capability", ("flying",), lambda i, v: ru.experiments.applicable("165_65R14", v))
each("tire_as_files", "roads", ((), ("gravel",), "flat"), lambda i, v: ru.experiments.tire_as_files("165_65R14", v))

# ---------------------------------------------------------------- settings


def _setting(variable: str, value: str, read: Callable[[], Any]):
    def call(i, tmp, env):
        env.setenv(variable, value)
        return read()

    return call


for _value in ("two", "0", "-1", "1.5"):
    CASES.append(
        Case(
            f"setting-ROADNOISE_THREADS={_value!r}",
            _setting("ROADNOISE_THREADS", _value, parallel.threads),
            ("ROADNOISE_THREADS",),
            (ValueError,),
            ("tmp", "env"),
        )
    )
for _value in ("lots", "-1", "0", "nan"):
    CASES.append(
        Case(
            f"setting-ROADNOISE_MAX_BYTES={_value!r}",
            _setting("ROADNOISE_MAX_BYTES", _value, guards.memory_limit),
            ("ROADNOISE_MAX_BYTES",),
            (ValueError,),
            ("tmp", "env"),
        )
    )
for _value in ("maybe", "of", ""):
    CASES.append(
        Case(
            f"setting-ROADNOISE_CACHE={_value!r}",
            _setting("ROADNOISE_CACHE", _value, lambda: settings.flag("ROADNOISE_CACHE", True)),
            ("ROADNOISE_CACHE",),
            (ValueError,),
            ("tmp", "env"),
        )
    )
for _variable, _read in (("ROADNOISE_CACHE_DIR", paths.cache_dir), ("ROADNOISE_DATA_DIR", paths.data_dir)):
    CASES.append(
        Case(f"setting-{_variable}=''", _setting(_variable, " ", _read), (_variable,), (ValueError,), ("tmp", "env"))
    )
CASES.append(
    Case(
        "setting-ROADNOISE_DATA_DIR=no tires",
        _setting("ROADNOISE_DATA_DIR", "/", paths.data_dir),
        ("ROADNOISE_DATA_DIR",),
        (ValueError, FileNotFoundError),
        ("tmp", "env"),
    )
)

# ---------------------------------------------------------------- files: read and written

FILE_ERRORS = (ValueError, TypeError, FileNotFoundError, OSError)


def _data_text(*parts: str) -> str:
    return (paths.data_dir().joinpath(*parts)).read_text()


def _file_case(id: str, names: Iterable[str], write: Callable[[Path], Path], read: Callable[[Path], Any]):
    def call(i, tmp):
        return read(write(tmp))

    CASES.append(Case(id, call, tuple(names), FILE_ERRORS, ("tmp",)))


def _edited(folder: str, name: str, edit: Callable[[str], str]) -> Callable[[Path], Path]:
    def write(tmp: Path) -> Path:
        path = tmp / name
        path.write_text(edit(_data_text(folder, name)))
        return path

    return write


def _sub(pattern: str, replacement: str) -> Callable[[str], str]:
    def edit(text: str) -> str:
        new, count = re.subn(pattern, replacement, text, count=1, flags=re.M)
        assert count == 1, f"the data file no longer holds {pattern!r}"
        return new

    return edit


_TIRE = "165_65R14.toml"
_file_case(
    "tire file-unknown key",
    ("tirex.toml", "unknown_key"),
    lambda t: _rename(
        _edited("tires", _TIRE, _sub(r"^\[operating\]$", "[operating]\nunknown_key = 1"))(t), "tirex.toml"
    ),
    ru.load_tire,
)
_file_case(
    "tire file-string for a number",
    ("tirey.toml", "inflation_pressure"),
    lambda t: _rename(
        _edited("tires", _TIRE, _sub(r"^inflation_pressure\s*=.*$", 'inflation_pressure = "2.2 bar"'))(t), "tirey.toml"
    ),
    ru.load_tire,
)
_file_case(
    "tire file-negative modulus",
    ("tirez.toml", "inflation_pressure"),
    lambda t: _rename(
        _edited("tires", _TIRE, _sub(r"^inflation_pressure\s*=.*$", "inflation_pressure = -2.2e5"))(t), "tirez.toml"
    ),
    ru.load_tire,
)
_file_case(
    "tire file-truncated",
    ("tiret.toml",),
    lambda t: _rename(_edited("tires", _TIRE, lambda s: s[: len(s) // 2] + '\nx = "')(t), "tiret.toml"),
    ru.load_tire,
)
_file_case(
    "texture file-unknown key",
    ("roughx.toml", "colour"),
    lambda t: _rename(_edited("roads", "rough.toml", lambda s: 'colour = "grey"\n' + s)(t), "roughx.toml"),
    ru.road.load_texture,
)
_file_case(
    "texture file-bad class",
    ("roughy.toml",),
    lambda t: _rename(
        _edited("roads", "rough.toml", lambda s: re.sub(r'(?m)^(iso_class\s*=\s*)".*"', r'\1"Z"', s))(t), "roughy.toml"
    ),
    ru.road.load_texture,
)
_file_case(
    "vehicle file-unknown key",
    ("carx.toml", "turbo"),
    lambda t: _rename(_edited("vehicles", "midsize_195_65R15.toml", lambda s: "turbo = true\n" + s)(t), "carx.toml"),
    ru.vehicle.load_vehicle,
)
_file_case(
    "vehicle file-negative mass",
    ("cary.toml",),
    lambda t: _rename(
        _edited("vehicles", "midsize_195_65R15.toml", _sub(r"^(unsprung\s*=\s*)([0-9.eE+]+)", r"\1-\2"))(t), "cary.toml"
    ),
    ru.vehicle.load_vehicle,
)


def _rename(path: Path, name: str) -> Path:
    return path.rename(path.with_name(name))


def _csv(text: str) -> Callable[[Path], Path]:
    def write(tmp: Path) -> Path:
        path = tmp / "road.csv"
        path.write_text(text)
        return path

    return write


_ROWS = "".join(f"{0.01 * k:.2f},{0.001 * math.sin(k):.6f}\n" for k in range(200))
_file_case(
    "road csv-NaN height",
    ("road.csv",),
    _csv("distance_m,height_m\n" + _ROWS.replace("0.000841", "nan", 1)),
    ru.road.load_road_file,
)
_file_case(
    "road csv-one column",
    ("road.csv",),
    _csv("distance_m\n" + "".join(f"{0.01 * k}\n" for k in range(50))),
    ru.road.load_road_file,
)
_file_case(
    "road csv-decreasing distance",
    ("road.csv",),
    _csv("distance_m,height_m\n" + "".join(reversed(_ROWS.splitlines(True)))),
    ru.road.load_road_file,
)
_file_case("road csv-empty", ("road.csv",), _csv(""), ru.road.load_road_file)
_file_case(
    "road csv-text in the data",
    ("road.csv",),
    _csv("distance_m,height_m\n" + _ROWS + "3.0,abc\n"),
    ru.road.load_road_file,
)
_file_case(
    "road csv-huge heights",
    ("road.csv",),
    _csv("distance_m,height_m\n" + "".join(f"{0.01 * k:.2f},{5.0 * k}\n" for k in range(200))),
    ru.road.load_road_file,
)
_file_case("uff-missing file", ("nowhere.uff",), lambda t: t / "nowhere.uff", ru.read_uff58)
_file_case("uff-a folder", ("folder.uff",), lambda t: (t / "folder.uff").mkdir() or t / "folder.uff", ru.read_uff58)
_file_case(
    "uff-empty file",
    ("empty.uff",),
    lambda t: (t / "empty.uff").write_text("") and t / "empty.uff" or t / "empty.uff",
    ru.read_uff58,
)
_file_case(
    "uff-garbage",
    ("junk.uff",),
    lambda t: (t / "junk.uff").write_text("    -1\n    58\nnot a dataset\n    -1\n") and t / "junk.uff",
    ru.read_uff58,
)
_file_case("crg-missing file", ("nowhere.crg",), lambda t: t / "nowhere.crg", ru.road.load_crg)
_file_case(
    "crg-garbage",
    ("junk.crg",),
    lambda t: (t / "junk.crg").write_text("$CT\nnot a road\n$\n") and t / "junk.crg",
    ru.road.load_crg,
)


@case("write_uff58-path=unwritable", ("uff",), FILE_ERRORS)
def _uff_unwritable(i, tmp):
    blocker = tmp / "file"
    blocker.write_text("x")
    return ru.write_uff58(blocker / "out.uff", i.frf)


for _name, _values in (
    ("frfs", (None, "frf", 42)),
    ("overwrite", ("yes", 1)),
    ("binary", ("no",)),
    ("points", ("all",)),
):
    for _value in _values:
        CASES.append(
            Case(
                f"write_uff58-{_name}={_value!r}",
                (
                    lambda n, v: (
                        lambda i, tmp: ru.write_uff58(
                            tmp / "out.uff", v if n == "frfs" else i.frf, **({} if n == "frfs" else {n: v})
                        )
                    )
                )(_name, _value),
                (_name,),
                FILE_ERRORS,
                ("tmp",),
            )
        )


def verdict(case: Case, outcome: BaseException | Any) -> str:
    """``clear``, ``poor``, ``silent`` or ``wrong`` (see the module's docstring) for what ``case.call`` gave."""
    if isinstance(outcome, BaseException):
        text = str(outcome)
        named = all(name.lower() in text.lower() for name in case.names)
        return "clear" if isinstance(outcome, case.errors) and named else "poor"
    warned = getattr(outcome, "messages", None)  # doubtful but valid: a RoadnoiseWarning naming the parameter
    if warned and any(all(name.lower() in m.lower() for name in case.names) for m in warned):
        return "clear"
    outcome = getattr(outcome, "result", outcome)
    values = _floats(outcome)
    return "wrong" if values.size and not np.all(np.isfinite(values)) else "silent"


def _floats(outcome: Any) -> np.ndarray:
    """The floating-point numbers a result holds (its arrays and float fields), for :func:`verdict`."""
    found: list[np.ndarray] = []
    items = [outcome]
    if hasattr(outcome, "__dict__"):
        items += list(vars(outcome).values())
    for item in items:
        if isinstance(item, float):
            found.append(np.array([item]))
        elif isinstance(item, np.ndarray) and item.dtype.kind in "fc":
            found.append(np.abs(item).ravel())
    return np.concatenate(found) if found else np.array([])
