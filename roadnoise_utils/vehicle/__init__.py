"""Stages 10 and 12: the vehicle — quarter car with strut, the corner coupled through G_H, spectra.

``quarter_car`` reads a vehicle file into a python-control model (paper Fig. 13, with the
strut that shapes Fig. 10) -> ``corner`` closes it through the moving-hub tire (Eq. 8 for one
corner), in the time and the frequency domain -> ``spectra`` (Welch PSDs and band statistics,
Fig. 11-14); ``full_car`` puts four such corners under a rigid body in heave, pitch and roll
(the whole vehicle of Eq. 8, beyond the paper).
"""

from . import corner, full_car, quarter_car, spectra
from .corner import CornerRun, corner_model, predicted_psd, run_corner
from .full_car import FullCar, full_car_model, load_full_vehicle, run_full_car
from .quarter_car import QuarterCar, load_vehicle, transmissibility, transmissibility_statistics, vehicle_statespace

__all__ = [
    "CornerRun",
    "FullCar",
    "QuarterCar",
    "corner",
    "corner_model",
    "full_car",
    "full_car_model",
    "load_full_vehicle",
    "load_vehicle",
    "predicted_psd",
    "quarter_car",
    "run_corner",
    "run_full_car",
    "spectra",
    "transmissibility",
    "transmissibility_statistics",
    "vehicle_statespace",
]
