"""Figures of notebook 03-tassello-fitting: the order scan and the fit of one tassello (Fig. 6)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd


def plot_order_scan(scans: dict[str, pd.DataFrame], tolerance: float = 0.01, ax: plt.Axes | None = None) -> plt.Axes:
    """Largest and median fit error vs model order, for one or more data sets."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    for (label, scan), colour in zip(scans.items(), ["tab:blue", "tab:orange", "tab:green"]):
        ax.semilogy(scan.index, scan["max rms error"], "o-", color=colour, label=f"{label}: worst tassello")
        ax.semilogy(scan.index, scan["median rms error"], "s--", color=colour, mfc="none", label=f"{label}: median")
    ax.axhline(tolerance, color="k", lw=0.8, ls=":", label=f"{tolerance:.0%} target")
    ax.axvline(8, color="0.6", lw=0.8, label="paper: 8 poles / 8 zeros")
    ax.set_xlabel("poles (= zeros) per tassello")
    ax.set_ylabel("relative RMS error, 0-250 Hz")
    ax.legend(fontsize=7)
    ax.set_title("Fit error of the tasselli against the number of poles")
    return ax


def plot_fit(freqs: np.ndarray, target: np.ndarray, fitted: np.ndarray, title: str) -> plt.Figure:
    """Fig. 6 analogue: target (FEA) and identified FRF (N/m), drawn as modulus (N/mm) and phase."""
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    a1.plot(freqs, np.abs(target) / 1e3, "k", lw=2.0, label="target (FEA)")
    a1.plot(freqs, np.abs(fitted) / 1e3, "--", color="tab:red", label="identified")
    a2.plot(freqs, np.degrees(np.unwrap(np.angle(target))), "k", lw=2.0)  # unwrapped: no ±180° jumps
    a2.plot(freqs, np.degrees(np.unwrap(np.angle(fitted))), "--", color="tab:red")
    a1.set_ylabel("|H_i| (N/mm)")
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend()
    fig.suptitle(title)
    return fig
