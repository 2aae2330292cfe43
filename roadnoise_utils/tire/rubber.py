"""Frequency-dependent rubber moduli: the fractional-derivative Zener law.

The paper's FETvisco model gives each rubber compound "both elastic and loss moduli
dependent on frequency" (section "The FET Model"). We use the four-parameter fractional
Zener law (Bagley & Torvik 1983; Pritz 1996), which reproduces the broad, flat loss peak of
filled rubber with few parameters:

.. math:: \\frac{E^*(\\omega)}{E_0} = g(\\omega)
          = \\frac{1 + r\\,(i\\omega\\tau)^\\alpha}{1 + (i\\omega\\tau)^\\alpha}

with :math:`E_0` the static (relaxed) modulus, :math:`r = E_\\infty/E_0 > 1` the ratio of
the glassy to the relaxed modulus, :math:`\\tau` a relaxation time and
:math:`0 < \\alpha \\le 1` the fractional order. :math:`g(0) = 1`, so the stiffness
matrix of a compound assembled with :math:`E_0` is simply scaled by :math:`g(\\omega)`:
``K(omega) = K_elastic + sum_c g_c(omega) K_c``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike


@dataclass(frozen=True)
class FractionalZener:
    """Normalised complex modulus of one rubber compound.

    Parameters
    ----------
    modulus_ratio : float
        :math:`r = E_\\infty / E_0` (-), > 1.
    relaxation_time : float
        :math:`\\tau` (s), > 0.
    order : float
        Fractional order :math:`\\alpha` (-), in (0, 1].
    """

    modulus_ratio: float
    relaxation_time: float
    order: float

    def __post_init__(self) -> None:
        if not self.modulus_ratio > 1.0:
            raise ValueError(f"modulus_ratio = {self.modulus_ratio} must be > 1 (E_inf / E_0)")
        if not self.relaxation_time > 0.0:
            raise ValueError(f"relaxation_time = {self.relaxation_time} s must be > 0")
        if not 0.0 < self.order <= 1.0:
            raise ValueError(f"order = {self.order} must be in (0, 1]")

    def ratio(self, omega: ArrayLike) -> np.ndarray:
        """Complex modulus ratio :math:`g(\\omega) = E^*(\\omega)/E_0` at angular frequency ``omega`` (rad/s)."""
        omega = np.asarray(omega, dtype=float)
        s = (1j * np.abs(omega) * self.relaxation_time) ** self.order
        g = (1.0 + self.modulus_ratio * s) / (1.0 + s)
        # negative frequencies: g(-w) = conj(g(w)) (real impulse response)
        return np.where(omega < 0, np.conj(g), g)

    def storage(self, omega: ArrayLike) -> np.ndarray:
        """Storage modulus ratio :math:`E'(\\omega)/E_0` (-)."""
        return np.real(self.ratio(omega))

    def loss_factor(self, omega: ArrayLike) -> np.ndarray:
        """Loss factor :math:`\\eta = E''/E'` (-)."""
        g = self.ratio(omega)
        return np.imag(g) / np.real(g)


def compound_table(laws: dict[str, FractionalZener], f_low: float = 1.0, f_high: float = 250.0) -> pd.DataFrame:
    """Storage rise from ``f_low`` to ``f_high`` (Hz) and loss factors of each compound."""
    w_low, w_high = 2 * np.pi * f_low, 2 * np.pi * f_high
    rows = {
        name: {
            f"storage rise {f_low:g}->{f_high:g} Hz": float(law.storage(w_high) / law.storage(w_low) - 1.0),
            f"loss factor at {f_low:g} Hz": float(law.loss_factor(w_low)),
            "loss factor at 80 Hz": float(law.loss_factor(2 * np.pi * 80.0)),
            f"loss factor at {f_high:g} Hz": float(law.loss_factor(w_high)),
        }
        for name, law in laws.items()
    }
    return pd.DataFrame(rows).T.rename_axis("compound")
