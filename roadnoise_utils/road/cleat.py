"""The cleat: a short obstacle on the drum, flowing through the footprint (paper Fig. 8-9)."""

from __future__ import annotations

import numpy as np

from .. import guards
from ..tire.model import Footprint
from .input import MAX_SPEED, RoadInput, profile_input


def cleat_profile(height: float, base: float, shape: str = "triangle"):
    """Road height of a cleat whose leading edge (met first) is at road coordinate 0, extending to ``base``.

    Shapes: ``"triangle"`` (paper), ``"rectangle"``, ``"half-sine"``.
    """
    height = guards.real("cleat height", height, 0.0, 0.1, lo_open=True, unit="m")
    base = guards.real("cleat base", base, 0.0, 0.5, lo_open=True, unit="m")
    if shape not in ("triangle", "rectangle", "half-sine"):
        raise ValueError(f"cleat shape = {shape!r}: valid values are 'triangle', 'rectangle', 'half-sine'")

    def profile(s: np.ndarray) -> np.ndarray:
        xi = np.asarray(s, dtype=float) / base  # 0 at the leading edge, 1 at the trailing edge
        inside = (xi >= 0) & (xi <= 1)
        if shape == "triangle":
            z = height * (1 - np.abs(2 * xi - 1))
        elif shape == "rectangle":
            z = np.full_like(xi, height)
        else:
            z = height * np.sin(np.pi * np.clip(xi, 0, 1))
        return np.where(inside, z, 0.0)

    return profile


def cleat_input(
    static: Footprint,
    speed: float,
    height: float,
    base: float,
    shape: str = "triangle",
    distance: tuple[float, float] = (-0.1, 0.5),
    sample_rate: float | None = None,
) -> RoadInput:
    """A cleat on the drum flowing through the footprint (paper Fig. 8-9).

    Parameters
    ----------
    static : Footprint
        The tire loaded on the drum.
    speed : float
        Rolling speed (m/s), > 0.
    height, base : float
        Cleat height and length along the road (m); the paper's is 15 mm x 15 mm
        (``data/conditions/cleat_test.toml``, resolved by ``ru.experiments.cleat_conditions``).
    shape : {"triangle", "rectangle", "half-sine"}
        Cleat profile (:func:`cleat_profile`).
    distance : (float, float)
        Travel range (m), 0 = the cleat's leading edge under the axle; the default runs from
        0.1 m before to 0.5 m after (the decay).
    sample_rate : float, optional
        Samples per second; default :func:`.input.sample_rate_for`.

    Notes
    -----
    The drum's curvature is in the static footprint; the cleat height is added normal to the
    drum surface (vertical to within 0.1 % over the footprint of a 1.25 m drum).
    """
    speed = guards.real("speed", speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s")
    return profile_input(
        static,
        cleat_profile(height, base, shape),
        speed,
        distance,
        sample_rate,
        description=f"{shape} cleat {base * 1e3:.0f} mm x {height * 1e3:.0f} mm at {speed * 3.6:.1f} km/h",
    )


#: Samples per hat in :func:`point_heights` (exact for the piecewise-linear cleats to ~1e-4 of their height).
HAT_SAMPLES = 41


def point_heights(x: np.ndarray, dx_minus: np.ndarray, dx_plus: np.ndarray, profile, travel: np.ndarray) -> np.ndarray:
    """Road height under each tread point, averaged over its hat shape function, at each travel.

    The point at ``x`` (m) with neighbours ``dx_minus`` behind and ``dx_plus`` ahead (m) sees
    the road coordinate ``x + d`` after a travel ``d`` (as :func:`.input.profile_input`); its
    height is the hat-weighted mean of ``profile`` over ``[x - dx_minus, x + dx_plus]`` (the
    same shape functions that weigh a tassello's points). Returns (n_points, n_travel) in m.
    """
    dx_minus, dx_plus = np.asarray(dx_minus, float), np.asarray(dx_plus, float)
    half = HAT_SAMPLES // 2
    xi = np.linspace(0.0, 1.0, half + 1)  # 0 at the point, 1 at the neighbour
    ramp = 1.0 - xi  # the hat on either side (trapezoidal rule exact for it: integral 1/2)
    behind = np.asarray(x, float)[:, None] - xi[None, :] * dx_minus[:, None]
    ahead = np.asarray(x, float)[:, None] + xi[None, :] * dx_plus[:, None]
    mass = 0.5 * (dx_minus + dx_plus)
    out = np.empty((behind.shape[0], np.size(travel)))
    for k, d in enumerate(np.asarray(travel, float)):
        left = np.trapezoid(profile(behind + d) * ramp, dx=1.0 / half, axis=1)
        right = np.trapezoid(profile(ahead + d) * ramp, dx=1.0 / half, axis=1)
        out[:, k] = (dx_minus * left + dx_plus * right) / mass
    return out
