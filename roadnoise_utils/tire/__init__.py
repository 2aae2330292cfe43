"""Stage 1-2: the FE tire (FET) — parameters, the ring model, statics on the road, tasselli.

``spec`` (validated tire files) -> ``ring_model`` (mass and stiffness of the ring-based FET,
built from ``elements`` and ``rubber``) -> ``static`` (contact on a flat road or a drum) ->
``tasselli`` (the footprint in blocks). ``closed_form`` checks the ring against its
closed-form frequencies, ``mode_shapes`` labels mode shapes, ``symmetry`` gives the exact
mirror-symmetric subspace the response solvers use. A second tire model (the cross-section,
DESIGN section 2b) takes its place beside ``ring_model``.
"""

from . import closed_form, elements, mode_shapes, ring_model, rubber, spec, static, symmetry, tasselli
from .closed_form import ring_check, ring_convergence, ring_frequencies, ring_parameters
from .ring_model import BeltMesh, FETModel, build_fet
from .rubber import FractionalZener, compound_table
from .spec import TireSpec, load_tire, tire_table
from .static import RoadSurface, StaticState, load_deflection, solve_static, static_summary
from .tasselli import Tasselli

__all__ = [
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
