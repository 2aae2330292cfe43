"""The assembled FET: symmetry, rigid-body modes, mass, and the closed-form ring."""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.ring.mechanics import PHI, UX, UZ


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
    assert np.max(np.abs(k @ u)) <= 1e-10 * abs(k).max()


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
