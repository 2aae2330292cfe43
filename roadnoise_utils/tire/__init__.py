"""Stage 1-2: the FE tire (FET) — parameters, the ring model, statics on the road, tasselli.

``spec`` (validated tire files) -> ``ring_model`` (mass and stiffness of the ring-based FET,
built from ``elements`` and ``rubber``) -> ``static`` (contact on a flat road or a drum) ->
``tasselli`` (the footprint in blocks). ``closed_form`` checks the ring against its
closed-form frequencies, ``mode_shapes`` labels mode shapes, ``symmetry`` gives the exact
mirror-symmetric subspace the response solvers use. The second tire model, the
cross-section (``[tire] model = "cross-section"``, notebook 09): ``cross_section``
(validated construction files) -> ``laminate`` (layer constants) -> ``section_geometry`` and
``section_mesh`` (the layered mesh) -> ``waveguide`` and ``section_model`` (harmonic matrices,
inflation) -> ``section_contact`` and ``section_static`` (Green's functions, the loaded tire)
-> ``section_dynamics`` (reduced harmonic receptances) -> ``section_stepping`` (the harmonics
stepped in time, for contact loss); ``section_checks`` verifies it.
"""

from . import (
    closed_form,
    cross_section,
    elements,
    laminate,
    mode_shapes,
    ring_model,
    rubber,
    section_checks,
    section_contact,
    section_dynamics,
    section_geometry,
    section_mesh,
    section_model,
    section_static,
    section_stepping,
    spec,
    static,
    symmetry,
    tasselli,
    waveguide,
)
from .closed_form import ring_check, ring_convergence, ring_frequencies, ring_parameters
from .ring_model import BeltMesh, FETModel, build_fet
from .rubber import FractionalZener, compound_table
from .spec import TireSpec, load_tire, tire_table
from .static import StaticState, load_deflection, solve_static, static_summary
from .surface import RoadSurface
from .tasselli import Tasselli

__all__ = [
    "cross_section",
    "laminate",
    "section_checks",
    "section_contact",
    "section_dynamics",
    "section_geometry",
    "section_mesh",
    "section_model",
    "section_static",
    "section_stepping",
    "waveguide",
    "BeltMesh",
    "FETModel",
    "FractionalZener",
    "RoadSurface",
    "StaticState",
    "Tasselli",
    "TireSpec",
    "build_fet",
    "closed_form",
    "compound_table",
    "elements",
    "load_deflection",
    "load_tire",
    "mode_shapes",
    "ring_check",
    "ring_convergence",
    "ring_frequencies",
    "ring_model",
    "ring_parameters",
    "rubber",
    "solve_static",
    "spec",
    "static",
    "static_summary",
    "symmetry",
    "tasselli",
    "tire_table",
]
