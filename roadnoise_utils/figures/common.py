"""Helpers shared by the chapters' figure modules: units at the plotting edge, the tassello map, paper values."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Rectangle

from ..tire.model import Footprint

MM = 1e3  # m -> mm


def plot_tassello_map(
    static: Footprint,
    values: np.ndarray,
    label: str,
    ax: plt.Axes | None = None,
    cmap: str = "RdBu_r",
    symmetric: bool = True,
) -> plt.Axes:
    """A value per tassello drawn on the footprint (e.g. the static influence H_i(0))."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    t = static.tasselli
    vmax = np.max(np.abs(values))
    norm = plt.Normalize(-vmax if symmetric else np.min(values), vmax)
    cm = plt.get_cmap(cmap)
    for (x0, x1, y0, y1), v in zip(t.bounds, values):
        ax.add_patch(Rectangle((x0 * MM, y0 * MM), (x1 - x0) * MM, (y1 - y0) * MM, fc=cm(norm(v)), ec="w", lw=0.6))
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cm), ax=ax, label=label, shrink=0.8)
    ax.set_xlim(t.bounds[:, 0].min() * MM - 5, t.bounds[:, 1].max() * MM + 5)
    ax.set_ylim(t.bounds[:, 2].min() * MM - 5, t.bounds[:, 3].max() * MM + 5)
    ax.set_aspect("equal")
    ax.grid(False)
    ax.set_xlabel("x (mm), direction of travel →")
    ax.set_ylabel("y (mm)")
    return ax


def paper_lines(
    ax: plt.Axes, values: dict[str, float], axis: str = "y", scale: float = 1.0, unit: str = ""
) -> plt.Axes:
    """Reference lines at the paper's numbers, labelled with their source, so a deviation shows at a glance.

    Parameters
    ----------
    ax : matplotlib Axes
        Where to draw.
    values : dict of str to float
        Label (say where the number comes from) -> value, in SI units.
    axis : {"y", "x"}
        Horizontal lines at y values (forces) or vertical lines at x values (frequencies).
    scale : float
        Factor from SI to the axis' unit (e.g. 1e-3 for N/m -> N/mm).
    unit : str
        The axis' unit; the label then ends with the value, e.g. "= 850 N".

    Horizontal lines get headroom above the highest of them and the data, where the legend
    goes: a line across the whole axes never runs through its text.
    """
    colours = ["tab:purple", "tab:brown", "tab:olive", "tab:cyan"]
    for (label, value), colour in zip(values.items(), colours):
        line = ax.axhline if axis == "y" else ax.axvline
        shown = f"{label} = {value * scale:.4g} {unit}" if unit else label
        line(value * scale, color=colour, ls=(0, (6, 3)), lw=1.1, label=shown)
    if axis == "y":
        bottom, top = ax.dataLim.y0, ax.dataLim.y1  # the curves and the lines (not the limits: panels may share them)
        entries = len(ax.get_legend_handles_labels()[0])
        ax.set_ylim(bottom - 0.05 * (top - bottom), top + (0.1 + 0.05 * entries) * (top - bottom))
        ax.legend(fontsize=8, loc="upper right")
    else:
        ax.legend(fontsize=8)
    return ax
