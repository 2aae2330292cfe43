"""Stages 3-5: the loaded tire's response — direct FRFs (FETvisco), modes, modal reduction, FE references.

``loaded`` linearises the tire about its static state (footprint tied to the road) ->
``frf`` solves the direct FRFs :math:`H_{tot}, H_i, G_H` (paper Eq. (i)) -> ``modes`` (the
frozen FET70Hz eigenproblem) -> ``modal_reduction`` (damping identification, modal local FRFs,
paper Fig. 4-5). ``fe_reference`` holds the FE solves every RM-chain result is checked against.
The cross-section tire has its own: ``section_footprint`` (direct FRFs), ``section_modal`` (its
modal reduction, loaded modes by component-mode synthesis) and ``section_one_sided`` (the
quasi-static cleat passage with contact loss); ``one_sided`` is the ring's contact loss.
``uff`` writes every FRF set of either tire to a UFF 58 file and reads it back.
"""

from ..tire.model import FRFResult
from . import (
    fe_reference,
    frf,
    loaded,
    modal_reduction,
    modes,
    one_sided,
    section_footprint,
    section_modal,
    section_one_sided,
    uff,
)
from .fe_reference import fe_cleat_response, fe_moving_hub, fe_road_response
from .frf import frf_visco
from .loaded import LoadedTire, loaded_tire
from .modal_reduction import ModalReduction, identify_modes
from .modes import LoadedModes, loaded_modes
from .uff import read_uff58, write_uff58

__all__ = [
    "FRFResult",
    "LoadedModes",
    "LoadedTire",
    "ModalReduction",
    "fe_cleat_response",
    "fe_moving_hub",
    "fe_reference",
    "fe_road_response",
    "frf",
    "frf_visco",
    "identify_modes",
    "loaded",
    "loaded_modes",
    "loaded_tire",
    "modal_reduction",
    "modes",
    "one_sided",
    "read_uff58",
    "section_footprint",
    "section_modal",
    "section_one_sided",
    "uff",
    "write_uff58",
]
