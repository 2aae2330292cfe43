"""Figures of notebooks 11 (the whole car: layout, corner and body spectra, wheelbase filtering, the axles' coherence) and 14 (its air cavity)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.patches import Rectangle

from ..vehicle.full_car import CORNERS

#: One colour per corner.
CORNER_COLOURS = dict(zip(CORNERS, ["tab:red", "tab:orange", "tab:blue", "tab:cyan"]))


def plot_car_layout(car, tracks: np.ndarray | None = None) -> plt.Figure:
    """Top view: the body's centre of mass, the four wheels at their positions, and the road tracks they run on."""
    fig, ax = plt.subplots(figsize=(7, 3.6))
    positions = car.positions
    for corner, (x, y) in zip(CORNERS, positions):
        ax.add_patch(Rectangle((x - 0.3, y - 0.1), 0.6, 0.2, fc=CORNER_COLOURS[corner], alpha=0.6, ec="k"))
        ax.text(x, y + (0.18 if y > 0 else -0.18), corner, ha="center", va="center", fontsize=9)
    ax.plot([positions[:, 0].min(), positions[:, 0].max()], [0, 0], "k:", lw=0.8)
    ax.plot(0, 0, "k+", ms=12, mew=2)
    ax.text(0.05, 0.06, f"centre of mass\n{car.body.mass:g} kg", fontsize=8)
    if tracks is not None:
        for y in tracks:
            ax.axhline(y, color="tab:brown", lw=0.3, alpha=0.6)
    ax.annotate("", (positions[0, 0], -1.12), (positions[2, 0], -1.12), arrowprops={"arrowstyle": "<->"})
    ax.text(0.5 * (positions[0, 0] + positions[2, 0]), -1.2, f"wheelbase {car.wheelbase:g} m", ha="center", va="top")
    ax.annotate(
        "",
        (positions[0, 0] + 0.45, positions[0, 1]),
        (positions[0, 0] + 0.45, positions[1, 1]),
        arrowprops={"arrowstyle": "<->"},
    )
    ax.text(positions[0, 0] + 0.5, 0.0, f"track\n{car.track_front:g} m", va="center", fontsize=8)
    ax.text(
        positions[:, 0].min() - 0.1,
        0.0,
        "rear: the front's road\na wheelbase later",
        ha="right",
        va="center",
        fontsize=8,
    )
    ax.set_xlim(positions[:, 0].min() - 1.4, positions[:, 0].max() + 1.2)
    ax.set_ylim(-1.5, 1.1)
    ax.set_aspect("equal")
    ax.set_xlabel("x forward (m)")
    ax.set_ylabel("y left (m)")
    ax.set_title(f"{car.name}: top view, the road tracks of the belt strips in brown")
    return fig


def plot_corner_spectra(
    freqs: np.ndarray,
    psd: dict[str, np.ndarray],
    quantity: str,
    f_range: tuple[float, float],
    ax: plt.Axes | None = None,
) -> plt.Axes:
    """The amplitude spectral density of ``quantity`` (``a_hub``, ``a_mount``) at every corner."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    keep = (freqs >= f_range[0]) & (freqs <= f_range[1])
    for corner in CORNERS:
        ax.semilogy(
            freqs[keep], np.sqrt(psd[f"{quantity}_{corner}"][keep]), color=CORNER_COLOURS[corner], lw=1.0, label=corner
        )
    ax.set_xlim(*f_range)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel(f"{quantity} ASD ((m/s²)/√Hz)")
    ax.legend(ncol=4)
    return ax


def plot_body_spectra(freqs: np.ndarray, psd: dict[str, np.ndarray], f_range: tuple[float, float]) -> plt.Figure:
    """Heave acceleration (m/s²) and pitch and roll accelerations (rad/s²) of the body."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
    keep = (freqs >= f_range[0]) & (freqs <= f_range[1])
    left.semilogy(freqs[keep], np.sqrt(psd["a_heave"][keep]), color="k", lw=1.0, label="heave")
    left.set_ylabel("heave acceleration ASD ((m/s²)/√Hz)")
    for name, colour in (("a_pitch", "tab:purple"), ("a_roll", "tab:green")):
        right.semilogy(freqs[keep], np.sqrt(psd[name][keep]), color=colour, lw=1.0, label=name[2:])
    right.set_ylabel("angular acceleration ASD ((rad/s²)/√Hz)")
    for ax in (left, right):
        ax.set_xlim(*f_range)
        ax.set_xlabel("Frequency (Hz)")
        ax.legend()
    return fig


def plot_wheelbase_filtering(check, notches: dict[str, np.ndarray], f_range: tuple[float, float]) -> plt.Figure:
    """Heave and pitch on a 2-D road: the time-domain Welch estimate, the frequency domain, and the
    closed-form notches of a car symmetric front to rear (:math:`kV/L` pitch, :math:`(k + 1/2) V/L` heave)."""
    run = check.run
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for ax, name, label in zip(axes, ("a_heave", "a_pitch"), ("heave", "pitch")):
        f = run.spectra.freqs
        keep = (f >= f_range[0]) & (f <= f_range[1])
        ax.semilogy(
            f[keep], np.sqrt(run.spectra.psd[name][keep]), color="tab:blue", lw=1.0, label="time domain (Welch)"
        )
        fp = check.freqs
        k = (fp >= f_range[0]) & (fp <= f_range[1])
        ax.semilogy(fp[k], np.sqrt(check.predicted[name][k]), "k--", lw=0.8, label="frequency domain (Eq. 8, delay)")
        for j, f_notch in enumerate(notches[label]):
            ax.axvline(f_notch, color="tab:red", lw=0.6, alpha=0.5, label="symmetric car's notches" if j == 0 else None)
        unit = "(m/s²)/√Hz" if name == "a_heave" else "(rad/s²)/√Hz"
        ax.set_ylabel(f"{label} ASD ({unit})")
    axes[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))  # outside: the notches span the axes
    axes[-1].set_xlim(*f_range)
    axes[-1].set_xlabel("Frequency (Hz)")
    fig.suptitle(
        f"Wheelbase filtering at {check.speed * 3.6:.0f} km/h: notches V/L = {check.speed / check.wheelbase:.1f} Hz apart"
    )
    return fig


def plot_axle_coherence(check) -> plt.Axes:
    """Coherence of the front axle's left and right road forces: estimated, predicted, and the road's own at the track."""
    _, ax = plt.subplots(figsize=(8, 3.8))
    ax.plot(check.freqs, check.estimated, color="tab:blue", lw=1.0, marker=".", label="time domain (Welch estimate)")
    ax.plot(check.freqs, check.predicted, "k--", lw=1.0, label="road forces, frequency domain")
    low, high = check.predicted - 2 * check.deviation, check.predicted + 2 * check.deviation
    ax.fill_between(check.freqs, low, high, color="0.5", alpha=0.2, label="± 2 standard deviations of the estimate")
    ax.plot(check.freqs, check.road, color="tab:brown", lw=2.0, alpha=0.4, label="road tracks a track width apart")
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("coherence γ² (-)")
    ax.set_ylim(0, 1.02)
    ax.legend()
    return ax


def plot_cavity_split(tables, measured: tuple[float, float], rated_load: float) -> plt.Figure:
    """The loaded cavity's fore-aft and vertical modes against the load, and their split with the
    measured range of passenger tires at rated load drawn in; ``tables`` one
    :func:`.experiments.cavity.split_against_load` table or several by label (one line style each)."""
    tables = {"": tables} if isinstance(tables, pd.DataFrame) else dict(tables)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
    for (label, table), style in zip(tables.items(), ("-", "-.", ":")):
        tag = f", {label}" if label else ""
        load = table["load (N)"]
        left.plot(load, table["vertical (Hz)"], "o" + style, color="tab:red", label=f"vertical (even){tag}")
        left.plot(load, table["fore-aft (Hz)"], "s" + style, color="tab:blue", label=f"fore-aft (odd){tag}")
        right.plot(load, table["split (Hz)"], "o" + style, color="k", label=f"Webster, loaded section{tag}")
        right.plot(load, table["first-order split (Hz)"], style, color="0.6", label=f"first-order formula{tag}")
    left.set_ylabel("cavity mode (Hz)")
    right.errorbar([rated_load], [0.5 * sum(measured)], yerr=[[0.5 * (measured[1] - measured[0])]], fmt="none",
                   ecolor="tab:green", elinewidth=6, alpha=0.5, label="measured at rated load (Choi & Bolton 2020)")  # fmt: skip
    right.set_ylabel("split (Hz)")
    for ax in (left, right):
        ax.set_xlabel("load (N)")
    low, high = left.get_ylim()
    left.set_ylim(low - 0.45 * (high - low), high)  # room under the lines for the legend
    left.legend(fontsize=7, loc="lower left")
    right.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0))  # outside: it covers nothing
    return fig


def plot_cavity_frfs(result) -> plt.Figure:
    """The moduli :math:`|H_{tot}|` and :math:`|G_H|` of the fixed-hub tire without and with its air cavity, the loaded doublet marked."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharex=True)
    f = result.plain.freqs
    for ax, name, label in zip(axes, ("H_tot", "G_H"), ("|H_tot| (N/mm)", "|G_H| (N/mm)")):
        plain, coupled = np.abs(getattr(result.plain, name)) / 1e3, np.abs(getattr(result.with_cavity, name)) / 1e3
        ax.semilogy(f, plain, color="0.4", lw=1.0, label="without the cavity (the paper's model)")
        ax.semilogy(f, coupled, color="tab:red", lw=1.2, label="with the cavity")
        for k, f_mode in enumerate(result.loaded_doublet):
            ax.axvline(
                f_mode, color="tab:blue", ls=":", lw=0.8, label="loaded cavity: fore-aft, vertical" if k == 0 else None
            )
        ax.set_ylabel(label)
        ax.set_xlabel("Frequency (Hz)")
    axes[0].legend(fontsize=8)
    return fig


def plot_hub_and_heave(
    freqs: np.ndarray,
    by_label: dict[str, dict[str, np.ndarray]],
    colours: tuple[str, ...],
    f_range: tuple[float, float],
    styles: tuple[str, ...] | None = None,
) -> plt.Figure:
    """Front-left hub and body heave ASDs of a few predicted cases (e.g. two tire models, cavity off and on).

    ``styles``: a line style per case (default solid), e.g. dashed for a case that may lie on another.
    """
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    for (label, psd), colour, style in zip(by_label.items(), colours, styles or ("-",) * len(by_label)):
        left.semilogy(freqs, np.sqrt(psd["a_hub_FL"]), color=colour, ls=style, lw=1.0, label=label)
        right.semilogy(freqs, np.sqrt(psd["a_heave"]), color=colour, ls=style, lw=1.0, label=label)
    left.set_ylabel("front-left hub ASD ((m/s²)/√Hz)")
    right.set_ylabel("heave ASD ((m/s²)/√Hz)")
    for ax in (left, right):
        ax.set_xlabel("Frequency (Hz)")
        ax.set_xlim(*f_range)
        ax.legend()
    return fig


def plot_rolling_cavity(result) -> plt.Figure:
    """The moduli :math:`|H_{tot}|` and :math:`|G_H|` of the fixed-hub tire with its rolling cavity at each speed, the waveguide's rolling
    doublet of each speed marked in its colour (``result``: :class:`.experiments.cavity.RollingCavityFRFs`)."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharex=True)
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, len(result.speeds_kmh)))
    for ax, values, label in zip(axes, (result.H_tot, result.G_H), ("|H_tot| (N/mm)", "|G_H| (N/mm)")):
        for speed, response, doublet, colour in zip(result.speeds_kmh, values, result.doublets, colours):
            ax.semilogy(result.freqs, np.abs(response) / 1e3, color=colour, lw=1.2, label=f"{speed:.0f} km/h")
            for f_mode in doublet:
                ax.axvline(f_mode, color=colour, ls=":", lw=0.9)
        ax.set_ylabel(label)
        ax.set_xlabel("Frequency (Hz)")
    axes[1].legend(
        fontsize=8,
        title="dotted: the waveguide's doublet",
        title_fontsize=8,
        loc="upper left",
        bbox_to_anchor=(1.01, 1.0),
    )  # outside: the doublet lines span the axes
    return fig
