"""The paper's claims, our value for each, and the reproduction report.

The claims, what the paper says, the tolerance and the notebook live in
``data/paper/claims.toml``; this module computes *our* number for each claim with the same
experiments and cached stages the notebooks call (:mod:`roadnoise_utils.experiments`, on the
paper's tires and conditions, whatever a notebook's parameters) and judges it with the data's
test. :func:`report` is the table notebook 00 and the
reproduction command show; :func:`write_report` writes it as CSV and Markdown.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from ..analysis import band_errors, distinct_peaks, peak_comparison, resonance_peaks
from ..experiments.cleat import PAPER_TIRE, CleatTest, cleat_test
from ..experiments.corner import PAPER_CAR, QuarterCarTest, quarter_car
from ..experiments.moving_hub import CHECK_TIRE, moving_hub_check
from ..experiments.one_sided_cleat import OneSidedCleatTest, one_sided_cleat_test
from ..response.frf import FRFResult
from ..rm.fitting import fit_tasselli
from ..road.kernels import tassellation_error
from ..vehicle.quarter_car import FrequencyBand, load_vehicle, transmissibility_statistics
from ..vehicle.spectra import band_rms, power_share
from . import stages
from .paths import data_dir, read_toml


def load_claims() -> list[dict]:
    """The claims of ``data/paper/claims.toml``, in order."""
    claims = read_toml(data_dir() / "paper" / "claims.toml")["claim"]
    tests = ("rel", "min", "max", "equal")
    for c in claims:
        if not any(t in c for t in tests):
            raise ValueError(f"claim {c.get('id')!r} has no test; give one of {tests}")
    return claims


def paper_value(claim_id: str, key: str = "paper") -> float:
    """A number the paper reports, from ``data/paper/claims.toml``: the claim's ``paper`` value or another key (``measured``).

    Raises
    ------
    KeyError
        No claim ``claim_id``, or it has no numeric ``key``.
    """
    for c in load_claims():
        if c["id"] == claim_id:
            value = c.get(key)
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise KeyError(f"claim {claim_id!r} has no number {key!r}")
            return float(value)
    raise KeyError(f"no claim {claim_id!r} in data/paper/claims.toml")


def judge(claim: dict, ours: float) -> bool:
    """Whether ``ours`` passes the claim's test (relative tolerance, bounds or equality)."""
    if not np.isfinite(ours):
        return False
    ok = True
    if "rel" in claim:
        ok &= abs(ours / float(claim["paper"]) - 1.0) <= claim["rel"]
    if "min" in claim:
        ok &= ours >= claim["min"]
    if "max" in claim:
        ok &= ours <= claim["max"]
    if claim.get("equal"):
        ok &= ours == float(claim["paper"])
    return bool(ok)


def tolerance_text(claim: dict) -> str:
    """The claim's test in words."""
    parts = []
    if "rel" in claim:
        parts.append(f"±{claim['rel']:.0%}")
    if "min" in claim:
        parts.append(f">= {claim['min']:g}")
    if "max" in claim:
        parts.append(f"<= {claim['max']:g}")
    if claim.get("equal"):
        parts.append("equal")
    return ", ".join(parts)


# ---------------------------------------------------------------- shared inputs, each computed once


@functools.cache
def _visco(road: str = "flat") -> FRFResult:
    return stages.frf_visco(PAPER_TIRE, road)


@functools.cache
def _cleat() -> CleatTest:
    return cleat_test(PAPER_TIRE)


@functools.cache
def _contact() -> OneSidedCleatTest:
    return one_sided_cleat_test(PAPER_TIRE)


def _two_peaks(distance: np.ndarray, force: np.ndarray, window: tuple[float, float] = (-np.inf, np.inf)) -> int:
    """Distinct peaks (prominence >= 10 % of the largest force) while the cleat passes."""
    return distinct_peaks(distance, force, window)


@functools.cache
def _quarter_car() -> QuarterCarTest:
    return quarter_car(PAPER_CAR)


def _hub_rms(texture: str) -> float:
    return band_rms(_quarter_car().spectra[texture]["a_hub"])


def _low_share(texture: str, output: str) -> float:
    return power_share(_quarter_car().spectra[texture][output], 0.0, 50.0)


def transmissibility_bands() -> dict[str, FrequencyBand]:
    """The paper's Fig. 10 claims as bands: ``claim id -> FrequencyBand`` (Hz, statistic of |T|, label)."""
    return {c["id"]: FrequencyBand(*c["band"], c["statistic"], c["label"]) for c in load_claims() if "band" in c}


@functools.cache
def _transmissibility_stats() -> dict[str, float]:
    return transmissibility_statistics(load_vehicle(PAPER_CAR), transmissibility_bands())


# ---------------------------------------------------------------- one evaluator per claim


def _first_vertical_resonance() -> float:
    v = _visco()
    return float(resonance_peaks(v.freqs, v.H_tot)[0][0])


def _superposition() -> float:
    v = _visco()
    return float(np.max(np.abs(v.H_sum - v.H_tot) / np.abs(v.H_tot)))


def _footprint_slip() -> float:
    v = _visco()
    keep = v.freqs <= 300
    sliding = stages.frf_visco(PAPER_TIRE, freqs=v.freqs[keep], stick=False)
    return float(band_errors(v.freqs[keep], v.H_tot[keep], sliding.H_tot)["complex rel. RMS"].max())


def _frozen_underestimates() -> float:
    reduced = stages.modal_reduction(PAPER_TIRE)
    v = _visco()
    peaks = peak_comparison(v.freqs, v.H_tot, reduced.frf.H_tot, f_max=260.0)
    above = peaks["reference (Hz)"] > reduced.reference_frequency + 5.0
    return float(peaks.loc[above, "shift (%)"].max())


def _paper_modal_errors() -> np.ndarray:
    v = _visco()
    paper = stages.modal_reduction(PAPER_TIRE, frozen="storage", damping="identified")
    return band_errors(v.freqs, v.H_tot, paper.frf.H_sum)["complex rel. RMS"].to_numpy()


def _eight_poles() -> float:
    v = _visco()
    return float(fit_tasselli(v.freqs, v.H, n_poles=8).rms_errors.max())


def _fig6_fit() -> float:
    static = stages.solve_static(PAPER_TIRE)
    centre = int(np.argmin(np.hypot(static.tasselli.centre_x, static.tasselli.centre_y)))
    return float(stages.fit_tasselli(PAPER_TIRE)[centre].rms_error)


def _moving_hub() -> float:
    check = moving_hub_check(CHECK_TIRE, freqs=np.arange(2.0, 251.0, 4.0))
    return check.errors()["hub force F_M"]


def _resolution() -> float:
    v = stages.frf_visco(CHECK_TIRE)
    k = int(np.argmin(np.abs(v.freqs - 100.0)))
    return float(tassellation_error(stages.solve_static(CHECK_TIRE), v.H_points[:, k], [0.05])[0])


def _fig14_modes() -> float:
    test = _quarter_car()
    f = np.arange(40.0, 221.0, 1.0)
    psd = test.setup.predicted(f, test.conditions.spectra()["rough"], test.conditions.speed)["a_hub"]
    return float(resonance_peaks(f, np.sqrt(psd), min_ratio=0.0)[0].size)


EVALUATORS: dict[str, Callable[[], float]] = {
    "fe_dof": lambda: float(stages.build_fet(PAPER_TIRE).n_dof),
    "n_tasselli": lambda: float(stages.solve_static(PAPER_TIRE).tasselli.n),
    "first_vertical_resonance": _first_vertical_resonance,
    "superposition": _superposition,
    "footprint_slip": _footprint_slip,
    "freezing_frequency": lambda: stages.modal_reduction(PAPER_TIRE).reference_frequency,
    "frozen_underestimates": _frozen_underestimates,
    "fig5_match": lambda: float(_paper_modal_errors()[0]),
    "fig5_degrades": lambda: float(_paper_modal_errors()[-1] / _paper_modal_errors()[0]),
    "eight_poles": _eight_poles,
    "fig6_fit": _fig6_fit,
    "cleat_two_peaks": lambda: float(
        _two_peaks(_cleat().quasi_static.result.distance, _cleat().quasi_static.result.force)
    ),
    "cleat_quasi_static": lambda: _cleat().quasi_static.peak_force,
    "cleat_dynamic": lambda: _cleat().dynamic.peak_force,
    "moving_hub": _moving_hub,
    "hub_poles": lambda: float(stages.fit_hub(CHECK_TIRE).n_poles),
    "resolution_5cm": _resolution,
    "fig10_low": lambda: _transmissibility_stats()["fig10_low"],
    "fig10_mid": lambda: _transmissibility_stats()["fig10_mid"],
    "fig10_high": lambda: _transmissibility_stats()["fig10_high"],
    "fig11_low_frequency": lambda: _low_share("rough", "a_hub"),
    "fig12_equalized": lambda: _low_share("rough", "a_mount"),
    "fig11_textures": lambda: _hub_rms("rough") / _hub_rms("smooth"),
    "fig14_modes": _fig14_modes,
    "contact_two_peaks": lambda: float(
        _two_peaks(_contact().dynamic.distance, _contact().dynamic.hub_force, (-0.15, 0.15))
    ),
    "contact_quasi_static": lambda: _contact().quasi_static.peak_force,
    "contact_dynamic": lambda: _contact().dynamic.peak_force,
    "contact_ratio": lambda: _contact().ratio,
    "contact_decay": lambda: float(_contact().decay["frequency (Hz)"].iloc[0]),
}


def _format(value: float) -> str:
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.2e}"


def report(
    notebook: str | None = None,
    claims: list[dict] | None = None,
    evaluators: dict[str, Callable[[], float]] | None = None,
) -> pd.DataFrame:
    """One row per claim: claim, where, paper, ours, tolerance, verdict, notebook, known deviation.

    ``notebook`` keeps the claims shown by one notebook; ``claims``/``evaluators`` replace the
    data file and the evaluators (tests).
    """
    claims = load_claims() if claims is None else claims
    evaluators = EVALUATORS if evaluators is None else evaluators
    rows = []
    for c in claims:
        if notebook is not None and c["notebook"] != notebook:
            continue
        if c["id"] not in evaluators:
            raise KeyError(f"no evaluator for claim {c['id']!r}")
        ours = float(evaluators[c["id"]]())
        passed = judge(c, ours)
        rows.append(
            {
                "id": c["id"],
                "claim": c["claim"],
                "where": c["where"],
                "paper": c["paper"] if isinstance(c["paper"], str) else _format(float(c["paper"])),
                "ours": _format(ours),
                "tolerance": tolerance_text(c),
                "verdict": "pass" if passed else "fail",
                "notebook": c["notebook"],
                "known deviation": "" if passed else c.get("known_deviation", ""),
            }
        )
    return pd.DataFrame(rows).set_index("id")


def unexpected_failures(table: pd.DataFrame) -> pd.DataFrame:
    """Failed claims that are not documented known deviations."""
    return table[(table["verdict"] == "fail") & (table["known deviation"] == "")]


def exit_status(table: pd.DataFrame) -> int:
    """0 when every claim passes or fails only as a documented deviation, else 1."""
    return int(len(unexpected_failures(table)) > 0)


def to_markdown(table: pd.DataFrame) -> str:
    """The report as a GitHub Markdown table (known deviations as footnotes)."""
    columns = ["claim", "where", "paper", "ours", "tolerance", "verdict", "notebook"]
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    notes = []
    for cid, row in table.iterrows():
        verdict = row["verdict"]
        if row["known deviation"]:
            notes.append(f"- **{cid}**: {row['known deviation']}")
            verdict = f"fail (known deviation: {cid})"
        cells = [row["claim"], row["where"], row["paper"], row["ours"], row["tolerance"], verdict, row["notebook"]]
        lines.append("| " + " | ".join(str(c).replace("|", "/") for c in cells) + " |")
    passed = int((table["verdict"] == "pass").sum())
    summary = (
        f"{passed} of {len(table)} claims reproduced; {len(table) - passed} not ({len(notes)} documented deviations)."
    )
    return "\n".join([summary, "", *lines, "", *(["Known deviations:", "", *notes] if notes else [])]) + "\n"


def write_report(table: pd.DataFrame, folder: Path) -> tuple[Path, Path]:
    """Write ``reproduction-report.csv`` and ``.md`` into ``folder``, each atomically; returns their paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    csv_path = folder / "reproduction-report.csv"
    md_path = folder / "reproduction-report.md"
    _write_atomically(csv_path, table.to_csv())
    _write_atomically(md_path, "# Reproduction report: Belluzzo et al. (2002)\n\n" + to_markdown(table))
    return csv_path, md_path


def _write_atomically(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def verdicts(table: pd.DataFrame) -> str:
    """One line per claim, ``id: pass`` or ``id: fail (documented deviation)``: stable printed output."""
    lines = []
    for cid, row in table.iterrows():
        note = " (documented deviation)" if row["verdict"] == "fail" and row["known deviation"] else ""
        lines.append(f"{cid}: {row['verdict']}{note}")
    return "\n".join(lines)


def check(table: pd.DataFrame) -> None:
    """Raise ``AssertionError`` naming every claim that fails without a documented deviation."""
    failures = unexpected_failures(table)
    if len(failures):
        raise AssertionError(
            "claims not reproduced: "
            + "; ".join(
                f"{cid} (paper {row['paper']}, ours {row['ours']}, {row['tolerance']})"
                for cid, row in failures.iterrows()
            )
        )
