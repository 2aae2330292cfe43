"""roadnoise: the road-noise (RM) model of Belluzzo et al. (2002), stage by stage.

Public entry points (DESIGN section 6)::

    import roadnoise_utils as ru
    tire   = ru.load_tire("165_65R14")          # validated TireSpec from data/tires/*.toml
    fet    = ru.build_fet(tire)                 # FETModel: sparse M, K(omega), DOF maps
    static = ru.solve_static(fet, road="flat")  # or road="drum": footprint, pressures, tasselli
    visco  = ru.frf_visco(fet, static, freqs)   # direct FRFs: H_tot, H_i, G_H (fixed hub)
    reduced = ru.modal_reduction(fet, static, visco=visco)  # damping id., frozen modes, modal H_i
    fits   = ru.fit_tasselli(visco.freqs, visco.H, n_poles=14)  # one rational fit per tassello (Eq. 1)
    tire_F = ru.assemble_fixed_hub(fits)        # python-control StateSpace (A_F, B_F, C_F, D_F), Eq. 3-4
    u      = ru.cleat_input(static, speed=30/3.6)  # RoadInput: t, u[tassello, t] (cleat on the drum)
    force  = ru.simulate(tire_F, u)             # fast LTI simulation: hub force (N) vs time/distance

Cached stage results for the notebooks: :mod:`roadnoise_utils.pipeline`.
"""

from . import analysis, claims, cleat, conditions, corner, movinghub, peers, pipeline, textures, vehicle
from .calibration import calibration_table
from .fet import FETModel, build_fet
from .fitting import FitSet, RationalFit, fit_tasselli, vector_fit
from .frf import FRFResult, frf_visco
from .modal import ModalReduction, identify_modes, modal_reduction
from .modes import LoadedModes, loaded_modes
from .ring import ring_check, ring_frequencies, ring_parameters
from .road import RoadInput, cleat_input
from .simulation import SimulationResult, simulate
from .statespace import assemble_fixed_hub, realize
from .static import StaticState, load_deflection, solve_static
from .style import set_style
from .tasselli import Tasselli
from .tire_spec import TireSpec, load_tire

__version__ = "0.1.0"

__all__ = [
    "analysis",
    "claims",
    "cleat",
    "conditions",
    "corner",
    "movinghub",
    "peers",
    "FETModel",
    "FRFResult",
    "FitSet",
    "RationalFit",
    "RoadInput",
    "SimulationResult",
    "LoadedModes",
    "ModalReduction",
    "StaticState",
    "Tasselli",
    "TireSpec",
    "assemble_fixed_hub",
    "build_fet",
    "calibration_table",
    "cleat_input",
    "fit_tasselli",
    "frf_visco",
    "identify_modes",
    "load_deflection",
    "load_tire",
    "loaded_modes",
    "modal_reduction",
    "pipeline",
    "textures",
    "vehicle",
    "realize",
    "ring_check",
    "ring_frequencies",
    "ring_parameters",
    "set_style",
    "simulate",
    "solve_static",
    "vector_fit",
]
