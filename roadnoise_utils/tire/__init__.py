"""Stage 1-2: the FE tire — the tire-model interface, what every model shares, one folder per model.

``model`` holds the interface (:class:`TireModel`, :class:`LoadCase`, :class:`Footprint`,
:class:`FRFResult`) and the registry that maps a tire file's ``[tire] model`` to its class.
Shared by every model: ``tasselli`` (the footprint in blocks, paper Fig. 2), ``surface`` (the
road a tire is loaded on), ``active_set`` (frictionless vertical contact), ``rubber`` (the
compounds' frequency-dependent moduli), ``cavity`` (the air cavity's acoustic waveguide),
``contact`` (the result and time grid of a one-sided contact run), ``footprint_file`` (a
footprint geometry read from CSV). One folder per model, each with its spec, statics,
dynamics and checks: ``ring`` (the ring-based FET of notebook 01), ``cross_section`` (the
layered cross-section tire of notebook 09), ``frf_file`` (a user's FE tire read from UFF 58
FRFs and a footprint file), ``loaded`` (the cross-section's construction as 3-D solids loaded by
large-deformation statics, linearised about its loaded state).
"""

from . import active_set, cavity, contact, footprint_file, model, rubber, surface, tasselli
from .model import Footprint, FRFResult, LoadCase, NotApplicable, TireModel, load_tire, tire_model
from .rubber import FractionalZener, compound_table
from .surface import RoadSurface
from .tasselli import Tasselli

__all__ = [
    "Footprint",
    "FRFResult",
    "FractionalZener",
    "LoadCase",
    "NotApplicable",
    "RoadSurface",
    "Tasselli",
    "TireModel",
    "active_set",
    "cavity",
    "compound_table",
    "contact",
    "footprint_file",
    "load_tire",
    "model",
    "rubber",
    "surface",
    "tasselli",
    "tire_model",
]
