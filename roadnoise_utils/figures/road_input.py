"""Figures of notebook 06-road-input: road spectra, 3D tracks, tassello inputs, the footprint's wavelength filter."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..tire.model import Footprint
from .common import MM


def plot_road_spectra(
    spectra: dict,
    n: np.ndarray,
    iso_classes: dict[str, float],
    ax: plt.Axes | None = None,
    measured: dict | None = None,
    title: str = "Road spectra: targets (light), generated profiles (Welch) and the ISO 8608 classes (grey)",
) -> plt.Axes:
    """Road displacement PSDs (m^3) vs wavenumber with the ISO 8608 class boundaries; each generated
    profile's estimate drawn over its (light, wide) target so a seed's scatter shows."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4.5))
    for name, g0 in iso_classes.items():
        ax.loglog(n, g0 * (n / 0.1) ** -2.0, color="0.8", lw=0.8)
        ax.text(n[0] * 1.05, g0 * (n[0] / 0.1) ** -2.0, name, fontsize=7, color="0.5", va="bottom")
    floor = np.inf
    for (name, spectrum), colour in zip(spectra.items(), ["tab:red", "tab:blue", "tab:green"]):
        target = spectrum.psd(n)
        floor = min(floor, target[target > 0].min())
        ax.loglog(n, target, lw=4, color=colour, alpha=0.3, label=f"{name} (target)")
        if measured and name in measured:
            nm, gm = measured[name]
            shown = (nm > 0) & (nm <= n.max())
            ax.loglog(nm[shown], gm[shown], lw=0.9, color=colour, label=f"{name} (generated, Welch)")
    # the targets' band sets the scale, not the estimate's leakage past the shortest wavelength
    top = max(iso_classes.values()) * (n[0] / 0.1) ** -2.0
    ax.set_ylim(floor / 100.0, top * 10.0)
    ax.axvline(1 / 0.05, color="k", ls=":", lw=0.8)
    ax.text(1 / 0.05, ax.get_ylim()[1], " 5 cm", va="top", fontsize=8)
    ax.set_xlabel("wavenumber n (cycles/m)")
    ax.set_ylabel("displacement PSD G(n) (m³)")
    ax.set_title(title)
    ax.legend(fontsize=7)
    return ax


def plot_tracks(profile, length: float, ax: plt.Axes | None = None) -> plt.Axes:
    """The first ``length`` m of a 3D road: one track per belt strip, as an image."""
    if ax is None:
        _, ax = plt.subplots(figsize=(10, 2.6))
    keep = profile.s <= length
    im = ax.pcolormesh(profile.s[keep], profile.y * MM, profile.z[:, keep] * MM, shading="nearest", cmap="terrain")
    plt.colorbar(im, ax=ax, label="height (mm)")
    ax.set_xlabel("road coordinate s (m)")
    ax.set_ylabel("track y (mm)")
    ax.grid(False)
    return ax


def plot_row_inputs(roads: dict, static: Footprint, row: int = 0, samples: int = 1000) -> plt.Figure:
    """Displacement histories of every tassello of one row, one panel per road (``title -> RoadInput``).

    On a 2D road every column of the row sees the same track (the curves differ only by the
    tasselli's positions along the road); on a 3D road each column has its own.
    """
    members = np.nonzero(static.tasselli.row == row)[0]
    fig, axes = plt.subplots(1, len(roads), figsize=(6 * len(roads), 3.5), sharey=True, squeeze=False)
    for ax, (title, road) in zip(axes[0], roads.items(), strict=True):
        for i in members:
            ax.plot(road.t[:samples] * 1e3, road.u[i, :samples] * MM, lw=0.8)
        ax.set_title(f"{title} (row {row + 1})")
        ax.set_xlabel("time (ms)")
    axes[0, 0].set_ylabel("tassello displacement (mm)")
    return fig


def plot_kernel_filter(
    wavelengths: np.ndarray, gains: np.ndarray, labels: list[str], ax: plt.Axes | None = None
) -> plt.Axes:
    """The kernel gain :math:`|K_i(1/\\lambda)|`: how much of a sinusoidal road of wavelength λ reaches each tassello."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for g, label in zip(gains, labels):
        ax.semilogx(wavelengths * 100, np.abs(g), label=label)
    ax.axvline(5.0, color="k", ls=":", lw=0.8)
    ax.text(5.0, 1.02, " 5 cm", fontsize=8)
    ax.set_xlabel("road wavelength λ (cm)")
    ax.set_ylabel("|tassello input / road amplitude|")
    ax.set_ylim(0, 1.1)
    ax.legend(fontsize=7)
    return ax
