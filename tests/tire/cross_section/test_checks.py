"""The cross-section (waveguide) FE tire: element checks against closed forms and a 3-D assembly.

Verification (a), (b), (e) of notebook 09, section 3, and the element properties; the loaded
tire is in ``test_section_static.py``.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.cross_section import checks as section_checks
from roadnoise_utils.tire.cross_section.checks import LAW, band
from roadnoise_utils.tire.cross_section.operators import harmonic_operators
from roadnoise_utils.tire.cross_section.waveguide import harmonic_weight, pressure_operators
from roadnoise_utils.tire.ring_theory import RingParameters, ring_frequencies


def test_thin_ring_on_foundation_matches_the_closed_form():
    """(a) One thin stiff layer, tension and follower pressure, radial/tangential foundation: Gong 1993."""
    table = section_checks.ring_check()
    assert table["error (%)"].abs().max() < 1.0


def test_free_thin_ring_bending_frequencies():
    """(a) Without tension or foundation the flexural modes n = 2..6 agree to 0.1 %."""
    table = section_checks.ring_check(tension=0.0, k_r=0.0, k_t=0.0)
    assert table["error (%)"].iloc[1:].abs().max() < 0.1
    ring = RingParameters(0.3, 2e9 * 0.1 * 0.002**3 / 12, 0.0, 0.0, 0.0, 1200.0 * 0.1 * 0.002)
    np.testing.assert_allclose(table["closed form (Hz)"].iloc[1:], ring_frequencies(np.arange(2, 7), ring))


def test_rigid_body_motions_store_no_strain_energy():
    """The strain operators: translation (n = 0 along y, n = 1 across) and rotation about the axle are free."""
    mesh = band(n_el=3, poisson=0.3)
    ops = harmonic_operators(mesh, LAW, 0.0, fixed=np.array([], int), prestress=np.zeros((mesh.points.element.size, 6)))
    k0, k1 = ops.stiffness(0, storage_only=True), ops.stiffness(1, storage_only=True)
    axial = np.zeros(mesh.n_dof)
    axial[2::3] = 1.0
    spin = np.zeros(mesh.n_dof)
    spin[1::3] = mesh.r  # u_theta = r
    across = np.zeros(mesh.n_dof)
    across[0::3], across[1::3] = 1.0, -1.0  # u = e_r cos - e_t sin: a rigid translation
    scale = abs(k0).max()
    for k, u in ((k0, axial), (k0, spin), (k1, across)):
        assert np.abs(k @ u).max() < 1e-9 * scale * np.abs(u).max()


def test_pressure_volume_matches_the_exact_deformed_volume():
    """The load stiffness is -p times the Hessian of the volume: second-order volume of a ring deformation."""
    mesh = band(n_el=4)
    dv, h0, h1 = pressure_operators(mesh.r, mesh.y, mesh.face_lines(0), mesh.n_dof)
    inner, width = 0.3 - 0.001, 0.1
    assert harmonic_weight(0) * dv[0::3].sum() == pytest.approx(2 * np.pi * inner * width)
    theta = np.linspace(0, 2 * np.pi, 4001)[:-1]
    for n, a_r, a_t in ((2, 1.0, -0.5), (3, 0.7, 0.4)):
        a = np.zeros(mesh.n_dof)
        a[0::3], a[1::3] = a_r, a_t
        ours = harmonic_weight(n) * 0.5 * a @ ((h0 + n * h1) @ a)

        # exact area inside the curve r = inner + u_r, tangential u_t, second order in the amplitude
        def area(eps, n=n, a_r=a_r, a_t=a_t):
            ur, ut = eps * a_r * np.cos(n * theta), eps * a_t * np.sin(n * theta)
            x = (inner + ur) * np.cos(theta) - ut * np.sin(theta)
            z = (inner + ur) * np.sin(theta) + ut * np.cos(theta)
            dx = np.gradient(np.concatenate([x[-1:], x, x[:1]]), 2 * np.pi / theta.size)[1:-1]
            dz = np.gradient(np.concatenate([z[-1:], z, z[:1]]), 2 * np.pi / theta.size)[1:-1]
            return 0.5 * np.mean(x * dz - z * dx) * 2 * np.pi

        eps = 1e-3
        exact = width * (area(eps) + area(-eps) - 2 * area(0.0)) / (2 * eps**2)
        assert ours == pytest.approx(exact, rel=1e-5)


def test_inflated_torus_carries_the_membrane_forces():
    """(b) Linear inflation of a thin torus: the membrane forces of Timoshenko & Woinowsky-Krieger to 1.5 %."""
    table = section_checks.torus_check()
    assert table[["error N_theta (%)", "error N_phi (%)"]].abs().to_numpy().max() < 1.5


def test_harmonic_sum_equals_a_direct_three_d_assembly():
    """(e) Receptance of a clamped band under vertical point forces: harmonic sum = 3-D solve to round-off
    (about 3e-12; the bound leaves room for other BLAS builds)."""
    assert section_checks.three_d_check() < 1e-10


def test_the_pneumatic_stiffness_leaves_rigid_rotations_free():
    """Pre-stress and pressure load stiffness each resist a rigid tilt of an inflated ring; together they do not
    (why they always share one law, section_model)."""
    radius, width, h, tension = 0.3, 0.1, 0.002, 2000.0
    mesh = band(radius, width, h)
    inner = radius - h / 2
    stress = np.zeros((mesh.points.element.size, 6))
    stress[:, 1] = tension / (width * h) * inner / radius  # hoop force balancing the pressure on the inner face
    ops = harmonic_operators(mesh, LAW, tension / (radius * width), fixed=np.array([], int), prestress=stress)
    tilt = np.zeros(mesh.n_dof)  # rotation about the horizontal axis: a_r = -y, a_theta = y, a_y = r (n = 1)
    tilt[0::3], tilt[1::3], tilt[2::3] = -mesh.y, mesh.y, mesh.r
    k0, k1, k2 = ops.geometric
    geometric = tilt @ ((k0 + k1 + k2) @ tilt)
    assert abs(tilt @ (ops.pneumatic(1) @ tilt)) < 1e-2 * abs(geometric)
