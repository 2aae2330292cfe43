"""Calibration of a FE tire against its targets: the "target / obtained" table.

Targets live in ``data/calibration/<tire>.toml`` (a range and a source for each quantity);
the obtained values are computed from the static state and the direct FRF of the tire (the
damping ratio of the first vertical mode by the modal least squares of notebook 02).
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from ..analysis import resonance_peaks
from ..repro.paths import data_dir, read_toml
from ..repro.stages import Tire
from ..response.modal_reduction import identify_modes
from ..tire.model import tire_model

#: Suffixes of the tire files of other models built for the same size as a ring tire file (same
#: targets): the cross-section tire and the loaded FE tire.
MODEL_SUFFIXES = ("_cross_section", "_loaded")


def calibration_targets(tire: str) -> dict:
    """Targets of a tire (file stem in ``data/calibration``); empty when the tire has none.

    A cross-section or loaded FE tire file (``<size>_cross_section``, ``<size>_loaded``) shares the
    targets of ``<size>``: the targets belong to the tire, not to the model of it.
    """
    path = data_dir() / "calibration" / f"{tire}.toml"
    for suffix in MODEL_SUFFIXES:
        if not path.exists() and tire.endswith(suffix):
            path = data_dir() / "calibration" / f"{tire.removesuffix(suffix)}.toml"
    if not path.exists():
        return {}
    return read_toml(path)


def tire_targets(tire: Tire) -> dict:
    """The targets of a tire (any model), found by its file's name (:func:`calibration_targets`)."""
    return calibration_targets(Path(tire_model(tire).spec.source.split(" ")[0]).stem)


def calibration_values(tire: Tire) -> dict[str, float]:
    """The calibrated quantities of a tire (any model), in the targets' units: its footprint and its
    fixed-hub FRFs on the flat road at its file's load (cached)."""
    model = tire_model(tire)
    case = model.case("flat")
    static, frf = model.load(case), model.fixed_hub_frfs(case)
    peaks, _ = resonance_peaks(frf.freqs, frf.H_tot)
    t = static.tasselli
    return {
        "vertical_stiffness": static.vertical_stiffness / 1e3,
        "first_vertical_resonance": float(peaks[0]) if peaks.size else float("nan"),
        "first_vertical_damping": float(identify_modes(frf.freqs, frf.H_tot).damping[0]),
        "footprint_length": static.footprint_length * 1e3,
        "footprint_width": static.footprint_width * 1e3,
        "n_tasselli": t.n,
        "max_tassello_size": max(t.length.max(), t.width.max()) * 1e3,
    }


def calibration_table(tire: Tire = "165_65R14") -> pd.DataFrame:
    """Table "quantity / target / obtained / unit / ok / source" of the tire's calibration.

    A tire without ``data/calibration/<tire>.toml`` gets the obtained values only (target
    ``-``, ok ``True``): copy and edit a targets file to check your own tire.
    """
    model = tire_model(tire)
    targets = tire_targets(model)
    values = calibration_values(model)
    rows = []
    for name, value in values.items():
        t = targets.get(name)
        rows.append(
            {
                "quantity": name.replace("_", " "),
                "target": f"{t['low']:g} - {t['high']:g}" if t else "-",
                "obtained": value,
                "unit": t["unit"] if t else _UNITS[name],
                "ok": bool(t["low"] <= value <= t["high"]) if t else True,
                "source": t["source"] if t else "no targets for this tire",
            }
        )
    return pd.DataFrame(rows).set_index("quantity")


_UNITS = {
    "vertical_stiffness": "N/mm",
    "first_vertical_resonance": "Hz",
    "first_vertical_damping": "-",
    "footprint_length": "mm",
    "footprint_width": "mm",
    "n_tasselli": "-",
    "max_tassello_size": "mm",
}
