"""Figures of notebook 10-extension-to-400-hz: the 250 Hz and the 400 Hz models on the cleat and the rough road."""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib.pyplot as plt
import numpy as np

if TYPE_CHECKING:
    from ..experiments.bands import BandExtension

#: Lowest frequency of the road PSD figure (Hz): the tire's band, not the road's long waves.
LOWEST_SHOWN = 10.0


def plot_band_cleat(extension: BandExtension, ax: plt.Axes | None = None) -> plt.Axes:
    """Hub force over the cleat (30 km/h, drum): each band's RM chain and the direct FE model at the widest band."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.5))
    widest = max(extension.models)
    ref = extension.models[widest]
    ax.plot(ref.cleat.distance, ref.cleat_fe, "k-", lw=2.4, alpha=0.35, label=f"direct FE, 0-{widest:g} Hz")
    for (band, model), style in zip(sorted(extension.models.items()), ["--", "-", ":"]):
        ax.plot(model.cleat.distance, model.cleat_rm, style, lw=1.3, label=f"RM chain, 0-{band:g} Hz")
    ax.set_xlabel("distance travelled (m); 0 = cleat leading edge under the axle")
    ax.set_ylabel("hub force (N)")
    c = extension.cleat_conditions
    ax.set_title(f"cleat {c.height * 1e3:g} x {c.base * 1e3:g} mm on the drum, {c.dynamic_kmh:.0f} km/h, hub fixed")
    ax.legend()
    return ax


def plot_band_road(extension: BandExtension, ax: plt.Axes | None = None) -> plt.Axes:
    """Hub-force PSD on the rough road at the road test's speed: each band's RM chain and the direct FE model."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.5))
    f = extension.road_freqs
    ax.semilogy(f, extension.road_fe_psd, "k-", lw=2.4, alpha=0.35, label="direct FE")
    for (band, model), style in zip(sorted(extension.models.items()), ["--", "-", ":"]):
        ax.semilogy(f, model.road_psd, style, lw=1.2, label=f"RM chain fitted 0-{band:g} Hz")
        ax.axvline(band, color="0.6", lw=0.8, ls=":")
    shown = f >= LOWEST_SHOWN  # below it the road's long waves rise by decades over the tire's band
    ax.set_xlim(LOWEST_SHOWN, f.max())
    levels = np.concatenate([extension.road_fe_psd[shown]] + [m.road_psd[shown] for m in extension.models.values()])
    ax.set_ylim(levels[levels > 0].min() / 2, levels.max() * 2)
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("hub force PSD (N$^2$/Hz)")
    ax.set_title(f"rough road at {extension.road_conditions.speed_kmh:.0f} km/h, hub fixed")
    ax.legend()
    return ax
