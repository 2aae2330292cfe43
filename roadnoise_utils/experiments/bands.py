"""The RM model taken from 0-250 Hz to 0-400 Hz (paper, Abstract and Conclusions: "it can be
easily improved to 400 Hz"; "an extension up to 400 Hz can be easily performed").

What the band sets, stage by stage, for a band ``B``:

* **FRFs** of the direct viscoelastic model over 0-``B`` (the default sweep is 0-400 Hz);
* **fits** of Eq. 1 over 0-``B``, the order chosen automatically (1 % on every tassello, or the
  best order with a warning, :func:`roadnoise_utils.rm.order.lowest_order`);
* **sampling**: at least :data:`~roadnoise_utils.road.input.SAMPLES_PER_PERIOD` samples per
  period of ``B`` and a road step of at most
  :data:`~roadnoise_utils.road.input.MAX_ROAD_STEP` (:func:`.road.input.sample_rate_for`);
* **road resolution**: the shortest road wavelength the band reaches at speed ``V`` is
  ``V / B``; a tassello of length ``l`` averages the road over ``l`` (the tassellation error at
  that wavelength and frequency, :func:`.road.kernels.tassellation_error`);
* **modal reduction** (paper Fig. 4) with loaded modes to at least ``2 B``.

Both models are compared band-limited the same way: flat to ``B - TAPER`` and zero at ``B``
(:func:`roadnoise_utils.response.band_limit.band_window`), so no FRF is needed above its band. On the cleat
the reference is the direct FE response (no reduction, no fit); on the rough road the
frequency-domain hub-force PSD of the direct FRFs (road uniform across the width).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .. import guards
from ..analysis import relative_rms_error
from ..repro import stages
from ..repro.inputs import DEFAULT_FREQS
from ..response.band_limit import frequency_domain_response, on_frf_grid
from ..response.modal_reduction import ModalReduction
from ..rm.fitting import FitSet
from ..rm.realisation import assemble_fixed_hub
from ..rm.simulation import modal_sections
from ..road.cleat import cleat_input
from ..road.input import RoadInput, sample_rate_for
from ..road.kernels import tassellation_error
from ..tire.model import FRFResult
from ..vehicle.corner import predicted_psd
from .cleat import CleatConditions, cleat_conditions
from .passage import rm_cleat_response
from .road import RoadTestConditions, road_test_conditions

#: Width of the raised-cosine edge of the comparison window below each band (Hz).
TAPER = 50.0
#: The paper's band and the extension (Hz).
BANDS = (250.0, 400.0)
#: Where the rough-road levels are compared (Hz): above the paper's band, below the extension's taper.
ADDED_BAND = (250.0, 350.0)


@dataclass(frozen=True, eq=False)
class BandModel:
    """The RM chain built for one band.

    Attributes
    ----------
    band : float
        Upper end of the band (Hz).
    drum_fits, road_fits : FitSet
        Tassello fits (Eq. 1) over 0-``band`` on the drum (cleat) and the flat road.
    cleat : RoadInput
        The cleat's tassello inputs, sampled for this band.
    cleat_rm, cleat_fe : ndarray
        Hub force (N) from the RM chain and from the direct FE FRFs, both band-limited to ``band``.
    road_psd : ndarray
        Hub-force PSD of the RM chain on the rough road (N^2/Hz) at :attr:`BandExtension.road_freqs`.
    modal : ModalReduction
        The paper's modal reduction for this band (loaded modes to at least ``2 band``).
    """

    band: float
    drum_fits: FitSet
    road_fits: FitSet
    cleat: RoadInput
    cleat_rm: np.ndarray
    cleat_fe: np.ndarray
    road_psd: np.ndarray
    modal: ModalReduction


@dataclass(frozen=True, eq=False)
class BandExtension:
    """The RM chain at each band against the direct FE model, on the cleat and on the rough road.

    Attributes
    ----------
    tire : str
        The tire file.
    cleat_conditions : CleatConditions
    road_conditions : RoadTestConditions
    models : dict of float to BandModel
    road_freqs : ndarray
        Frequencies of the rough-road PSDs (Hz).
    road_fe_psd : ndarray
        Hub-force PSD of the direct FE FRFs on the rough road (N^2/Hz).
    visco : FRFResult
        The direct FRFs on the flat road (0-400 Hz).
    tassello_length : float
        Longest tassello along the road on the flat road (m).
    """

    tire: str
    cleat_conditions: CleatConditions
    road_conditions: RoadTestConditions
    models: dict[float, BandModel]
    road_freqs: np.ndarray
    road_fe_psd: np.ndarray
    visco: FRFResult
    tassello_length: float

    def table(self) -> pd.DataFrame:
        """What each band needs and how well the chain follows the FE model (one column per band)."""
        static = stages.solve_static(self.tire)
        rows = {}
        for band, m in self.models.items():
            k = int(np.argmin(np.abs(self.visco.freqs - band)))
            road_speed, cleat_speed = self.road_conditions.speed, self.cleat_conditions.dynamic_speed
            lam_road, lam_cleat = band_wavelengths(band, road_speed, cleat_speed)
            modal_error = _band_error(self.visco, m.modal.frf, (0.0, band))
            added = (self.road_freqs > ADDED_BAND[0]) & (self.road_freqs <= ADDED_BAND[1])
            rows[f"0-{band:g} Hz"] = {
                "poles per tassello (automatic)": m.drum_fits.n_poles,
                "worst fit error, drum (%)": 100 * m.drum_fits.rms_errors.max(),
                "worst fit error, flat road (%)": 100 * m.road_fits.rms_errors.max(),
                "sample rate at the cleat speed (kHz)": m.cleat.sample_rate / 1e3,
                f"shortest wavelength at {3.6 * cleat_speed:.0f} km/h (mm)": 1e3 * lam_cleat,
                f"shortest wavelength at {3.6 * road_speed:.0f} km/h (mm)": 1e3 * lam_road,
                "tasselli per shortest wavelength (cleat speed)": lam_cleat / self.tassello_length,
                "tassellation error at the shortest wavelength (%)": 100
                * tassellation_error(static, self.visco.H_points[:, k], [lam_cleat])[0],
                "cleat: RM vs FE peak (%)": 100 * (m.cleat_rm.max() / m.cleat_fe.max() - 1),
                "cleat: RM vs FE RMS (%)": 100 * relative_rms_error(m.cleat_rm, m.cleat_fe),
                "rough road: RM vs FE level 250-350 Hz (dB)": _level_difference(
                    m.road_psd[added], self.road_fe_psd[added]
                ),
                "modal reduction: highest loaded mode (Hz)": m.modal.model.freqs.max(),
                "modal reduction: H_tot error over the band (%)": 100 * modal_error,
            }
        return pd.DataFrame(rows)

    def cleat_against_widest(self) -> pd.DataFrame:
        """Each band's RM cleat force against the widest band's direct FE force (peak and RMS, -).

        What a narrower model misses of the cleat's content; the RM forces are interpolated onto
        the widest band's (finer) time grid.
        """
        widest = self.models[max(self.models)]
        rows = {}
        for band, model in self.models.items():
            force = np.interp(widest.cleat.t, model.cleat.t, model.cleat_rm)
            rows[f"0-{band:g} Hz"] = {
                "RM peak (N)": model.cleat_rm.max(),
                "peak against the widest FE": force.max() / widest.cleat_fe.max() - 1,
                "RMS against the widest FE": relative_rms_error(force, widest.cleat_fe),
            }
        return pd.DataFrame(rows).T


def band_wavelengths(band: float, road_speed: float, cleat_speed: float) -> tuple[float, float]:
    """Shortest wavelengths ``speed / band`` (m) at the road test's and the cleat test's speeds."""
    band = guards.real("band", band, 0.0, lo_open=True, unit="Hz")
    return road_speed / band, cleat_speed / band


def _band_error(reference: FRFResult, approximation: FRFResult, band: tuple[float, float]) -> float:
    keep = (reference.freqs >= band[0]) & (reference.freqs <= band[1])
    return relative_rms_error(approximation.H_tot[keep], reference.H_tot[keep])


def _level_difference(psd: np.ndarray, reference: np.ndarray) -> float:
    """Band level of ``psd`` over the reference's (dB); NaN for an empty band."""
    if psd.size == 0:
        return float("nan")
    return float(10 * np.log10(np.sum(psd) / np.sum(reference)))


def cleat_chain(
    tire, band: float, test: CleatConditions | None = None
) -> tuple[RoadInput, FitSet, np.ndarray, np.ndarray]:
    """The paper's dynamic cleat run through the RM chain built for 0-``band`` Hz and through the
    direct FE FRFs, both band-limited the same way: ``(road, drum fits, RM force, FE force)`` (N)."""
    band = guards.real(
        "band", band, TAPER, float(DEFAULT_FREQS[-1]), lo_open=True, unit="Hz (the FRF sweep ends at 400 Hz)"
    )
    test = cleat_conditions() if test is None else test
    drum = {"road": "drum", "drum_radius": test.drum_radius}
    fits = stages.fit_tasselli(tire, f_max=band, **drum)
    speed = test.dynamic_speed
    road = cleat_input(
        stages.solve_static(tire, **drum), speed, test.height, test.base, test.shape, test.fe_distance,
        sample_rate=sample_rate_for(speed, band),
    )  # fmt: skip
    window = band - TAPER
    rm = rm_cleat_response(modal_sections(assemble_fixed_hub(fits)), road, band=window, duration=test.fe_duration)
    visco = stages.frf_visco(tire, **drum)
    fe = frequency_domain_response(on_frf_grid(visco), road.u, road.dt, window, test.fe_duration)
    return road, fits, rm, fe


def _band_model(tire, band, test: CleatConditions, road_test: RoadTestConditions, road_freqs) -> BandModel:
    cleat, drum_fits, rm, fe = cleat_chain(tire, band, test)
    road_fits = stages.fit_tasselli(tire, f_max=band)
    spectrum = road_test.spectra()["rough"]
    static = stages.solve_static(tire)
    psd = predicted_psd(road_freqs, road_fits.responses(road_freqs), static, spectrum, road_test.speed)["F_F"]
    return BandModel(
        band=band,
        drum_fits=drum_fits,
        road_fits=road_fits,
        cleat=cleat,
        cleat_rm=rm,
        cleat_fe=fe,
        road_psd=psd,
        modal=stages.modal_reduction(tire, f_band=band),
    )


def band_extension(tire: str = "165_65R14_cross_section", bands: tuple[float, ...] = BANDS) -> BandExtension:
    """The RM chain at each band on the paper's cleat test and the rough road (see the module notes).

    ``bands`` (Hz) in (``TAPER``, 400]: the direct FRFs of the default sweep end at 400 Hz.
    """
    bands = tuple(
        guards.real("bands", b, TAPER, float(DEFAULT_FREQS[-1]), lo_open=True, unit="Hz (the FRF sweep ends at 400 Hz)")
        for b in bands
    )
    if not bands:
        raise ValueError("bands is empty: give at least one band in (50, 400] Hz")
    test, road_test = cleat_conditions(), road_test_conditions()
    road_freqs = np.arange(1.0, max(bands) + 1.0)
    visco = stages.frf_visco(tire)
    static = stages.solve_static(tire)
    road_fe_psd = predicted_psd(
        road_freqs, on_frf_grid(visco)(road_freqs), static, road_test.spectra()["rough"], road_test.speed
    )["F_F"]
    return BandExtension(
        tire=tire,
        cleat_conditions=test,
        road_conditions=road_test,
        models={b: _band_model(tire, b, test, road_test, road_freqs) for b in bands},
        road_freqs=road_freqs,
        road_fe_psd=road_fe_psd,
        visco=visco,
        tassello_length=float(static.tasselli.length.max()),
    )
