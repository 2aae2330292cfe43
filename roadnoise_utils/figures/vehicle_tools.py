"""Figures of notebook 15-tire-in-your-vehicle-tool: the FMU against our simulation, and the co-simulated car."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from ..vehicle.spectra import OCTAVE_CENTRES


def plot_fmu_against_ours(
    t: np.ndarray, ours: np.ndarray, fmu: np.ndarray, label: str, ax: plt.Axes | None = None
) -> plt.Axes:
    """A force history from our simulation (bold) and from the FMU (dashed), their difference on a second axis."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 3.6))
    ax.plot(t * 1e3, ours, "k", lw=2.2, label=f"{label}: ours (ru.simulate / road_hub_force)")
    ax.plot(t * 1e3, fmu, "--", color="tab:orange", lw=1.3, label=f"{label}: the FMU, driven by fmpy")
    ax.set_xlabel("Time (ms)")
    ax.set_ylabel("Force on the hub (N)")
    twin = ax.twinx()
    twin.plot(t * 1e3, fmu - ours, color="tab:red", lw=0.8, label="FMU - ours")
    twin.set_ylabel("FMU - ours (N)", color="tab:red")
    twin.ticklabel_format(axis="y", style="sci", scilimits=(0, 0))
    lines = ax.get_legend_handles_labels()[0] + twin.get_legend_handles_labels()[0]
    labels = ax.get_legend_handles_labels()[1] + twin.get_legend_handles_labels()[1]
    ax.legend(lines, labels, loc="upper right", fontsize=8)
    return ax


def plot_cosimulated_car(
    ours: tuple[np.ndarray, np.ndarray], cosimulated: tuple[np.ndarray, np.ndarray], octaves: pd.DataFrame, output: str
) -> plt.Figure:
    """The ASD of one car output, ours and co-simulated with the FMU, and the per-octave RMS ratio of every output."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4), gridspec_kw={"width_ratios": [1.6, 1]})
    band = (ours[0] >= 2.0) & (ours[0] <= 250.0)
    left.semilogy(ours[0][band], np.sqrt(ours[1][band]), "k", lw=2.2, label="ours: ru.experiments.quarter_car")
    left.semilogy(cosimulated[0][band], np.sqrt(cosimulated[1][band]), "--", color="tab:orange", lw=1.3,
                  label="the tire FMU co-simulated with the quarter car")  # fmt: skip
    left.set_xlabel("Frequency (Hz)")
    left.set_ylabel(f"ASD of {output} (m/s² / √Hz)")
    left.legend(fontsize=8)
    names = list(dict.fromkeys(octaves["output"]))
    width = 0.8 / len(names)
    positions = np.arange(len(OCTAVE_CENTRES))
    for k, name in enumerate(names):
        ratios = octaves[octaves["output"] == name]["ratio - 1"].to_numpy() * 100
        right.bar(positions + (k - (len(names) - 1) / 2) * width, ratios, width, label=name)
    right.axhspan(-1.0, 1.0, color="0.9", zorder=0, label="± 1 %")
    right.set_xticks(positions, [f"{c:g}" for c in OCTAVE_CENTRES])
    right.set_xlabel("Octave band centre (Hz)")
    right.set_ylabel("co-simulated / ours - 1 (%), RMS per octave")
    right.legend(fontsize=8)
    return fig
