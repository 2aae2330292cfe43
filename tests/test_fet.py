"""The assembled FET: symmetry, rigid-body modes, mass, and the closed-form ring."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fet import PHI, UX, UZ
from roadnoise_utils.ring import RingParameters, ring_frequencies


def _rigid(fet, kind):
    """Rigid-body displacement of the whole tire (belt and hub)."""
    mesh = fet.mesh
    u = np.zeros(fet.n_dof)
    j, k = np.meshgrid(range(mesh.n_strips), range(mesh.n_elements), indexing="ij")
    x, z = mesh.belt_xz()
    if kind == "rotation":
        u[mesh.dof(j, k, UX)] = -z
        u[mesh.dof(j, k, UZ)] = x
        u[mesh.dof(j, k, PHI)] = 1.0
        u[mesh.hub_dofs[2]] = 1.0
    else:
        c = UX if kind == "x" else UZ
        u[mesh.dof(j, k, c)] = 1.0
        u[mesh.hub_dofs[c]] = 1.0
    return u


def test_dof_count_matches_paper_scale(fet):
    assert fet.n_dof == 9 * 300 * 3 + 3  # the paper's FET had "about 8000" DOF


def test_matrices_symmetric(fet):
    for name, m in [("M", fet.M), ("K_elastic", fet.K_elastic), *fet.K_compound.items()]:
        scale = abs(m).max()
        assert abs(m - m.T).max() <= 1e-12 * scale, name


@pytest.mark.parametrize("kind", ["x", "z", "rotation"])
def test_free_tire_has_three_rigid_body_modes(fet, kind):
    """Translations and the rotation cost no energy: pre-tension and pressure load stiffness balance."""
    u = _rigid(fet, kind)
    k = fet.K(2 * np.pi * 100.0)
    assert np.max(np.abs(k @ u)) <= 1e-10 * abs(fet.K_elastic).max()


def test_total_mass(tire, fet):
    """Translational mass = belt mass per length x chord perimeter + sidewalls."""
    u = _rigid(fet, "z")
    mass = u @ fet.M @ u
    n = tire.mesh.n_elements
    perimeter = 2 * n * tire.geometry.belt_radius * np.sin(np.pi / n)
    assert mass == pytest.approx(tire.belt.mass_per_length * perimeter + tire.foundation.sidewall_mass, rel=1e-12)


def test_stiffness_is_complex_and_passive(fet):
    """Above 0 Hz the rubber adds a positive-semidefinite imaginary (loss) stiffness."""
    k = fet.K(2 * np.pi * 80.0)
    rng = np.random.default_rng(0)
    u = rng.standard_normal(fet.n_dof)
    assert u @ (k.imag @ u) > 0
    assert np.all(fet.K(0.0).imag.data == 0)


def test_closed_form_formula_special_cases():
    """n = 0 torsion and n = 1 translation reduce to the foundation alone."""
    ring = RingParameters(
        radius=0.3, bending_stiffness=5.0, tension=8000.0, k_radial=3e5, k_tangential=5e5, mass_per_length=1.5
    )
    f0, f1 = ring_frequencies([0, 1], ring)
    assert f0 == pytest.approx(np.sqrt(5e5 / 1.5) / (2 * np.pi))
    assert f1 == pytest.approx(np.sqrt((3e5 + 5e5) / (2 * 1.5)) / (2 * np.pi))


def test_ring_matches_closed_form_at_default_mesh(tire):
    table = ru.ring_check(tire, n_max=8)
    assert table["rel_error"].abs().loc[:6].max() < 0.01  # issue: < 1 % for n <= 6
    assert table["rel_error"].abs().max() < 1e-3  # what we actually get up to n = 8


def test_ring_converges_with_mesh(tire):
    """Discretisation error at n = 6 falls by > 10x from 30 to 120 elements (O(h^2))."""
    coarse = ru.ring_check(tire, n_max=6, n_elements=30)["rel_error"].abs()
    fine = ru.ring_check(tire, n_max=6, n_elements=120)["rel_error"].abs()
    assert fine.loc[6] < coarse.loc[6] / 10


def test_ring_needs_the_pressure_load_stiffness(tire, monkeypatch):
    """Without the follower-pressure stiffness the n >= 2 frequencies are far off the closed form."""
    from roadnoise_utils import elements

    original = elements.pressure_load_stiffness
    monkeypatch.setattr(elements, "pressure_load_stiffness", lambda pb: 0 * original(pb))
    table = ru.ring_check(tire, n_max=4, n_elements=120)
    assert table["rel_error"].abs().loc[2:].min() > 0.02
