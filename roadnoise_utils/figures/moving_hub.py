"""Figures of notebook 05-moving-hub: the moving-hub scheme (Fig. 7) and FRF pairs."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Circle


def plot_moving_hub_scheme() -> plt.Figure:
    """Fig. 7 analogue: the force on the moving hub as fixed-hub road force plus hub-motion force."""
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.2))
    titles = [
        "moving hub, road input\nF_M",
        "fixed hub, road input\nF_F = Σ_i G_i u_i",
        "moving hub, no road input\nF_H = G_H u_H",
    ]
    for ax, title, hub_moves, road_moves in zip(axes, titles, [True, False, True], [True, True, False]):
        ax.set_xlim(-1.3, 1.3)
        ax.set_ylim(-1.45, 1.3)
        ax.set_aspect("equal")
        ax.axis("off")
        ax.add_patch(Circle((0, 0.1), 1.0, fill=False, lw=2))
        ax.add_patch(Circle((0, 0.1), 0.35, fc="0.8", ec="k"))
        ax.plot([-1.2, 1.2], [-0.92, -0.92], color="tab:brown", lw=3)
        if hub_moves:
            ax.annotate("", (0, 0.75), (0, 0.1), arrowprops={"arrowstyle": "<->", "color": "tab:red", "lw": 1.5})
            ax.text(0.12, 0.55, "u_H", color="tab:red")
        else:
            ax.plot([-0.2, 0.2], [0.1, 0.1], "k", lw=4)
            ax.text(0.42, 0.1, "fixed", va="center", fontsize=8)  # beside the hub, inside the tire
        if road_moves:
            for x in (-0.4, 0.0, 0.4):
                ax.annotate("", (x, -0.65), (x, -1.25), arrowprops={"arrowstyle": "->", "color": "tab:blue"})
            ax.text(0.5, -1.35, "u_i", color="tab:blue")
        ax.set_title(title, fontsize=9)
    fig.text(0.355, 0.5, "=", fontsize=22, ha="center")
    fig.text(0.68, 0.5, "+", fontsize=22, ha="center")
    fig.suptitle("Fig. 7 analogue: computation of the force on the moving hub, F_M = F_F + F_H (Eq. 5)")
    return fig


def plot_frf_pair(
    freqs: np.ndarray,
    curves: dict[str, np.ndarray],
    ylabel: str,
    ax: plt.Axes | None = None,
    log: bool = True,
    scale: float = 1.0,
) -> plt.Axes:
    """Moduli of a few complex FRFs on one axis (first curve bold: the reference); ``scale`` takes the
    curves' SI values to the axis' unit (e.g. 1e-3 for N/m to N/mm, the unit of every FRF figure)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for k, (label, values) in enumerate(curves.items()):
        style = {"color": "k", "lw": 2.2} if k == 0 else {"ls": "--", "lw": 1.3}
        (ax.semilogy if log else ax.plot)(freqs, np.abs(values) * scale, label=label, **style)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel(ylabel)
    ax.legend()
    return ax
