"""The assembled FET: symmetry, rigid-body modes, mass, and the closed-form ring."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.ring_theory import RingParameters, ring_frequencies


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
    from roadnoise_utils.tire.ring import elements

    original = elements.pressure_load_stiffness
    monkeypatch.setattr(elements, "pressure_load_stiffness", lambda pb: 0 * original(pb))
    table = ru.ring_check(tire, n_max=4, n_elements=120)
    assert table["rel_error"].abs().loc[2:].min() > 0.02


def test_the_edge_zone_wavenumber_is_the_beam_on_springs_closed_form():
    """beta = (k b / 4 EI)^(1/4): eight times the bending stiffness, beta / 8^(1/4); sixteen times the
    tread stiffness, twice beta."""
    from roadnoise_utils.tire.ring.closed_form import edge_zone_wavenumber

    spec = ru.load_tire("165_65R14")
    beta = edge_zone_wavenumber(spec)
    stiffer_belt = spec.replace(**{"belt.bending_stiffness": 8 * spec.belt.bending_stiffness})
    stiffer_tread = spec.replace(**{"tread.normal_stiffness_per_area": 16 * spec.tread.normal_stiffness_per_area})
    assert edge_zone_wavenumber(stiffer_belt) == pytest.approx(beta / 8**0.25, rel=1e-12)
    assert edge_zone_wavenumber(stiffer_tread) == pytest.approx(2 * beta, rel=1e-12)
