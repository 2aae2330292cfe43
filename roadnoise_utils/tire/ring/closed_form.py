"""Closed-form check of the belt: one ring on an elastic foundation.

An inextensible ring of radius :math:`R`, bending stiffness :math:`EI`, inflation tension
:math:`T`, mass per length :math:`\\rho A` on a radial and tangential foundation
:math:`k_r, k_t` (per unit length) has the in-plane natural frequencies (Gong 1993;
Kung, Soedel & Yang 1986, with the follower pressure)

.. math:: \\omega_n^2 = \\frac{n^2\\left[\\frac{EI (n^2-1)^2}{R^4} + \\frac{T (n^2-1)}{R^2} + k_r\\right] + k_t}
                              {\\rho A\\,(n^2+1)},\\quad n \\ge 1,
          \\qquad \\omega_0^2 = \\frac{k_t}{\\rho A}.

Our FE ring is the belt of :func:`.fet.build_fet` with one strip and no tread, contact or
lateral coupling; it must converge to these values with the mesh.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import scipy.sparse.linalg as spla

from ... import guards
from ..ring_theory import RingParameters, ring_frequencies
from .mechanics import build_fet
from .mode_shapes import wave_numbers
from .spec import TireSpec


def ring_parameters(spec: TireSpec) -> RingParameters:
    """The whole belt of ``spec`` lumped into one ring, static moduli."""
    p = spec.operating.inflation_pressure
    f = spec.foundation
    return RingParameters(
        radius=spec.geometry.belt_radius,
        bending_stiffness=spec.belt.bending_stiffness,
        tension=spec.hoop_tension,
        k_radial=f.radial_pressure_factor * p + f.radial_rubber,
        k_tangential=f.tangential_pressure_factor * p + f.tangential_rubber,
        mass_per_length=spec.belt.mass_per_length,
    )


def edge_zone_wavenumber(spec: TireSpec) -> float:
    r"""The belt's wavenumber on the tread springs (1/m), :math:`\beta = (k_{tread}\,b / 4EI)^{1/4}`.

    The belt on the tread springs is a beam on an elastic foundation: its response to a load at
    the footprint's edge decays as :math:`e^{-\beta s}\cos\beta s` (Hetenyi), so the footprint's
    stiffness sits in an edge zone :math:`1/\beta` deep.
    """
    foundation = spec.tread.normal_stiffness_per_area * spec.geometry.belt_width  # N/m per m of belt
    return float((foundation / (4 * spec.belt.bending_stiffness)) ** 0.25)


def single_ring_spec(spec: TireSpec, n_elements: int | None = None) -> TireSpec:
    """``spec`` reduced to one ring: one strip, no sidewall mass, no crown (tread is contact-only)."""
    changes = {"mesh.n_strips": 1, "foundation.sidewall_mass": 0.0, "geometry.crown_drop": 0.0}
    if n_elements is not None:
        changes["mesh.n_elements"] = n_elements
    return spec.replace(**changes)


def ring_check(spec: TireSpec, n_max: int = 8, n_elements: int | None = None) -> pd.DataFrame:
    """FE single-ring frequencies against the closed form, wave numbers n = 0 to ``n_max``.

    Returns
    -------
    pandas.DataFrame
        Index ``n``; columns ``closed_form_Hz``, ``fe_Hz`` (mean of the sin/cos pair) and
        ``rel_error`` (FE / closed form - 1).
    """
    n_max = guards.integer("n_max", n_max, 0, 40)
    ring_spec = single_ring_spec(spec, n_elements)
    fet = build_fet(ring_spec)
    free = np.setdiff1d(np.arange(fet.n_dof), fet.mesh.hub_dofs)
    K = fet.K(0.0, storage_only=True)[free][:, free]
    M = fet.M[free][:, free]
    n_modes = 2 * n_max + 6
    start = np.random.default_rng(0).standard_normal(K.shape[0])  # ARPACK's default start is random
    vals, vecs = spla.eigsh(K.tocsc(), k=n_modes, M=M.tocsc(), sigma=0.0, v0=start)
    order = np.argsort(vals)
    vals, vecs = vals[order], vecs[:, order]
    shapes = np.zeros((fet.n_dof, vecs.shape[1]))
    shapes[free] = vecs
    wn = wave_numbers(fet, shapes)
    freqs = np.sqrt(np.abs(vals)) / (2 * np.pi)
    rows = []
    ring = ring_parameters(ring_spec)
    for n in range(n_max + 1):
        fe = freqs[wn == n]
        if n == 0:
            fe = fe[:1]  # torsion; the breathing (extensional) mode is far above
        rows.append({"n": n, "closed_form_Hz": float(ring_frequencies(n, ring)), "fe_Hz": float(np.mean(fe[:2]))})
    table = pd.DataFrame(rows).set_index("n")
    table["rel_error"] = table["fe_Hz"] / table["closed_form_Hz"] - 1.0
    return table


def ring_convergence(spec: TireSpec, meshes: tuple[int, ...] = (60, 120, 240, 480), n_max: int = 8) -> pd.DataFrame:
    """Relative error of the FE ring frequencies (rows ``n``) for each mesh (columns: elements)."""
    return pd.DataFrame({m: ring_check(spec, n_max, n_elements=m)["rel_error"] for m in meshes}).rename_axis(
        columns="elements"
    )
