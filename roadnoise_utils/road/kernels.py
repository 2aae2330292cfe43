"""The footprint as a road filter: each tassello's averaging kernel, in space and in wavenumber.

Paper, *Simulation of Wheel-Road Interaction*: the displacement of a tassello is "a weighted
average of all the physical displacements of the points inside the area of the tassello, where
the weighting function consists of the shape functions of the finite elements". For a road
uniform across the width that average is a correlation with a kernel :math:`k_i(x)`
(:func:`tassello_kernels`); its Fourier transform :math:`K_i(n)` (:func:`kernel_transforms`)
is how the tassello filters a wavenumber ``n``, and :func:`tassellation_error` what the blocks
lose against the contact points' own resolution (the paper's 5 cm claim).
"""

from __future__ import annotations

import numpy as np

from ..tire.model import Footprint
from ..tire.tasselli import Tasselli


def tassello_kernels(tasselli: Tasselli, step: float) -> tuple[np.ndarray, float]:
    """Kernels :math:`k_i` on a uniform grid of spacing ``step`` (m): (n_tasselli, n_x) and x of column 0.

    Each row integrates to one (trapezoidal rule); the hats are piecewise linear, so a fine
    grid makes the correlation with a piecewise-linear road essentially exact.
    """
    parts, x0 = strip_kernels(tasselli, step)
    kernels = np.zeros((tasselli.n, parts[0][2].shape[1]))
    for _, rows, part in parts:
        kernels[rows] += part
    return kernels, x0


def strip_kernels(tasselli: Tasselli, step: float) -> tuple[list[tuple[int, np.ndarray, np.ndarray]], float]:
    """Kernels split by belt strip: ``[(strip, rows (tasselli), kernels (rows, n_x))]`` and x of column 0.

    Each tassello's nodes lie in the strips of its column; for a road uniform across the width
    the strip parts of a kernel simply add up to :func:`tassello_kernels`.
    """
    x_lo = np.min(tasselli.node_x - tasselli.node_dx_minus)
    x_hi = np.max(tasselli.node_x + tasselli.node_dx_plus)
    x = np.arange(np.floor(x_lo / step) - 1, np.ceil(x_hi / step) + 2) * step
    left = np.clip(1.0 + (x[None, :] - tasselli.node_x[:, None]) / tasselli.node_dx_minus[:, None], 0.0, 1.0)
    right = np.clip(1.0 - (x[None, :] - tasselli.node_x[:, None]) / tasselli.node_dx_plus[:, None], 0.0, 1.0)
    hats = np.where(x[None, :] <= tasselli.node_x[:, None], left, right)
    hats /= np.trapezoid(hats, dx=step, axis=1)[:, None]
    weighted = tasselli.node_weight[:, None] * hats
    total = np.zeros((tasselli.n, x.size))
    np.add.at(total, tasselli.node_tassello, weighted)
    norm = np.trapezoid(total, dx=step, axis=1)
    parts = []
    for strip in np.unique(tasselli.node_strip):
        nodes = tasselli.node_strip == strip
        rows = np.unique(tasselli.node_tassello[nodes])
        kernel = np.zeros((tasselli.n, x.size))
        np.add.at(kernel, tasselli.node_tassello[nodes], weighted[nodes])
        parts.append((int(strip), rows, kernel[rows] / norm[rows, None]))
    return parts, float(x[0])


def kernel_transforms(static: Footprint, wavenumbers: np.ndarray, step: float = 2.0e-4) -> np.ndarray:
    """:math:`K_i(n) = \\int k_i(x) e^{i 2\\pi n x} dx` for every tassello (rows) and wavenumber (cycles/m)."""
    kernels, x0 = tassello_kernels(static.tasselli, step)
    x = x0 + step * np.arange(kernels.shape[1])
    phase = np.exp(2j * np.pi * np.outer(x, np.asarray(wavenumbers, float)))
    return step * (kernels @ phase)


def _phi(z: np.ndarray) -> np.ndarray:
    """:math:`(e^z - 1 - z)/z^2`, with its Taylor series near 0 (no cancellation)."""
    z = np.asarray(z, dtype=complex)
    small = np.abs(z) < 0.1
    safe = np.where(small, 1.0, z)
    closed = (np.expm1(safe) - safe) / safe**2
    series = sum(z**j / float(np.prod(np.arange(1, j + 3))) for j in range(10))
    return np.where(small, series, closed)


def point_transforms(static: Footprint, wavenumbers: np.ndarray) -> np.ndarray:
    """Transforms of each contact point's normalised hat kernel, (n_points, n_wavenumbers).

    A hat rising over ``a`` to 1 at ``x`` and falling over ``b`` has
    :math:`\\int N e^{iks} ds = e^{ikx}\\,[a\\,\\varphi(-ika) + b\\,\\varphi(ikb)]`,
    :math:`\\varphi(z) = (e^z - 1 - z)/z^2`; divided by its area :math:`(a+b)/2`.
    """
    t = static.tasselli
    k = 2 * np.pi * np.asarray(wavenumbers, float)[None, :]
    a, b, x = t.node_dx_minus[:, None], t.node_dx_plus[:, None], t.node_x[:, None]
    return np.exp(1j * k * x) * (a * _phi(-1j * k * a) + b * _phi(1j * k * b)) * 2 / (a + b)


def tassellation_error(static: Footprint, point_frf: np.ndarray, wavelengths: np.ndarray) -> np.ndarray:
    """Error of the hub force from tasselli against contact-point resolution, per wavelength.

    Relative to the force a long wave of the same amplitude would give, :math:`|\\sum_n H_n|`
    (at short wavelengths the exact force itself nearly cancels over the footprint).

    For a sinusoidal road of wavelength λ, the FE model at the resolution of its contact points
    gives :math:`F = \\sum_n H_n Z_n`; the RM model moves each tassello as one block with the
    weighted average of its points, :math:`F = \\sum_i H_i \\sum_{n\\in i} w_n Z_n`.
    ``point_frf``: the contact points' FRFs at the frequency of interest (one column).
    """
    t = static.tasselli
    z = point_transforms(static, 1.0 / np.asarray(wavelengths, float))  # (points, wavelengths)
    points = np.asarray(point_frf)[:, None] * z
    exact = points.sum(axis=0)
    membership = t.membership()
    tassello_frf = membership @ np.asarray(point_frf)
    tassello_input = membership @ (t.node_weight[:, None] * z)
    blocks = (tassello_frf[:, None] * tassello_input).sum(axis=0)
    return np.abs(blocks - exact) / np.abs(np.sum(point_frf))
