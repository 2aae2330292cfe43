"""Stage 11: the road flowing through the footprint — tassello inputs from cleats, textures and road files.

``input`` turns any road (a 2D profile or a 3D height field) into tassello displacement
histories through each tassello's shape-function kernel (``kernels``); ``cleat`` is the drum
test's obstacle, ``textures`` the ISO 8608 + megatexture spectra and seeded random roads,
``files`` measured roads read from CSV, ``two_track`` the four wheels of a vehicle on one road.
"""

from . import cleat, files, input, kernels, textures, two_track
from .cleat import cleat_profile
from .files import load_road_file
from .input import RoadInput, contact_tracks, profile_input, sample_rate_for, texture_input
from .kernels import kernel_transforms, tassellation_error, tassello_kernels
from .textures import RoadProfile, RoadSpectrum, generate_field, generate_profile, load_texture

__all__ = [
    "RoadInput",
    "RoadProfile",
    "RoadSpectrum",
    "cleat",
    "cleat_profile",
    "contact_tracks",
    "files",
    "generate_field",
    "generate_profile",
    "input",
    "kernel_transforms",
    "kernels",
    "load_road_file",
    "load_texture",
    "profile_input",
    "sample_rate_for",
    "tassellation_error",
    "tassello_kernels",
    "texture_input",
    "textures",
    "two_track",
]
