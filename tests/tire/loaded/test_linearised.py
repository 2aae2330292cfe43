"""The loaded tire linearised about its inflated state, on the small test tire (``conftest``).

The nonlinear loaded state tends to the linearised one as the road's lift tends to zero, the
difference first order in the lift (the geometric nonlinearity); the linearised flat road held
at a load and at a lift are one solution; its stiffness is the derivative of its force.
Linearised as the waveguide tire (about the round tire, pre-stressed by the linear inflation),
the solids have the waveguide tire's inflated frequencies, converging at h^4 around the arcs.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from roadnoise_utils.tire.cross_section.checks import harmonic_frequencies
from roadnoise_utils.tire.cross_section.operators import harmonic_operators
from roadnoise_utils.tire.loaded import linearised, road_contact, solid, statics


@pytest.fixture(scope="module")
def compliance(tire, inflated):
    return linearised.contact_compliance(tire, inflated)


def test_the_compliance_is_symmetric_positive_and_the_tangent_s_inverse(tire, inflated, compliance):
    c = compliance.matrix
    assert np.all(np.linalg.eigvalsh(c) > 0)
    _, k = statics.residual_and_tangent(tire, inflated.u, inflated.pressure)
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    force = np.zeros(tire.n_dof)
    force[3 * compliance.nodes[0] + 2] = 1.0  # a unit force on one node: K u = f, the rim held
    u = np.zeros(tire.n_dof)
    u[free] = np.linalg.solve(k[free][:, free].toarray(), force[free])
    np.testing.assert_allclose(c[:, 0], u[3 * compliance.nodes + 2], rtol=1e-9, atol=1e-9 * c[0, 0])
    assert compliance.gap.min() == 0.0 and compliance.gap.max() < compliance.depth


def test_the_nonlinear_state_tends_to_the_linearised_one_at_first_order_in_the_lift(tire, inflated, compliance):
    """F_nonlinear / F_linearised - 1 = a h + b h^2 + O(h^3): zero at zero lift, with one slope ``a``.

    Richardson's extrapolation from the lifts (h, 2h) and from (2h, 4h), ``2 x(h) / h - x(2h) / 2h``,
    gives ``a`` to O(h^2) from both. The cords compressed at the inflated state (under the belts and
    at their edges) bend the curve within strains of their buckling strain, ~1e-4, so the lifts
    are small: 12.5-50 um."""
    excess = []
    lifts = (1.25e-5, 2.5e-5, 5e-5)
    for lift in lifts:
        linear = linearised.flat_road_at_lift(compliance, lift)
        loaded = road_contact.press_on_road(tire, inflated, lift, steps=1)
        assert np.array_equal(np.sort(loaded.contact), np.sort(linear.contact))
        excess.append(loaded.road_force / linear.load - 1.0)
    assert abs(excess[0]) < 1e-3
    slope = [e / h for e, h in zip(excess, lifts)]
    from_small, from_large = 2 * slope[0] - slope[1], 2 * slope[1] - slope[2]
    assert abs(from_large / from_small - 1.0) < 0.01


def test_held_at_a_load_and_at_its_lift_the_linearised_road_is_one_solution(compliance):
    at_load = linearised.flat_road_at_load(compliance, 300.0)
    at_lift = linearised.flat_road_at_lift(compliance, at_load.deflection)
    assert abs(at_lift.load / 300.0 - 1.0) < 1e-9
    np.testing.assert_array_equal(at_lift.contact, at_load.contact)
    assert np.all(at_load.forces >= 0.0)
    assert abs(at_lift.stiffness / at_load.stiffness - 1.0) < 1e-9
    nudged = linearised.flat_road_at_lift(compliance, at_load.deflection * (1 + 1e-6))
    secant = (nudged.load - at_lift.load) / (1e-6 * at_load.deflection)
    assert abs(secant / at_lift.stiffness - 1.0) < 1e-5


def test_a_contact_beyond_the_candidates_or_a_non_positive_load_is_refused(tire, inflated, compliance):
    shallow = linearised.contact_compliance(tire, inflated, depth=0.002)
    with pytest.raises(ValueError, match="larger depth"):
        linearised.flat_road_at_lift(shallow, 0.0015)
    with pytest.raises(ValueError, match="load"):
        linearised.flat_road_at_load(compliance, -1.0)
    with pytest.raises(ValueError, match="depth"):
        linearised.contact_compliance(tire, inflated, depth=float("nan"))


def _lowest_frequencies(tire, stiffness, count):
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    mass = solid.mass_matrix(tire.groups, tire.n_dof)[free][:, free].tocsc()
    values = spla.eigsh(stiffness[free][:, free].tocsc(), k=count, M=mass, sigma=0.0, return_eigenvectors=False)
    return np.sort(np.sqrt(values)) / (2 * np.pi)


def test_linearised_as_the_waveguide_the_inflated_solids_have_its_frequencies(tire):
    """The two lowest modes of n = 0 and of n = 1 (each a pair) at the file's pressure: within 0.2 % on
    6 arcs, 16x closer on 12 (h^4); the waveguide's own eigenproblem per harmonic is the reference."""
    ops = harmonic_operators(tire.mesh.section, tire.spec.laws(), tire.spec.operating.inflation_pressure)
    (n0_first, n0_second), (n1_first, n1_second) = (harmonic_frequencies(ops, n)[:2] for n in (0, 1))
    reference = np.array([n0_first, n1_first, n1_first, n0_second, n1_second, n1_second])
    assert np.all(np.diff(reference) >= 0)  # the order the solids' sorted frequencies take
    errors = []
    for n_arcs in (6, 12):
        swept = tire if n_arcs == 6 else statics.build_loaded_tire(tire.spec, np.linspace(-np.pi, np.pi, n_arcs + 1))
        rounded = linearised.round_linearisation(swept)
        errors.append(np.abs(_lowest_frequencies(swept, rounded.tangent, 6) / reference - 1).max())
    assert errors[0] < 2e-3 and errors[1] < errors[0] / 10


def test_the_round_linearisation_s_pre_stress_is_linear_in_the_pressure(tire):
    """Twice the pressure, twice the inflation and twice the pre-stress and pressure stiffness."""
    one, two = linearised.round_linearisation(tire, 1.0e5), linearised.round_linearisation(tire, 2.0e5)
    elastic = solid.prestressed_tangent(tire.groups, np.zeros(tire.n_dof), tire.n_dof)
    np.testing.assert_allclose(two.inflation, 2 * one.inflation, rtol=0, atol=1e-12 * np.abs(two.inflation).max())
    pneumatic_one, pneumatic_two = one.tangent - elastic, two.tangent - elastic
    assert abs(pneumatic_two - 2 * pneumatic_one).max() < 1e-9 * abs(pneumatic_two).max()
