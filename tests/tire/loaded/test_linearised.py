"""The loaded tire linearised about its inflated state, on the small test tire (``conftest``).

The nonlinear loaded state tends to the linearised one as the road's lift tends to zero, the
difference first order in the lift (the geometric nonlinearity); the linearised flat road held
at a load and at a lift are one solution; its stiffness is the derivative of its force.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.loaded import linearised, statics


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
    """F_nonlinear / F_linearised - 1 = a h + O(h^2): zero at zero lift, doubled with the lift."""
    excess = []
    for lift in (5e-5, 1e-4, 2e-4):
        linear = linearised.flat_road_at_lift(compliance, lift)
        loaded = statics.press_on_flat_road(tire, inflated, lift, steps=1)
        assert np.array_equal(np.sort(loaded.contact), np.sort(linear.contact))
        excess.append(loaded.road_force / linear.load - 1.0)
    assert abs(excess[0]) < 1e-3
    assert abs(excess[1] / excess[0] - 2.0) < 0.02 and abs(excess[2] / excess[1] - 2.0) < 0.02


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
