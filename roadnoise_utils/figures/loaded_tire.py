"""Figures of notebook 16-loaded-fe-tire: the loaded shape beside the round tire, curves against load, the modal reduction."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from ..tire.loaded.statics import LoadedTire, StaticState
from ..tire.model import FRFResult
from .common import MM


def centre_line(tire: LoadedTire, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fore-aft and vertical position (m) of the tread's centre line displaced by ``u``, round the wheel in order."""
    mesh = tire.mesh
    section = mesh.section
    centre = section.node(section.n_stations // 2, section.n_rows - 1)
    rings = np.argsort(mesh.theta)
    nodes = mesh.node(rings, centre)
    position = mesh.coordinates[nodes] + u.reshape(-1, 3)[nodes]
    return position[:, 0], position[:, 2]


def plot_loaded_side_view(
    tire: LoadedTire, state: StaticState, window: float = 0.2, ax: plt.Axes | None = None
) -> plt.Axes:
    """The tread's centre line at the bottom of the wheel: round (mounted, unloaded), loaded, and the road,
    with a marker at every ring of nodes (the mesh's grading along the wheel); ``window`` (m) either side."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.5))
    x0, z0 = centre_line(tire, np.zeros(tire.n_dof))
    x, z = centre_line(tire, state.u)
    near = (np.abs(x0) < window) & (z0 < 0.0)  # the bottom of the wheel, where the road is
    ax.plot(x0[near] * MM, z0[near] * MM, "--", color="0.5", label="round tire (mounted, unloaded)")
    ax.plot(x[near] * MM, z[near] * MM, "o-", ms=3, color="tab:blue", label="loaded (a marker per ring of nodes)")
    ax.axhline(state.road_top * MM, color="k", lw=1.0, label=f"road: {state.road.kind}, {state.road_force:.0f} N")
    ax.set_xlabel("x (mm), direction of travel →")
    ax.set_ylabel("z (mm)")
    ax.set_title(f"the tread's centre line: {state.contact.size} tread nodes held on the road")
    ax.legend(fontsize=8, loc="upper right")
    return ax


def plot_against_load(
    table: pd.DataFrame,
    column: str,
    ax: plt.Axes | None = None,
    target: tuple[float, float, str] | None = None,
    nominal: float | None = None,
) -> plt.Axes:
    """One curve per model of ``column`` against load (:func:`~roadnoise_utils.experiments.loaded_tire.load_curves`);
    ``target`` = (low, high, source) drawn as a band at the ``nominal`` load (N)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 4))
    for model, rows in table.groupby("model", sort=False):
        ax.plot(rows["load (kN)"], rows[column], "o-", label=model)
    if target is not None and nominal is not None:
        low, high, source = target
        ax.errorbar(
            nominal / 1e3, (low + high) / 2, yerr=(high - low) / 2, fmt="none", ecolor="tab:purple",
            capsize=6, lw=2, label=f"target at {nominal / 1e3:.2f} kN: {source}",
        )  # fmt: skip
    ax.set_xlabel("vertical load (kN)")
    ax.set_ylabel(column)
    ax.legend(fontsize=7)
    return ax


def plot_split_against_load(
    splits: pd.DataFrame, measured: tuple[float, float, str], ax: plt.Axes | None = None
) -> plt.Axes:
    """The cavity's split against load per model, log-log, with the measured growth's exponents
    ``measured`` = (lowest, highest, source) drawn as slopes from the lightest load's smallest split."""
    ax = plot_against_load(splits, "split (Hz)", ax)
    ax.set_xscale("log")
    ax.set_yscale("log")
    loads = np.array([splits["load (kN)"].min(), splits["load (kN)"].max()])
    start = splits.loc[splits["load (kN)"] == loads[0], "split (Hz)"].min()
    low, high, source = measured
    for k, style in ((low, ":"), (high, "--")):
        ax.plot(loads, start * (loads / loads[0]) ** k, style, color="tab:purple", lw=1.1,
                label=f"measured growth, load^{k:g} ({source})")  # fmt: skip
    ax.set_xticks(np.unique(splits["load (kN)"]))
    ax.set_ylim(0.8 * splits["split (Hz)"].min(), 1.6 * splits["split (Hz)"].max())  # the steep slope leaves the frame
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(plt.ScalarFormatter())
        axis.set_minor_formatter(plt.NullFormatter())
    ax.legend(fontsize=7)
    ax.set_title("the loaded cavity's first doublet: vertical minus fore-aft frequency")
    return ax


def plot_modal_variants(direct: FRFResult, reductions: dict, f_max: float = 250.0) -> plt.Figure:
    """Fig. 5 analogue: the direct :math:`H_{tot}` (modulus, N/mm, and phase, deg) and each modal reduction's."""
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    styles = ["--", ":", "-."]
    keep = direct.freqs <= f_max
    top.plot(direct.freqs[keep], np.abs(direct.H_tot[keep]) / 1e3, "k-", label="direct (loaded, linearised)")
    bottom.plot(direct.freqs[keep], np.degrees(np.angle(direct.H_tot[keep])), "k-")
    for (label, reduction), style in zip(reductions.items(), styles, strict=False):
        frf = reduction.frf
        inside = frf.freqs <= f_max
        top.plot(frf.freqs[inside], np.abs(frf.H_tot[inside]) / 1e3, style, label=label)
        bottom.plot(frf.freqs[inside], np.degrees(np.angle(frf.H_tot[inside])), style)
    top.set_ylabel("|H_tot| (N/mm)")
    bottom.set_ylabel("phase (deg)")
    bottom.set_xlabel("Frequency (Hz)")
    bottom.set_xlim(0, f_max)
    top.legend(fontsize=8)
    return fig
