"""Figures of notebook 12: the trade-offs of a design sweep (:func:`roadnoise_utils.experiments.sweep`).

The sweep's table holds SI units; this edge turns them into the units an NVH engineer reads
(N/mm, Hz, N, m/s^2) and labels each point with its design number.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import pandas as pd

#: SI column of a sweep table -> (axis label, factor to that label's unit).
LABELS = {
    "K_v (N/m)": ("vertical stiffness K_v (N/mm)", 1e-3),
    "f1 (Hz)": ("first vertical resonance f1 (Hz)", 1.0),
    "zeta1 (-)": ("damping ratio of the first mode zeta1 (-)", 1.0),
    "footprint_length (m)": ("footprint length (mm)", 1e3),
    "footprint_width (m)": ("footprint width (mm)", 1e3),
    "cleat_quasi_static_peak (N)": ("cleat peak, quasi-static, linear chain (N)", 1.0),
    "cleat_dynamic_peak (N)": ("cleat peak at 30 km/h, linear chain (N)", 1.0),
    "one_sided_quasi_static_peak (N)": ("cleat peak, quasi-static, one-sided contact (N)", 1.0),
    "one_sided_dynamic_peak (N)": ("cleat peak at 30 km/h, one-sided contact (N)", 1.0),
    "a_hub_rms (m/s^2)": ("hub acceleration RMS, 40-220 Hz (m/s²)", 1.0),
    "operating.inflation_pressure (Pa)": ("inflation pressure (bar)", 1e-5),
    "operating.vertical_load (N)": ("vertical load (N)", 1.0),
    "tread.normal_stiffness_per_area (N/m^3)": ("tread normal stiffness (N/mm^3)", 1e-9),
    "belt.bending_stiffness (N m^2)": ("belt bending stiffness EI (N m^2)", 1.0),
}


def label(column: str) -> tuple[str, float]:
    """Axis label and unit factor of a sweep column (the column itself, factor 1, when unlisted)."""
    return LABELS.get(column, (column, 1.0))


def in_paper_units(table: pd.DataFrame) -> pd.DataFrame:
    """The sweep's parameter and output columns converted to the units of :data:`LABELS`, relabelled."""
    columns = [c for c in table.columns if c not in ("warnings", "error")]
    return pd.DataFrame({label(c)[0]: table[c] * label(c)[1] for c in columns}, index=table.index)


def plot_trade_off(
    table: pd.DataFrame,
    x: str,
    y: str,
    colour: str,
    ax: plt.Axes | None = None,
    target: tuple[float, float] | None = None,
    target_label: str = "",
    baseline: pd.Series | None = None,
) -> plt.Axes:
    """``y`` against ``x`` over the designs, coloured by ``colour``, each point numbered.

    Parameters
    ----------
    table : pandas.DataFrame
        A sweep's table (SI columns).
    x, y, colour : str
        Its columns to plot.
    ax : matplotlib Axes, optional
        Where to draw (default a new figure).
    target : (float, float), optional
        A target range of ``x`` (SI), shaded and labelled ``target_label``.
    baseline : pandas.Series, optional
        The tire file as it is (a row with the same columns), circled.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 4.5))
    (xl, xs), (yl, ys), (cl, cs) = label(x), label(y), label(colour)
    if target is not None:
        ax.axvspan(target[0] * xs, target[1] * xs, color="tab:green", alpha=0.12, label=target_label)
    points = ax.scatter(table[x] * xs, table[y] * ys, c=table[colour] * cs, cmap="viridis", s=60, zorder=3)
    for k, (index, row) in enumerate(table.iterrows()):  # labels above and below in turn: neighbours do not overlap
        offset = (5, 4) if k % 2 == 0 else (5, -11)
        ax.annotate(str(index), (row[x] * xs, row[y] * ys), xytext=offset, textcoords="offset points", fontsize=8)
    if baseline is not None:
        ax.scatter(
            baseline[x] * xs, baseline[y] * ys, marker="o", s=220, facecolors="none", edgecolors="k", lw=1.5,
            zorder=4, label="the tire file as is",
        )  # fmt: skip
    plt.colorbar(points, ax=ax, label=cl)
    ax.set_xlabel(xl)
    ax.set_ylabel(yl)
    if target is not None or baseline is not None:
        ax.legend(loc="lower right", fontsize=8)
    return ax
