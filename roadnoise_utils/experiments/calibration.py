"""Calibration of a FET against its targets: the "target / obtained" table.

Targets live in ``data/calibration/<tire>.toml`` (a range and a source for each quantity);
the obtained values are computed from the static state and the direct FRF of the tire (the
damping ratio of the first vertical mode by the modal least squares of notebook 02).
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from ..analysis import resonance_peaks
from ..repro import stages
from ..repro.paths import data_dir, read_toml
from ..response.modal_reduction import identify_modes
from ..tire.cross_section import stages as section_stages
from ..tire.cross_section.spec import CrossSectionSpec
from ..tire.spec import TireSpec

#: Suffix of a cross-section tire file built for the same size as a ring tire file (same targets).
CROSS_SECTION_SUFFIX = "_cross_section"


def calibration_targets(tire: str) -> dict:
    """Targets of a tire (file stem in ``data/calibration``); empty when the tire has none.

    A cross-section tire file ``<size>_cross_section`` shares the targets of ``<size>``: the
    targets belong to the tire, not to the model of it.
    """
    path = data_dir() / "calibration" / f"{tire}.toml"
    if not path.exists() and tire.endswith(CROSS_SECTION_SUFFIX):
        path = data_dir() / "calibration" / f"{tire.removesuffix(CROSS_SECTION_SUFFIX)}.toml"
    if not path.exists():
        return {}
    return read_toml(path)


def calibration_values(tire: str | TireSpec | CrossSectionSpec) -> dict[str, float]:
    """The calibrated quantities of a tire (either model), in the targets' units."""
    spec = stages.load_tire(tire) if not isinstance(tire, CrossSectionSpec) else tire
    if isinstance(spec, CrossSectionSpec):
        static = section_stages.section_static(spec, "flat")
        frf = section_stages.section_footprint(spec, "flat")
    else:
        static = stages.solve_static(spec, "flat")
        frf = stages.frf_visco(spec, "flat")
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


def calibration_table(tire: str | TireSpec | CrossSectionSpec = "165_65R14") -> pd.DataFrame:
    """Table "quantity / target / obtained / unit / ok / source" of the tire's calibration.

    A tire without ``data/calibration/<tire>.toml`` gets the obtained values only (target
    ``-``, ok ``True``): copy and edit a targets file to check your own tire.
    """
    spec = stages.load_tire(tire)
    targets = calibration_targets(Path(spec.source.split(" ")[0]).stem)
    values = calibration_values(spec)
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
