"""Model order of the rational fits: the error against the number of poles, and the lowest order
that fits every FRF within a tolerance (notebook 03: the paper's 8 poles against our tire's needs)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from .. import guards
from .fitting import FitSet, fit_tasselli


def order_scan(
    freqs: np.ndarray, H: np.ndarray, orders: range | list[int] = range(8, 19), f_max: float | None = None, **options
) -> pd.DataFrame:
    """Largest and median relative RMS error of :func:`fit_tasselli` for each model order.

    ``f_max`` (Hz) the top of the fitted band, ``None`` (default) the data's; the paper's is 250 Hz.
    """
    rows = []
    for n in orders:
        fits = fit_tasselli(freqs, H, n_poles=n, f_max=f_max, **options)
        e = fits.rms_errors
        rows.append(
            {"poles": n, "max rms error": e.max(), "median rms error": float(np.median(e)), "time (s)": fits.seconds}
        )
    return pd.DataFrame(rows).set_index("poles")


def default_orders(f_max: float | None) -> range:
    """Orders searched for a band 0-``f_max`` Hz: 8 to 24 up to 250 Hz, the top growing with the band
    beyond (the modes in band grow about in proportion: 8 to 39 at 400 Hz)."""
    top = 24 if f_max is None or f_max <= 250.0 else int(np.ceil(24 * f_max / 250.0))
    return range(8, top + 1)


def lowest_order(
    freqs: np.ndarray,
    H: np.ndarray,
    tolerance: float = 0.01,
    orders: range | list[int] | None = None,
    f_max: float | None = None,
    strict: bool = True,
    **options,
) -> FitSet:
    """The fits at the lowest order whose every fit has relative RMS error below ``tolerance``.

    ``orders`` default :func:`default_orders` of the band; ``f_max`` (Hz) its top, ``None``
    (default) the data's top frequency (the paper's band is 0-250 Hz). :func:`fit_tasselli` with
    ``n_poles="auto"`` searches the even orders alone.

    When no order in ``orders`` gets there: ``strict`` raises ``ValueError``; otherwise the order
    with the smallest worst error is returned with a :class:`~roadnoise_utils.guards.RoadnoiseWarning`
    naming it (the chain then runs, the error stated).
    """
    orders = default_orders(float(np.max(freqs)) if f_max is None else f_max) if orders is None else orders
    best = None
    for n in orders:
        fits = fit_tasselli(freqs, H, n_poles=n, f_max=f_max, **options)
        if fits.rms_errors.max() < tolerance:
            return fits
        if best is None or fits.rms_errors.max() < best.rms_errors.max():
            best = fits
    message = f"no order in {list(orders)} fits every FRF within {tolerance:.1%}"
    if strict or best is None:
        raise ValueError(message)
    e = best.rms_errors
    guards.warn(
        f"{message}: using {best.n_poles} poles, the smallest worst error ({e.max():.2%}; "
        f"{int(np.sum(e >= tolerance))} of {e.size} FRFs above {tolerance:.0%}, median {np.median(e):.2%})",
        stacklevel=3,
    )
    return best


def fit_at_order(
    freqs: np.ndarray,
    H: np.ndarray,
    n_poles: int | None = None,
    f_max: float = 250.0,
    tolerance: float = 0.01,
    strict: bool = True,
) -> FitSet:
    """Fits with ``n_poles`` poles each, or, with ``n_poles=None``, at the :func:`lowest_order` within ``tolerance``."""
    if n_poles is None:
        return lowest_order(freqs, H, tolerance=tolerance, f_max=f_max, strict=strict)
    return fit_tasselli(freqs, H, n_poles=n_poles, f_max=f_max)
