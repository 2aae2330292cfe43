"""The closed-form check of a tire belt: one inextensible ring on an elastic foundation.

The analytic natural frequencies of a pressurised ring of radius :math:`R`, bending stiffness
:math:`EI`, mass per length and radial/tangential foundation stiffnesses (Kung, Soedel & Yang
1986, with the follower pressure): the second method that checks each FE tire model's belt.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RingParameters:
    """Per-unit-length parameters of the equivalent single ring (SI units)."""

    radius: float  # m
    bending_stiffness: float  # N m^2
    tension: float  # N
    k_radial: float  # N/m^2
    k_tangential: float  # N/m^2
    mass_per_length: float  # kg/m


def ring_frequencies(n: np.ndarray | int, ring: RingParameters) -> np.ndarray:
    """Closed-form natural frequencies (Hz) of circumferential wave numbers ``n`` (n = 0: torsion)."""
    try:
        n = np.asarray(n, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"n = {n!r} must be wave numbers: whole numbers >= 0") from None
    if not (np.all(np.isfinite(n)) and np.all(n >= 0) and np.all(n == np.round(n))):
        raise ValueError(f"n = {n!r} must be wave numbers: whole numbers >= 0")
    r = ring.radius
    bracket = ring.bending_stiffness * (n**2 - 1) ** 2 / r**4 + ring.tension * (n**2 - 1) / r**2 + ring.k_radial
    omega2 = (n**2 * bracket + ring.k_tangential) / (ring.mass_per_length * (n**2 + 1))
    omega2 = np.where(n == 0, ring.k_tangential / ring.mass_per_length, omega2)
    return np.sqrt(omega2) / (2 * np.pi)
