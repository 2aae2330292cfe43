"""Figures of notebook 08-contact-loss-cleat-test: one-sided contact against the linear chain and the measurement."""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib.pyplot as plt
import pandas as pd

from .common import paper_lines

if TYPE_CHECKING:
    from ..experiments.cleat import CleatRun
    from ..tire.contact import ContactRun


def plot_contact_runs(
    contact: dict[str, ContactRun],
    linear: dict[str, CleatRun],
    ax: plt.Axes | None = None,
    title: str = "",
    paper: dict[str, float] | None = None,
    raw: dict[str, ContactRun] | None = None,
    x_range: tuple[float, float] | None = None,
) -> plt.Axes:
    """Fig. 8 analogue: hub force vs distance, one-sided contact (solid, its peak marked) and the
    linear chain (dashed).

    ``paper``: the measured values (label -> N), drawn as reference lines; ``raw``: runs as stepped
    (before the band limit), thin and grey behind the others; ``x_range``: the distance shown (m).
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.5))
    for label, run in (raw or {}).items():
        ax.plot(run.distance, run.hub_force, color="0.7", lw=0.4, zorder=0, label=label)
    colours = ["tab:blue", "tab:red", "tab:green", "tab:orange"]
    for (label, run), colour in zip(contact.items(), colours):
        ax.plot(run.distance, run.hub_force, "-", color=colour, lw=1.6, label=label)
        peak = int(run.hub_force.argmax())
        ax.plot(run.distance[peak], run.hub_force[peak], "o", ms=5, color=colour)
    for (label, run), colour in zip(linear.items(), colours):
        r = run.result
        ax.plot(r.distance, r.force, "--", color=colour, lw=1.0, alpha=0.8, label=label)
    ax.axhline(0, color="0.5", lw=0.6)
    ax.set_xlabel("distance travelled (m); 0 = cleat leading edge under the axle")
    ax.set_ylabel("hub force minus the static load (N)")
    ax.set_title(title)
    if x_range is not None:
        ax.set_xlim(*x_range)
    ax.legend(fontsize=8)
    if paper:
        paper_lines(ax, paper, unit="N")
    return ax


def plot_contact_points(runs: dict[str, ContactRun], static_points: int, ax: plt.Axes | None = None) -> plt.Axes:
    """Tread points in contact against distance: where the tread lifts off the drum."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 3.2))
    for label, run in runs.items():
        ax.plot(run.distance, run.contact_points, lw=1.3, label=label)
    ax.axhline(static_points, color="0.4", ls=":", lw=1.0, label=f"static footprint ({static_points} points)")
    ax.set_xlabel("distance travelled (m)")
    ax.set_ylabel("tread points in contact")
    ax.legend(fontsize=8)
    ax.set_title("Tread points in contact with the drum while the cleat passes")
    return ax


def plot_speed_sweep(
    sweep: pd.DataFrame, paper: dict[str, float] | None = None, ax: plt.Axes | None = None
) -> plt.Axes:
    """Peak hub force against speed: linear chain and one-sided contact."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    speeds = sweep.index.to_numpy(float)
    ax.plot(speeds, sweep["one-sided contact (N)"], "o-", label="one-sided contact (FE tire, time stepping)")
    ax.plot(speeds, sweep["linear chain (N)"], "s--", label="linear RM chain (the paper's method)")
    ax.set_xlabel("speed (km/h)")
    ax.set_ylabel("peak hub force (N)")
    ax.legend(fontsize=8)
    if paper:
        paper_lines(ax, paper, unit="N")
    return ax
