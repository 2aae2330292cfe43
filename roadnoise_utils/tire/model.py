"""The tire-model interface: what the RM pipeline needs from any finite-element tire.

The RM method (paper Fig. 1, 4) is a pipeline from a loaded FE tire's footprint FRFs to a
time-domain tire: the tire is loaded on the road (its footprint divided into tasselli, each
with its FE weights), its fixed-hub FRFs ``H_i``, ``H_tot`` and ``G_H`` are computed, fitted
(Eq. 1) and assembled into a state space (Eq. 2-7). Everything after the FRFs is the same
for every tire, so the pipeline asks a :class:`TireModel` only for what this module lists:

================================  ============================================================
:meth:`TireModel.load`            the loaded tire on a :class:`LoadCase`: a :class:`Footprint`
:meth:`TireModel.fixed_hub_frfs`  :class:`FRFResult`: ``H_i``, ``H_tot``, ``G_H`` (fixed hub)
:meth:`TireModel.rim_side_mass`   the mass the hub carries besides ``G_H`` (kg)
:meth:`TireModel.fingerprint`     what the stage cache keys on (the validated tire file)
:meth:`TireModel.replace`         a variant for a design sweep
================================  ============================================================

and for the optional capabilities of :data:`CAPABILITIES` (the paper's modal reduction, an FE
reference of a road input, contact loss, the air cavity, ``G_H``), each of which a model may
lack: :meth:`TireModel.require` then raises :class:`NotApplicable`, naming the capability, and
the claims that need it are reported "not applicable". Measured data and a model answer the
same calls, as python-control's ``FrequencyResponseData`` stands beside ``StateSpace``.

The registry (:func:`register`, :func:`tire_model`) maps a tire file's ``[tire] model`` to its
class; nothing else needs to know which model it holds.
"""

from __future__ import annotations

import dataclasses
import sys
from abc import ABC, abstractmethod
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
import pandas as pd

from .. import guards
from ..repro.paths import data_file, read_toml
from .surface import RoadSurface, make_road
from .tasselli import FootprintMeasures, Tasselli

if TYPE_CHECKING:
    from .cavity import Cavity

#: Default frequency grid of the direct sweeps: 0-400 Hz every 1 Hz (paper: up to 250 Hz,
#: "easily improved to 400 Hz").
#: A tire model's validated tire file (each model's own frozen dataclass, :attr:`TireModel.spec`):
#: what a stage's cache key and a result's ``tire`` field hold, whatever the model.
ModelSpec = Any
DEFAULT_FREQS = np.arange(0.0, 400.0 + 0.5, 1.0)

#: Optional capabilities a tire model may have, with what each gives.
CAPABILITIES = {
    "fe_mesh": "an FE mesh of its own (its size, the paper's 'about 8000 DOF'; FRFs read from files have none)",
    "hub_transfer": "hub transfer function G_H (the moving hub, the quarter car and the whole car need it)",
    "modal_reduction": "modal reduction of the paper's Fig. 4 (identified damping, frozen moduli, modal H_i)",
    "loaded_modes": "eigenmodes of the loaded FE tire",
    "released_hub": "FE solve of the tire with its hub released on a suspension (the moving hub's reference)",
    "direct_response": "FE reference of a road input (the hub force straight from the FE model, no fit)",
    "one_sided_cleat": "cleat test with one-sided contact (the tread lifting off the drum)",
    "cavity": "air cavity coupled to the tire (its FRFs with the cavity)",
    "cavity_shape": "air cavity's section round the loaded wheel (its first doublet's split against the load)",
    "rolling_cavity": "fixed-hub FRFs with the cavity's air streaming round the rolling wheel",
}


class NotApplicable(NotImplementedError):
    """A tire model lacks a capability of :data:`CAPABILITIES`; the message names it."""

    def __init__(self, model: str, capability: str):
        self.model, self.capability = model, capability
        super().__init__(f"not applicable: {capability} ({CAPABILITIES[capability]}) is not part of the {model} model")


def check_load(load: float) -> float:
    """A vertical load (N) within the range a tire file accepts (``[operating] vertical_load``)."""
    return guards.real("load", load, *guards.LOAD_RANGE, unit="N")


@dataclass(frozen=True)
class LoadCase:
    """How a tire is loaded: the road it stands on and the vertical load (N).

    Build it with :meth:`TireModel.case`, which fills the tire file's own load.
    """

    road: RoadSurface
    load: float

    def __post_init__(self) -> None:
        if not isinstance(self.road, RoadSurface):
            raise TypeError(f"road: a RoadSurface, got {type(self.road).__name__}")
        object.__setattr__(self, "load", check_load(self.load))

    @classmethod
    def of(cls, road: str = "flat", load: float = 0.0, drum_radius: float | None = None) -> LoadCase:
        """A load case from the road's name (``"flat"`` or ``"drum"``), the load (N) and the drum radius (m)."""
        return cls(make_road(road, drum_radius), load)

    @property
    def drum_radius(self) -> float | None:
        """The drum radius (m), ``None`` on the flat road."""
        return self.road.drum_radius if self.road.kind == "drum" else None

    def key(self) -> dict[str, Any]:
        """The case as the stage cache keys it: road, drum radius (``inf`` when flat) and load."""
        return {"road": self.road.kind, "drum_radius": self.road.drum_radius, "load": self.load}

    def describe(self) -> str:
        where = "the flat road" if self.road.kind == "flat" else f"a drum of R = {self.road.drum_radius:.2f} m"
        return f"{self.load:.0f} N on {where}"


@dataclass(frozen=True, eq=False)
class Footprint(FootprintMeasures):
    """A tire loaded on a road: what the RM chain needs of its static state, for every model.

    Attributes
    ----------
    road : RoadSurface
        The surface it stands on.
    load : float
        Vertical load (N).
    deflection : float
        Rise of the road from first touch to equilibrium (m); NaN where a model's data lack it.
    hub_force : float
        Vertical force the tire exerts on the fixed hub (N), positive upward: the load.
    vertical_stiffness : float
        Tangent vertical stiffness at the load, dF/d(delta), the contact set frozen (N/m).
    tasselli : Tasselli
        The footprint divided into blocks, with the FE weights of their contact nodes.
    node_pressure : ndarray (n_nodes,)
        Contact pressure at each contact node, in the order of the tasselli's nodes (Pa).
    """

    road: RoadSurface
    load: float
    deflection: float
    hub_force: float
    vertical_stiffness: float
    tasselli: Tasselli
    node_pressure: np.ndarray

    @property
    def contact_points(self) -> int:
        """How many tread points (FE nodes) the road pushes."""
        return int(self.node_pressure.size)

    def force_balance(self) -> float:
        """Largest relative imbalance of the load against what carries it (-): the hub force here; a
        model with contact forces checks them too. Zero up to round-off on an FE model's solve."""
        return abs(self.hub_force / self.load - 1.0)

    def summary(self) -> pd.Series:
        """Key numbers in the paper's units, the same rows for every model (a model may add rows)."""
        t = self.tasselli
        return pd.Series(
            {
                "load (N)": self.load,
                "deflection (mm)": self.deflection * 1e3,
                "vertical stiffness, tangent (N/mm)": self.vertical_stiffness / 1e3,
                "vertical stiffness, secant (N/mm)": self.load / self.deflection / 1e3,
                "footprint length (mm)": self.footprint_length * 1e3,
                "footprint width (mm)": self.footprint_width * 1e3,
                "contact area (cm^2)": self.contact_area * 1e4,
                "mean contact pressure (MPa)": self.mean_pressure / 1e6,
                "peak contact pressure (MPa)": self.node_pressure.max() / 1e6,
                "contact points": int(t.node_x.size),
                "tasselli": t.n,
                "force balance (contact and hub = load to 1e-9)": bool(self.force_balance() < 1e-9),
            }
        )


@dataclass(frozen=True, eq=False)
class FRFResult:
    """Fixed-hub frequency responses of the loaded tire, the same for every tire model.

    Attributes
    ----------
    freqs : ndarray (n_freq,)
        Frequencies (Hz).
    H : ndarray (n_tasselli, n_freq), complex
        Hub vertical force per unit vertical displacement of each tassello (N/m).
    H_tot : ndarray (n_freq,), complex
        Hub vertical force per unit vertical displacement of the whole footprint (N/m).
    G_H : ndarray (n_freq,), complex, or None
        Hub vertical force per unit vertical hub displacement, footprint held (N/m), ``-K_v`` at
        rest; the rim's own inertia is not included (it belongs to the vehicle's unsprung mass).
        ``None`` where the data have no hub transfer.
    H_points : ndarray (n_contact, n_freq), complex, or None
        Hub force per unit displacement of each contact point (N/m); ``None`` where the data
        give the tasselli only.
    method : str
        How it was computed.
    """

    freqs: np.ndarray
    H: np.ndarray
    H_tot: np.ndarray
    G_H: np.ndarray | None
    H_points: np.ndarray | None
    method: str

    def take(self, index: np.ndarray) -> FRFResult:
        """The responses at the frequencies ``freqs[index]`` (an index array into :attr:`freqs`)."""
        return dataclasses.replace(
            self,
            freqs=self.freqs[index],
            H=self.H[:, index],
            H_tot=self.H_tot[index],
            G_H=None if self.G_H is None else self.G_H[index],
            H_points=None if self.H_points is None else self.H_points[:, index],
        )

    @property
    def H_sum(self) -> np.ndarray:
        """:math:`\\sum_i H_i` (N/m), the left side of the paper's Eq. (i)."""
        return self.H.sum(axis=0)

    @property
    def H_rms(self) -> np.ndarray:
        """RMS of :math:`|H_i|` over the tasselli (N/m): the resonances the tasselli see, those that
        cancel in :math:`H_{tot}` included."""
        return np.sqrt(np.mean(np.abs(self.H) ** 2, axis=0))


@dataclass(frozen=True)
class ContactSetup:
    """How a model runs the cleat test with one-sided contact (capability ``one_sided_cleat``).

    Attributes
    ----------
    model : TireModel
        The model the runs use (the ring refined along its circumference).
    quasi_static_distance : (float, float)
        Travel of the quasi-static passage (m).
    quasi_static_step : float
        Travel between its contact solves (m).
    dt : float or None
        Time step of the dynamic runs (s); None: the model's own choice.
    band : float or None
        The dynamic hub force is compared low-passed to this band (Hz; the paper's 250 Hz), None:
        as stepped.
    """

    model: TireModel
    quasi_static_distance: tuple[float, float]
    quasi_static_step: float
    dt: float | None
    band: float | None


class TireModel(ABC):
    """One implementation of the tire for the RM pipeline (a tire file's ``[tire] model``).

    A model is an immutable wrapper of its validated tire file (:attr:`roadnoise_utils.tire.ring.spec`); its methods
    compute (and cache, where costly) what the pipeline asks for. Subclasses set :attr:`kind`
    and :attr:`capabilities`, implement :meth:`parse`, :meth:`load`, :meth:`fixed_hub_frfs`
    and :meth:`rim_side_mass`, and override the optional methods of the capabilities they have.
    """

    #: The ``[tire] model`` of the files this class builds.
    kind: ClassVar[str] = ""
    #: The optional capabilities (keys of :data:`CAPABILITIES`) the model has.
    capabilities: ClassVar[frozenset[str]] = frozenset()
    #: Time step of its one-sided dynamic runs (s); None: the model's own choice.
    contact_dt: ClassVar[float | None] = None

    def __init__(self, spec: Any):
        if not dataclasses.is_dataclass(spec) or getattr(spec, "model", None) != self.kind:
            raise TypeError(f"{type(self).__name__} needs a validated {self.kind!r} tire file, got {spec!r}")
        self._spec = spec

    @property
    def spec(self) -> Any:
        """The validated tire file."""
        return self._spec

    @property
    def name(self) -> str:
        """The tire's name (``[tire] name``)."""
        return self._spec.name

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.name!r})"

    # ------------------------------------------------------------------ what every model gives

    @classmethod
    @abstractmethod
    def parse(cls, data: dict[str, Any], source: str, path: Path | None = None) -> Any:
        """The validated spec of a tire file's contents (``source`` names it in error messages;
        ``path``, where it was read from, locates the data files it names)."""

    @property
    @abstractmethod
    def default_load(self) -> float:
        """The tire file's vertical load (N)."""

    def case(self, road: str = "flat", load: float | None = None, drum_radius: float | None = None) -> LoadCase:
        """A :class:`LoadCase` of this tire; ``load=None`` takes the tire file's load."""
        return LoadCase.of(road, self.default_load if load is None else load, drum_radius)

    @abstractmethod
    def load(self, case: LoadCase) -> Footprint:
        """The tire loaded on ``case``: footprint, pressures, tasselli, K_v (cached where costly)."""

    def load_curve(self, loads: Sequence[float]) -> list[Footprint]:
        """The tire on the flat road at each of ``loads`` (N, increasing): one :meth:`load` per load; a
        model with a nonlinear loading continues one loading through them instead."""
        return [self.load(self.case("flat", load)) for load in loads]

    @abstractmethod
    def fixed_hub_frfs(
        self, case: LoadCase, freqs: np.ndarray | None = None, progress: bool = False, stick: bool | None = None
    ) -> FRFResult:
        """The fixed-hub FRFs of the tire loaded on ``case`` at ``freqs`` (Hz; ``None``: the model's own
        grid, :data:`DEFAULT_FREQS` for an FE model). ``stick``: the footprint held against sliding
        (``None``: the model's own contact); ``progress``: a progress bar for a long sweep."""

    @abstractmethod
    def rim_side_mass(self) -> float:
        """The FE tire's mass the hub carries besides :math:`G_H` (kg), added to the unsprung mass (Eq. 5-7)."""

    def degrees_of_freedom(self) -> str:
        """The size of the model's FE problem, as printed in the models' comparison."""
        return "-"

    def equivalent_dof(self) -> int:
        """Degrees of freedom of a 3-D FE mesh of the model's resolution (the paper's "about 8000 DOF")."""
        raise NotApplicable(self.kind, "fe_mesh")

    @abstractmethod
    def frf_runs(self) -> tuple[Callable | ModuleType, ...]:
        """The numerics behind :meth:`load` and :meth:`fixed_hub_frfs` (the fingerprint of stages built on them)."""

    def code_runs(self) -> tuple[Callable | ModuleType, ...]:
        """What a stage built on this model's results fingerprints (:func:`~roadnoise_utils.repro.cache.stage_fingerprint`):
        :meth:`frf_runs` and, for a model of this package, its own module with every package module it
        imports. An edit anywhere in the model's code (its footprint's tasselli included) then
        recomputes the fits, runs and sweeps made from its results, whatever :meth:`frf_runs` lists."""
        module = sys.modules[type(self).__module__]
        own = (module,) if module.__name__.startswith(f"{__package__.split('.')[0]}.") else ()
        return (*own, *self.frf_runs())

    def fingerprint(self) -> Any:
        """What the stage cache keys on: the validated tire file (its every value, its data files' contents)."""
        return self._spec

    def replace(self, **overrides: Any) -> TireModel:
        """The same model of a tire file with some values changed (``"section.field"`` keys), validated again."""
        return type(self)(self._spec.replace(**overrides))

    # ------------------------------------------------------------------ optional capabilities

    def has(self, capability: str) -> bool:
        """Whether the model has ``capability`` (a key of :data:`CAPABILITIES`)."""
        if capability not in CAPABILITIES:
            raise ValueError(f"capability = {capability!r}: valid values are {sorted(CAPABILITIES)}")
        return capability in self.capabilities

    def require(self, capability: str) -> None:
        """Raise :class:`NotApplicable` unless the model has ``capability``."""
        if not self.has(capability):
            raise NotApplicable(self.kind, capability)

    def released_hub(
        self, case: LoadCase, freqs: np.ndarray, mass: float, stiffness: float, damping: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """The FE tire solved with its hub released on a suspension (``mass`` kg, ``stiffness`` N/m,
        ``damping`` N s/m): the hub's displacement per unit road (-) and the road force per unit road
        (N/m) at ``freqs`` (Hz), the reference of the moving-hub model (paper Eq. 5-7)."""
        raise NotApplicable(self.kind, "released_hub")

    def one_sided_setup(self, conditions: Any) -> ContactSetup:
        """How this model runs the one-sided cleat test of ``conditions``
        (:class:`roadnoise_utils.experiments.one_sided_cleat.OneSidedConditions`)."""
        raise NotApplicable(self.kind, "one_sided_cleat")

    def frozen_reference(
        self, case: LoadCase, run: Any, cleat: tuple[float, float, str], duration: float
    ) -> tuple[np.ndarray, np.ndarray]:
        """A dynamic cleat run with its contact frozen (``run``, a ``ContactRun``) against the model's
        frequency-domain solve of the same point inputs: both hub forces (N), band-limited alike
        (``cleat``: height m, base m, shape; ``duration``: the FFT record, s)."""
        raise NotApplicable(self.kind, "one_sided_cleat")

    def air_cavity(self, temperature: float | None = None) -> Cavity:
        """The tire's air cavity, unloaded (``temperature`` in deg C; default the tire file's ``[cavity]``)."""
        raise NotApplicable(self.kind, "cavity_shape")

    def loaded_cavity_areas(
        self, loads: tuple[float, ...], temperature: float | None = None
    ) -> tuple[list[Footprint], np.ndarray]:
        """The tire on the flat road at each of ``loads`` (N) and its cavity's Webster area round the
        wheel in each (m^2, one row per load; :func:`roadnoise_utils.tire.cavity.webster_modes`)."""
        raise NotApplicable(self.kind, "cavity_shape")

    def rolling_cavity_frfs(self, case: LoadCase, freqs: np.ndarray, flow_speed: float) -> FRFResult:
        """The fixed-hub FRFs at ``freqs`` (Hz) with the cavity's air streaming at ``flow_speed`` (m/s)
        round the waveguide's axis (the tire file's ``[cavity]`` settings; not cached)."""
        raise NotApplicable(self.kind, "rolling_cavity")

    @property
    def cavity_enabled(self) -> bool:
        """Whether the tire file couples its air cavity (``[cavity] enabled``)."""
        cavity = getattr(self._spec, "cavity", None)
        return bool(cavity is not None and cavity.enabled)


#: ``[tire] model`` -> its class.
REGISTRY: dict[str, type[TireModel]] = {}


def register(cls: type[TireModel]) -> type[TireModel]:
    """Class decorator: make ``cls`` the model of the tire files whose ``[tire] model`` is ``cls.kind``."""
    if not cls.kind or cls.kind in REGISTRY and REGISTRY[cls.kind] is not cls:
        raise ValueError(f"tire model {cls.kind!r}: a kind must be given once")
    unknown = set(cls.__dict__.get("capabilities", frozenset())) - set(CAPABILITIES)
    if unknown:
        raise ValueError(
            f"{cls.__name__}: unknown capabilities {sorted(unknown)}; valid values are {sorted(CAPABILITIES)}"
        )
    REGISTRY[cls.kind] = cls
    return cls


def model_class(kind: str, source: str = "tire file") -> type[TireModel]:
    """The class of a ``[tire] model``, refused with the valid values."""
    if kind not in REGISTRY:
        raise ValueError(f"{source}: [tire] model = {kind!r}: valid values are {sorted(REGISTRY)}")
    return REGISTRY[kind]


def tire_kind(data: dict[str, Any], source: str) -> str:
    """The ``[tire] model`` of a tire file's contents, refused unless a registered model builds it."""
    tire = data.get("tire")
    kind = tire.get("model") if isinstance(tire, dict) else None
    if not isinstance(kind, str):
        raise ValueError(f"{source}: [tire] model is missing: valid values are {sorted(REGISTRY)}")
    model_class(kind, source)
    return kind


def load_tire(name: str | Path) -> Any:
    """Read and validate a tire file (a name in ``data/tires`` or a path); its ``[tire] model``
    chooses the class that validates it (:data:`REGISTRY`).

    Raises
    ------
    ValueError
        A field is missing, unknown, not a number or outside its physical range; the message
        names the field, its value and the valid range.
    """
    path = data_file(name, "tires", "tire file")
    data = read_toml(path)
    return model_class(tire_kind(data, path.name), path.name).parse(data, source=path.name, path=path)


def tire_model(tire: str | Path | TireModel | Any) -> TireModel:
    """The :class:`TireModel` of a tire: a model (returned as it is), a validated spec, or a tire
    file's name in ``data/tires`` or path (read and validated once)."""
    if isinstance(tire, TireModel):
        return tire
    if isinstance(tire, (str, Path)):
        tire = load_tire(tire)
    kind = getattr(tire, "model", None)
    if not dataclasses.is_dataclass(tire) or not isinstance(kind, str):
        raise TypeError(f"tire: a tire file name or path, a validated spec or a TireModel, got {tire!r}")
    return model_class(kind)(tire)
