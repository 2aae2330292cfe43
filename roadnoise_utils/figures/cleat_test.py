"""Figures of notebook 04-cleat-test: the cleat runs (Fig. 8-9), the tassello inputs, the row influences."""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from ..tire.model import Footprint
from .common import MM, paper_lines

if TYPE_CHECKING:
    from ..experiments.cleat import CleatRun


def plot_cleat_runs(
    runs: dict[str, CleatRun], ax: plt.Axes | None = None, title: str = "", paper: dict[str, float] | None = None
) -> plt.Axes:
    """Fig. 8/9 analogue: hub force vs distance travelled, several runs, peaks marked.

    ``paper``: the paper's peak forces (label -> N), drawn as reference lines
    (:func:`.common.paper_lines`).
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.5))
    for (label, run), style in zip(runs.items(), ["--", "-", ":", "-."]):
        r = run.result
        ax.plot(r.distance, r.force, style, lw=1.4, label=label)
        ax.plot(run.peaks["distance (m)"], run.peaks["force (N)"], "o", ms=4, color=ax.lines[-1].get_color())
    ax.axhline(0, color="0.5", lw=0.6)
    ax.set_xlabel("distance travelled (m); 0 = cleat leading edge under the axle")
    ax.set_ylabel("hub force (N)")
    ax.set_title(title)
    ax.legend()
    if paper:
        paper_lines(ax, paper, unit="N")
    return ax


def plot_tassello_inputs(road, static: Footprint, rows: list[int], ax: plt.Axes | None = None) -> plt.Axes:
    """Displacement histories of the centre-column tassello of some rows (the road flowing through)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 3.5))
    t = static.tasselli
    centre_column = int(np.median(t.column))
    for r in rows:
        i = np.nonzero((t.row == r) & (t.column == centre_column))[0]
        if i.size:
            ax.plot(road.distance, road.u[i[0]] * MM, label=f"tassello {i[0] + 1} (row {r + 1})")
    ax.set_xlabel("distance travelled (m)")
    ax.set_ylabel("tassello displacement (mm)")
    ax.legend(fontsize=7)
    ax.set_title("Tassello displacements: the road flowing through the footprint")
    return ax


def plot_row_influence(rows: pd.DataFrame, static: Footprint, base: float, ax: plt.Axes | None = None) -> plt.Axes:
    """Static influence of each row along the footprint, with the cleat drawn at the two peak positions."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.8))
    ax.bar(
        rows["x centre (mm)"],
        rows["H(0) of the row (N/mm)"],
        width=0.9 * rows["length (mm)"],
        color="tab:blue",
        alpha=0.7,
        label="H(0) of each row of tasselli",
    )
    ax.set_xlabel("x along the footprint (mm); the cleat enters on the left")
    ax.set_ylabel("static influence (N/mm)")
    ax.invert_xaxis()
    ax.legend()
    return ax
