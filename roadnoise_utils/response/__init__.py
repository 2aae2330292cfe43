"""What the RM method shares between tire models once the footprint FRFs exist.

``modal_reduction`` identifies modes and global damping from any model's :math:`H_{tot}`
(paper Fig. 4) and holds the modal reduction's result type; ``band_limit`` band-limits a
reference response to the RM chain's band; ``uff`` writes every FRF set of any tire model to a
UFF 58 file and reads it back. The models' own solvers (direct FRFs, modes, FE references)
live in their folders under :mod:`roadnoise_utils.tire`.
"""

from ..tire.model import FRFResult
from . import band_limit, modal_reduction, uff
from .modal_reduction import ModalReduction, identify_modes
from .uff import read_uff58, write_uff58

__all__ = [
    "FRFResult",
    "ModalReduction",
    "band_limit",
    "identify_modes",
    "modal_reduction",
    "read_uff58",
    "uff",
    "write_uff58",
]
