"""Figures of notebook 07-quarter-car: the quarter car (Fig. 13), transmissibility (Fig. 10), spectra (Fig. 11-12, 14)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Rectangle

from ..vehicle.spectra import power_share


def plot_quarter_car_scheme(vehicle) -> plt.Figure:
    """Fig. 13 analogue: the corner's masses and elements, with the RM tire under the hub."""
    names = ["body", "tower", "rod", "unsprung"]
    names = [n for n in names if n in vehicle.masses] + [n for n in vehicle.masses if n not in names]
    y = {name: 4.0 - 1.2 * k for k, name in enumerate(names)}
    x = {name: (0.6 if name == "rod" else 0.0) for name in names}
    fig, ax = plt.subplots(figsize=(8, 6.5))
    for name in names:
        ax.add_patch(Rectangle((x[name] - 0.45, y[name] - 0.25), 0.9, 0.5, fc="tab:blue", alpha=0.2, ec="tab:blue"))
        ax.text(x[name], y[name], f"{name}\n{vehicle.masses[name]:g} kg", ha="center", va="center", fontsize=8)
    ground_y = y[vehicle.hub] - 2.3
    ax.add_patch(Rectangle((-0.8, y[vehicle.hub] - 1.65), 1.6, 0.9, fc="0.3", alpha=0.25, ec="k"))
    ax.text(0, y[vehicle.hub] - 1.2, "RM tire\nF_M = F_F + G_H u_H\n(Eq. 5-7)", ha="center", va="center", fontsize=8)
    ax.plot([-1.2, 1.2], [ground_y, ground_y], color="tab:brown", lw=3)
    ax.text(0, ground_y - 0.25, "road irregularities → tasselli", ha="center", fontsize=8, color="tab:brown")
    ax.annotate("", (0, ground_y + 0.05), (0, y[vehicle.hub] - 1.65), arrowprops={"arrowstyle": "-", "ls": ":"})
    spacing, legend = 0.62, []
    for k, e in enumerate(vehicle.elements):
        ends = [(y.get(end, ground_y), x.get(end, 0.0)) for end in (e.a, e.b)]
        xm = -0.8 - spacing * (len(vehicle.elements) - 1 - k)
        (ya, _), (yb, _) = ends
        style = {"spring": "-", "damper": "--", "maxwell": "-."}[e.kind]
        ax.plot([xm, xm], [ya, yb], color="k", lw=1.2, ls=style)
        for y_end, x_end in ends:  # a leader from the element's end to the side of its mass
            ax.plot([xm, x_end - 0.45], [y_end, y_end], color="0.6", lw=0.6, zorder=0)
            ax.plot(xm, y_end, "o", color="k", ms=2.5)
        value = (
            f"{e.stiffness / 1e3:g} N/mm"
            if e.kind == "spring"
            else f"{e.damping:g} Ns/m"
            if e.kind == "damper"
            else f"{e.damping:g} Ns/m + {e.stiffness / 1e3:g} N/mm"
        )
        ax.text(
            xm, 0.5 * (ya + yb), str(k + 1), fontsize=7, ha="center", va="center",
            bbox={"boxstyle": "circle,pad=0.2", "fc": "w", "ec": "k", "lw": 0.6},
        )  # fmt: skip
        legend.append(f"{k + 1}  {e.a}-{e.b} {e.kind}: {value}")
    ax.text(
        -1.2 - spacing * len(vehicle.elements), ground_y + 0.1, "\n".join(legend), fontsize=7.5, va="bottom",
        ha="left", family="monospace",
    )  # fmt: skip
    ax.set_xlim(-1.2 - spacing * len(vehicle.elements), 1.6)
    ax.set_ylim(ground_y - 0.5, 4.5)
    ax.axis("off")
    fig.suptitle("Fig. 13 analogue: the quarter car (front corner, MacPherson strut)")
    return fig


def plot_transmissibility(
    freqs: np.ndarray,
    transmissibility: np.ndarray,
    bands: dict,
    ax: plt.Axes | None = None,
    paper: dict[str, float] | None = None,
    ours: dict[str, float] | None = None,
) -> plt.Axes:
    """Fig. 10 analogue: |a_mount / a_hub| with the paper's bands (``vehicle.FrequencyBand``) shaded.

    ``paper`` and ``ours`` (band key -> level of :math:`|T|`): the paper's level of each band's
    claim (dashed) and our statistic over the band (solid), drawn across the band. The legend
    sits outside the axes, so it covers neither the curve nor the bands' labels.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4))
    ax.plot(freqs, np.abs(transmissibility), "k", lw=1.8, label="quarter car (ours)")
    colours = ["tab:blue", "tab:green", "tab:orange", "tab:purple"]
    for (key, band), colour in zip(bands.items(), colours, strict=False):
        ax.axvspan(band.f_low, band.f_high, color=colour, alpha=0.12)
        ax.text(0.5 * (band.f_low + band.f_high), 1.9, band.label, ha="center", fontsize=8, color=colour)
        span = (band.f_low, band.f_high)
        if paper and key in paper:
            ax.plot(
                span, (paper[key],) * 2, color=colour, ls="--", lw=1.6, label=f"paper: {band.label} ({paper[key]:.2g})"
            )
        if ours and key in ours:
            ax.plot(span, (ours[key],) * 2, color=colour, lw=2.4, label=f"ours: {band.statistic} |T| ({ours[key]:.2f})")
    ax.axhline(1.0, color="0.5", lw=0.7, ls=":")
    ax.set_ylim(0, 2.1)
    ax.set_xlim(0, 300)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|a_upper mount / a_hub|")
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return ax


def plot_spectra(
    freqs: np.ndarray,
    curves: dict[str, np.ndarray],
    ylabel: str,
    f_range: tuple[float, float],
    ax: plt.Axes | None = None,
    log: bool = False,
    predicted: dict[str, tuple] | None = None,
    styles: tuple[str, ...] | None = None,
    split: float | None = None,
    band: tuple[float, float] = (2.0, 250.0),
    peaks: dict[str, np.ndarray] | None = None,
) -> plt.Axes:
    """Amplitude spectral densities (sqrt of PSD) of a few signals, optionally with predictions.

    ``styles``: a line style per curve (default solid), e.g. dashed for a curve that may lie on another.
    ``split`` (Hz): a dotted line there, and each curve's label gives the share of its power in
    ``band`` (Hz) lying below it (:func:`roadnoise_utils.vehicle.spectra.power_share`, as the
    paper reads Fig. 11-12: where the power is). ``peaks`` (curve label -> Hz): marked on that
    curve.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    styles = styles or ("-",) * len(curves)
    for (name, psd), colour, style in zip(curves.items(), ["tab:red", "tab:blue", "tab:green"], styles):
        keep, label = (freqs >= f_range[0]) & (freqs <= f_range[1]), name
        if split is not None:
            label = f"{label}: {power_share((freqs, psd), 0.0, split, band=band):.0%} of the power below {split:g} Hz"
        (ax.semilogy if log else ax.plot)(freqs[keep], np.sqrt(psd[keep]), color=colour, ls=style, lw=1.2, label=label)
        if peaks and name in peaks:
            ax.plot(peaks[name], np.interp(peaks[name], freqs, np.sqrt(psd)), "v", color=colour, ms=6)
        if predicted and name in predicted:
            fp, pp = predicted[name]
            k = (fp >= f_range[0]) & (fp <= f_range[1])
            (ax.semilogy if log else ax.plot)(fp[k], np.sqrt(pp[k]), "k--", lw=0.8)
    if split is not None:
        ax.axvline(split, color="0.4", ls=":", lw=1.0)
    ax.set_xlim(*f_range)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel(ylabel)
    ax.legend()
    return ax


def plot_hub_modes(
    freqs: np.ndarray, psd: np.ndarray, peaks, f_range: tuple[float, float] = (40.0, 220.0), n_peaks: int = 4
) -> plt.Axes:
    """Fig. 14 analogue: the hub-acceleration ASD of a time-domain run (``freqs``, ``psd``: the 3D road), the
    frequency-domain prediction the ``peaks`` were found on (``experiments.corner.hub_mode_peaks``,
    the 2D road) and its first ``n_peaks`` peaks marked on it with their nearest tire mode."""
    ax = plot_spectra(
        freqs, {"rough, 3D road (time domain)": psd}, "hub acceleration ASD ((m/s²)/√Hz)", f_range, log=True
    )
    f_pred, asd_pred = peaks.attrs["freqs"], peaks.attrs["asd"]
    ax.semilogy(f_pred, asd_pred, "k--", lw=0.9, label="2D road, frequency domain (peaks found here)")
    shown = peaks.head(n_peaks)
    low, high = ax.get_ylim()
    ax.set_ylim(low, high * 4.0)  # room above the highest peak for its label
    ax.plot(shown["peak (Hz)"], shown["ASD ((m/s²)/√Hz)"], "kv", ms=6, label="its peaks")
    for _, row in shown.iterrows():
        ax.annotate(
            f"mode {int(row['nearest vertical mode'])}\n{row['peak (Hz)']:.0f} Hz",
            (row["peak (Hz)"], row["ASD ((m/s²)/√Hz)"]),
            xytext=(0, 12),
            textcoords="offset points",
            ha="center",
            fontsize=8,
        )
    ax.legend(fontsize=8)
    return ax
