"""roadnoise: the road-noise (RM) model of Belluzzo et al. (2002), stage by stage.

Public entry points (DESIGN section 6)::

    import roadnoise_utils as ru
    tire   = ru.load_tire("165_65R14")          # validated TireSpec from data/tires/*.toml
    fet    = ru.build_fet(tire)                 # FETModel: sparse M, K(omega), DOF maps
    static = ru.solve_static(fet, road="flat")  # or road="drum": footprint, pressures, tasselli
    visco  = ru.frf_visco(fet, static, freqs)   # direct FRFs: H_tot, H_i, G_H (fixed hub)
    reduced = ru.modal_reduction(fet, static, visco=visco)  # damping id., frozen modes, modal H_i

Cached stage results for the notebooks: :mod:`roadnoise_utils.pipeline`.
"""

from . import analysis, collection, paper, pipeline
from .calibration import calibration_table
from .fet import FETModel, build_fet
from .frf import FRFResult, frf_visco
from .modal import ModalReduction, identify_modes, modal_reduction
from .modes import LoadedModes, loaded_modes
from .ring import ring_check, ring_frequencies, ring_parameters
from .static import StaticState, load_deflection, solve_static
from .style import set_style
from .tasselli import Tasselli
from .tire_spec import TireSpec, load_tire

__version__ = "0.1.0"

__all__ = [
    "analysis",
    "collection",
    "paper",
    "FETModel",
    "FRFResult",
    "LoadedModes",
    "ModalReduction",
    "StaticState",
    "Tasselli",
    "TireSpec",
    "build_fet",
    "calibration_table",
    "frf_visco",
    "identify_modes",
    "load_deflection",
    "load_tire",
    "loaded_modes",
    "modal_reduction",
    "pipeline",
    "ring_check",
    "ring_frequencies",
    "ring_parameters",
    "set_style",
    "solve_static",
]
