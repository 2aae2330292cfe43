"""Stage 11: the road flowing through the footprint — tassello inputs from cleats, textures and road files.

``input`` turns any road (a 2D profile or a 3D height field) into tassello displacement
histories through each tassello's shape-function kernel (``kernels``); ``cleat`` is the drum
test's obstacle, ``textures`` the ISO 8608 + megatexture spectra and seeded random roads,
``files`` measured roads read from CSV, ``crg`` OpenCRG road files in and out (their modifiers
explicit), ``two_track`` the four wheels of a vehicle on one road.
"""

from . import cleat, crg, files, input, kernels, textures, two_track
from .cleat import cleat_profile
from .crg import crg_modifiers, load_crg, save_crg
from .files import check_road_grid, load_road_file
from .input import RoadInput, contact_tracks, profile_input, sample_rate_for, texture_input
from .kernels import kernel_transforms, tassellation_error, tassello_kernels
from .textures import RoadProfile, RoadSpectrum, generate_field, generate_profile, load_texture

__all__ = [
    "RoadInput",
    "RoadProfile",
    "RoadSpectrum",
    "check_road_grid",
    "cleat",
    "cleat_profile",
    "contact_tracks",
    "crg",
    "crg_modifiers",
    "files",
    "generate_field",
    "generate_profile",
    "input",
    "kernel_transforms",
    "kernels",
    "load_crg",
    "load_road_file",
    "load_texture",
    "profile_input",
    "sample_rate_for",
    "save_crg",
    "tassellation_error",
    "tassello_kernels",
    "texture_input",
    "textures",
    "two_track",
]
