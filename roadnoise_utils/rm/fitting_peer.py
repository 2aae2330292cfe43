"""Peer libraries run on our data, for side-by-side checks (tests, benchmarks, notebooks).

Each peer is imported only when called, so the package does not depend on it.
"""

from __future__ import annotations

import logging
import time
import warnings

import numpy as np
import pandas as pd

from ..analysis import relative_rms_error


def skrf_vector_fit(freqs: np.ndarray, H: np.ndarray, n_poles: int, f_max: float = 250.0) -> tuple[np.ndarray, float]:
    """Fit each row of ``H`` with scikit-rf's ``VectorFitting`` (relaxed VF, Gustavsen 2006).

    Same model as ours: ``n_poles`` poles (complex pairs, one real pole if odd), a constant
    term, no proportional term; each row scaled to unit peak for the fit. Returns the relative
    RMS error of each fit over ``0-f_max`` Hz and the total wall time (s).
    """
    import skrf
    from skrf.vectorFitting import VectorFitting

    band = np.asarray(freqs) <= f_max
    f = np.asarray(freqs)[band]
    frequency = skrf.Frequency.from_f(f, unit="Hz")
    errors = []
    logging.disable(logging.WARNING)
    start = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for row in np.atleast_2d(H)[:, band]:
                scale = np.max(np.abs(row))
                vf = VectorFitting(skrf.Network(frequency=frequency, s=(row / scale).reshape(-1, 1, 1)))
                vf.vector_fit(
                    n_poles_real=n_poles % 2, n_poles_cmplx=n_poles // 2, fit_constant=True, fit_proportional=False
                )
                model = vf.get_model_response(0, 0, freqs=f) * scale
                errors.append(relative_rms_error(model, row))
    finally:
        logging.disable(logging.NOTSET)
    return np.array(errors), time.perf_counter() - start


def pyvectorfit_fit(
    freqs: np.ndarray, H: np.ndarray, n_poles: int, f_max: float = 250.0, common_poles: bool = False
) -> tuple[np.ndarray, float]:
    """Fit each row of ``H`` with pyvectorfit's ``fit`` (relaxed VF that keeps its best iterate).

    Same model as ours: ``n_poles`` poles, a constant term, the DC value imposed
    (``dc = Re H(0)``) when the data start at 0 Hz, uniform weights (the absolute error, as
    ours), the library's own starting poles, iteration cap and stopping rule. With
    ``common_poles`` all rows are fitted at once as channels of one model (one pole set), each
    row weighted by the inverse of its norm (each tassello by its relative error, as ours).
    Returns the relative RMS error of each row over ``0-f_max`` Hz and the total wall time (s).
    """
    import pyvectorfit

    band = np.asarray(freqs) <= f_max
    f = np.asarray(freqs)[band]
    rows = np.atleast_2d(H)[:, band]
    dc = rows[:, 0].real if f[0] == 0.0 else None
    start = time.perf_counter()
    if common_poles:
        w = np.broadcast_to(1.0 / np.linalg.norm(rows, axis=1), (f.size, rows.shape[0]))
        model = pyvectorfit.fit(f, rows.T, poles=n_poles, asymptote="constant", weights=w, dc=dc)[0]
        fitted = model.response(f).T
    else:
        fitted = np.array(
            [
                pyvectorfit.fit(
                    f, row, poles=n_poles, asymptote="constant", weights=None, dc=None if dc is None else dc[i]
                )[0].response(f)
                for i, row in enumerate(rows)
            ]
        )
    seconds = time.perf_counter() - start
    return np.array([relative_rms_error(g, h) for g, h in zip(fitted, rows)]), seconds


def fit_comparison(
    ours_errors: np.ndarray,
    ours_seconds: float,
    peer_errors: np.ndarray,
    peer_seconds: float,
    peer: str = "scikit-rf VectorFitting",
) -> pd.DataFrame:
    """Side-by-side table: max and median error, fits where each is better, wall time."""
    return pd.DataFrame(
        {
            "max rms error": [ours_errors.max(), peer_errors.max()],
            "median rms error": [np.median(ours_errors), np.median(peer_errors)],
            "fits at least as good as the other": [
                int(np.sum(ours_errors <= peer_errors)),
                int(np.sum(peer_errors <= ours_errors)),
            ],
            "time (s)": [ours_seconds, peer_seconds],
        },
        index=pd.Index(["roadnoise (ours)", peer], name="method"),
    )
