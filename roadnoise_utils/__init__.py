"""roadnoise: the road-noise (RM) model of Belluzzo et al. (2002), stage by stage.

Public entry points::

    import roadnoise_utils as ru
    tire   = ru.load_tire("165_65R14")          # validated TireSpec from data/tires/*.toml
    fet    = ru.build_fet(tire)                 # FETModel: sparse M, K(omega), DOF maps
    static = ru.solve_static(fet, road="flat")  # or road="drum" (the paper's drum): footprint, tasselli
    freqs  = ru.stages.DEFAULT_FREQS            # 0-400 Hz every 1 Hz
    visco  = ru.frf_visco(fet, static, freqs)   # direct FRFs: H_tot, H_i, G_H (fixed hub)
    reduced = ru.modal_reduction(fet, static, visco=visco)  # damping id., frozen modes, modal H_i
    fits   = ru.fit_tasselli(visco.freqs, visco.H, n_poles=14, f_max=250.0)  # one fit per tassello (Eq. 1), 0-250 Hz
    tire_F = ru.assemble_fixed_hub(fits)        # python-control StateSpace (A_F, B_F, C_F, D_F), Eq. 3-4
    u      = ru.cleat_input(static, speed=30/3.6)  # RoadInput: t, u[tassello, t] (the paper's cleat)
    force  = ru.simulate(tire_F, u)             # fast LTI simulation: hub force (N) vs time/distance
    ru.export_fmu("165_65R14", "tire.fmu", speed=30 / 3.6)  # the moving-hub tire as an FMI 2.0 FMU
    ru.write_uff58("frfs.uff", visco)           # every FRF (H_i, H_tot, G_H) as UFF 58; ru.read_uff58 reads it
    road   = ru.road.load_crg("road.crg")       # an OpenCRG road (its modifiers explicit: ``modifiers=``)
    run    = ru.experiments.cleat_test("165_65R14")   # the paper's test, conditions resolved once

The package, one folder per stage, data flowing one way:

* :mod:`.tire` — the tire-model interface, tasselli, rubber, cavity; one folder per model (stages 1-5)
* :mod:`.response` — damping identification and the modal model, band limits, UFF 58 (stages 3-5)
* :mod:`.rm` — fits, state space (fixed and moving hub), simulation (stages 6-9)
* :mod:`.road` — tassello inputs from cleats, textures and road files (stage 11)
* :mod:`.vehicle` — quarter car, corner coupling, spectra (stages 10, 12)
* :mod:`.fmu` — the tire for vehicle tools: an FMI 2.0 FMU, state-space ``.mat`` files
* :mod:`.experiments` — the paper's tests, reading ``data/conditions`` once
* :mod:`.figures` — the chapters' figure modules
* :mod:`.repro` — paths, the stage cache, :mod:`.stages` (cached stage functions), claims,
  the collection, the reproduce command (``python -m roadnoise_utils``)
"""

from . import analysis, experiments, figures, fmu, guards, response, rm, road, settings, tire, vehicle
from .experiments.fmu_export import export_fmu
from .experiments.paper_defaults import cleat_input, solve_static
from .repro import cache, claims, collection, stages
from .repro.style import set_style
from .response.modal_reduction import ModalReduction, identify_modes
from .response.uff import read_uff58, write_uff58
from .rm.fitting import FitSet, RationalFit, fit_tasselli, vector_fit
from .rm.realisation import assemble_fixed_hub, realize
from .rm.simulation import SimulationResult, simulate
from .road import textures
from .road.input import RoadInput
from .tire.cross_section import model as _cross_section_model  # noqa: F401 - registers the model
from .tire.cross_section import stages as section_stages
from .tire.frf_file import model as _frf_file_model  # noqa: F401 - registers the model
from .tire.frf_file.export import export_frf_files
from .tire.loaded import model as _loaded_model  # noqa: F401 - registers the model
from .tire.model import Footprint, FRFResult, LoadCase, NotApplicable, TireModel, tire_model
from .tire.ring import model as _ring_model  # noqa: F401 - registers the model
from .tire.ring.closed_form import ring_check, ring_frequencies, ring_parameters
from .tire.ring.frf import frf_visco
from .tire.ring.mechanics import FETModel, build_fet
from .tire.ring.modal_reduction import modal_reduction
from .tire.ring.modes import LoadedModes, loaded_modes
from .tire.ring.spec import TireSpec, load_tire
from .tire.ring.static import StaticState, load_deflection
from .tire.tasselli import Tasselli

__version__ = "0.1.0"

__all__ = [
    "FETModel",
    "FRFResult",
    "Footprint",
    "LoadCase",
    "NotApplicable",
    "TireModel",
    "FitSet",
    "LoadedModes",
    "ModalReduction",
    "RationalFit",
    "RoadInput",
    "SimulationResult",
    "StaticState",
    "Tasselli",
    "TireSpec",
    "analysis",
    "assemble_fixed_hub",
    "build_fet",
    "cache",
    "claims",
    "cleat_input",
    "collection",
    "experiments",
    "export_fmu",
    "export_frf_files",
    "figures",
    "fmu",
    "fit_tasselli",
    "frf_visco",
    "guards",
    "settings",
    "identify_modes",
    "load_deflection",
    "load_tire",
    "loaded_modes",
    "modal_reduction",
    "read_uff58",
    "realize",
    "response",
    "ring_check",
    "ring_frequencies",
    "ring_parameters",
    "rm",
    "road",
    "set_style",
    "simulate",
    "solve_static",
    "section_stages",
    "stages",
    "textures",
    "tire",
    "tire_model",
    "vector_fit",
    "vehicle",
    "write_uff58",
]
