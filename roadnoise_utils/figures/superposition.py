"""Figures of notebook 02-superposition-and-modal-reduction: the procedure (Fig. 4), superposition (Fig. 5), damping identification, local and hub FRFs."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Rectangle

from ..tire.model import Footprint, FRFResult
from .common import MM, paper_lines


def plot_modal_procedure() -> plt.Figure:
    """Fig. 4 analogue: the procedure for the local FRFs via modal reduction."""
    boxes = {
        "visco": (0.6, 0.82, "FETvisco\nK(ω) = K_el + Σ g_c(ω) K_c"),
        "htot": (0.6, 0.5, "H_tot(ω): whole footprint → hub\n(direct solve, 0-250 Hz)"),
        "ident": (0.6, 0.18, "1. global damping identification\nω_r, η_r of the vertical modes"),
        "frozen": (2.2, 0.82, "2. moduli frozen at the most\nrelevant vertical mode (FET80Hz)"),
        "modes": (2.2, 0.5, "eigenmodes of the symmetric\nclass, up to 2 x band"),
        "local": (3.8, 0.5, "3. local FRFs H_i(ω), every tassello\n+ quasi-static residual correction"),
        "check": (3.8, 0.18, "check (Fig. 5): Σ_i H_i vs H_tot"),
    }
    arrows = [
        ((0.6, 0.74), (0.6, 0.58)),
        ((0.6, 0.42), (0.6, 0.26)),
        ((1.25, 0.82), (1.6, 0.82)),
        ((2.2, 0.74), (2.2, 0.58)),
        ((2.75, 0.5), (3.1, 0.5)),
        ((1.25, 0.2), (3.15, 0.44)),
        ((3.8, 0.42), (3.8, 0.26)),
    ]
    fig, ax = plt.subplots(figsize=(11, 4))
    ax.set_xlim(-0.2, 4.6)
    ax.set_ylim(0.02, 0.98)
    ax.axis("off")
    for x, y, text in boxes.values():
        ax.text(
            x,
            y,
            text,
            ha="center",
            va="center",
            fontsize=8.5,
            bbox={"boxstyle": "round", "fc": "tab:blue", "alpha": 0.15, "ec": "tab:blue"},
        )
    for start, end in arrows:
        ax.annotate("", end, start, arrowprops={"arrowstyle": "->", "color": "0.4"})
    fig.suptitle("Fig. 4 analogue: computation of the local FRFs via modal reduction")
    return fig


def plot_superposition(
    visco: FRFResult,
    modal: dict[str, FRFResult],
    f_max: float = 300.0,
    ax: plt.Axes | None = None,
    paper: dict[str, float] | None = None,
) -> plt.Axes:
    """Fig. 5 analogue: :math:`|H_{tot}|` of the viscoelastic model vs :math:`|\\sum H_i|` of modal models (N/mm).

    ``paper``: the paper's frequencies (label -> Hz, e.g. its ~70 Hz freezing frequency), drawn as reference lines.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4.5))
    keep = visco.freqs <= f_max
    ax.plot(visco.freqs[keep], np.abs(visco.H_tot[keep]) / 1e3, "k", lw=1.6, label="H_tot, FETvisco (SISO, direct)")
    for (label, frf), style in zip(modal.items(), ["--", ":", "-."]):
        k = frf.freqs <= f_max
        ax.plot(frf.freqs[k], np.abs(frf.H_sum[k]) / 1e3, style, lw=1.4, label=f"Σ H_i, {label} (MIMO)")
    ax.set_xlim(0, f_max)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|H| (N/mm)")
    if paper:
        paper_lines(ax, paper, axis="x", unit="Hz")
    top = max(np.abs(visco.H_tot[keep]).max(), *(np.abs(f.H_sum[f.freqs <= f_max]).max() for f in modal.values()))
    ax.set_ylim(0, 1.6 * top / 1e3)  # the legend above the curves, covering none of them
    ax.legend(loc="upper right", fontsize=7)
    return ax


def plot_identification(visco: FRFResult, ident, f_max: float = 300.0) -> plt.Figure:
    """H_tot of the viscoelastic model and the identified modal model: modulus and phase."""
    f = visco.freqs[visco.freqs <= f_max]
    data = visco.H_tot[visco.freqs <= f_max]
    fit = ident.evaluate(f)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    a1.semilogy(f, np.abs(data) / 1e3, "k", label="H_tot, FETvisco")
    a1.semilogy(f, np.abs(fit) / 1e3, "--", color="tab:red", label="identified modal model (0-250 Hz)")
    for fr in ident.freqs:
        a1.axvline(fr, color="0.7", lw=0.7, ls=":")
    a2.plot(f, np.degrees(np.angle(data)), "k")
    a2.plot(f, np.degrees(np.angle(fit)), "--", color="tab:red")
    a1.axvspan(ident.band[1], f_max, color="0.9")
    a1.set_ylabel("|H_tot| (N/mm)")
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend()
    fig.suptitle("Global damping identification from H_tot (grey: outside the fitted band)")
    return fig


def plot_tassello_frf(static: Footprint, frfs: dict[str, FRFResult], tassello: int, f_max: float = 300.0) -> plt.Figure:
    """The modulus :math:`|H_i|` and phase of one tassello (number from 1) from several models, with its position."""
    i = tassello - 1
    fig = plt.figure(figsize=(11, 4.2))
    a1 = fig.add_subplot(2, 3, (1, 2))
    a2 = fig.add_subplot(2, 3, (4, 5), sharex=a1)
    a3 = fig.add_subplot(1, 3, 3)
    for (label, frf), style in zip(frfs.items(), ["k-", "--", ":", "-."], strict=False):
        k = frf.freqs <= f_max
        a1.plot(frf.freqs[k], np.abs(frf.H[i, k]) / 1e3, style, label=label)
        a2.plot(frf.freqs[k], np.degrees(np.angle(frf.H[i, k])), style)
    a1.set_ylabel("|H_i| (N/mm)")
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend(fontsize=7)
    t = static.tasselli
    for j, (x0, x1, y0, y1) in enumerate(t.bounds):
        a3.add_patch(
            Rectangle((x0 * MM, y0 * MM), (x1 - x0) * MM, (y1 - y0) * MM, fc="tab:red" if j == i else "0.85", ec="w")
        )
    a3.set_xlim(t.bounds[:, 0].min() * MM - 5, t.bounds[:, 1].max() * MM + 5)
    a3.set_ylim(t.bounds[:, 2].min() * MM - 5, t.bounds[:, 3].max() * MM + 5)
    a3.set_aspect("equal")
    a3.set_title(f"tassello {tassello}")
    a3.set_xlabel("x (mm) →")
    fig.suptitle(f"Local FRF of tassello {tassello}: hub force per unit displacement")
    return fig


def plot_hub_frf(frfs: dict[str, FRFResult], f_max: float = 300.0, ax: plt.Axes | None = None) -> plt.Axes:
    """The modulus :math:`|G_H|` (hub force per unit hub displacement, footprint held) in N/mm."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for (label, frf), style in zip(frfs.items(), ["k-", "--", ":", "-."], strict=False):
        k = frf.freqs <= f_max
        ax.plot(frf.freqs[k], np.abs(frf.G_H[k]) / 1e3, style, label=label)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|G_H| (N/mm)")
    ax.set_xlim(0, f_max)
    ax.legend()
    ax.set_title("G_H: hub force per unit hub displacement, footprint held")
    return ax
