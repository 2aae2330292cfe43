"""Stages 10 and 12: the vehicle — quarter car with strut, the corner coupled through G_H, spectra.

``quarter_car`` reads a vehicle file into a python-control model (paper Fig. 13, with the
strut that shapes Fig. 10) -> ``corner`` closes it through the moving-hub tire (Eq. 8 for one
corner), in the time and the frequency domain -> ``spectra`` (Welch PSDs and band statistics,
Fig. 11-14).
"""

from . import corner, quarter_car, spectra
from .corner import CornerRun, corner_model, predicted_psd, run_corner
from .quarter_car import QuarterCar, load_vehicle, transmissibility, transmissibility_statistics, vehicle_statespace

__all__ = [
    "CornerRun",
    "QuarterCar",
    "corner",
    "corner_model",
    "load_vehicle",
    "predicted_psd",
    "quarter_car",
    "run_corner",
    "spectra",
    "transmissibility",
    "transmissibility_statistics",
    "vehicle_statespace",
]
