"""Contact of the loaded tire with a drum: frictionless and one-sided with a cylinder, on the model's test mesh.

Checked by a second method each: the contact nodes lie on the drum and its forces on them are
normal to it (frictionless) and push (one-sided); the rim and the drum balance; the iterations
converge quadratically (the constraint's curvature in the tangent); the tangent K_v is the
derivative of the road force; the drum tends to the flat road as its radius grows, the difference
falling like 1/R (the drum's drop x^2 / 2R under the footprint); and at rest the linearised
footprint's transfer is K_v.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.loaded import dynamics, loading, road_contact, statics
from roadnoise_utils.tire.loaded.direct import footprint_frf_direct
from roadnoise_utils.tire.surface import make_road

DRUM = make_road("drum", 1.25)


@pytest.fixture(scope="module")
def on_drum(model_tire, model_inflated, model_state):
    """The test mesh on the paper's 1.25 m drum, raised as far as the flat road's state at 1 kN."""
    return road_contact.press_on_road(model_tire, model_inflated, model_state.road_lift, DRUM, steps=1)


def test_on_the_drum_the_nodes_lie_on_it_and_its_forces_push_along_its_normal(model_tire, on_drum):
    contact = road_contact.contact_of(model_tire, on_drum)
    gaps, normals = contact.gaps_and_normals(model_tire.tread, on_drum.u)
    held = np.isin(model_tire.tread, on_drum.contact)
    assert np.abs(gaps[held]).max() < 1e-12 and gaps[~held].min() > -1e-12  # on the drum, none inside it
    # the tire's out-of-balance force at each contact node, computed afresh (not the stored reactions,
    # which hold the normal component alone by construction): the drum's force, along its normal
    residual, _ = statics.residual_and_tangent(model_tire, on_drum.u, on_drum.pressure)
    force = residual.reshape(-1, 3)[on_drum.contact]
    n = normals[held][np.argsort(model_tire.tread[held])]  # tread order -> contact (sorted) order
    along = force[:, 0] * n[:, 0] + force[:, 2] * n[:, 1]
    across = force[:, 0] * n[:, 1] - force[:, 2] * n[:, 0]
    assert np.all(along > 0) and np.abs(across).max() < 1e-9 * along.max()  # pushing, frictionless
    assert np.abs(force[:, 1]).max() < 1e-9 * along.max()  # nothing along the axle either
    assert np.abs(np.ptp(n[:, 0])) > 0.02  # the normals do turn over the footprint: the check is not vacuous
    total = on_drum.reactions.reshape(-1, 3).sum(axis=0)  # the rim's and the drum's forces on the tire...
    assert np.abs(total).max() < 1e-8 * on_drum.road_force  # ... balance (no other load but the pressure's)
    x = model_tire.mesh.coordinates[on_drum.contact, 0]
    np.testing.assert_allclose(np.sort(x), np.sort(-x), atol=1e-12)


def test_on_the_drum_newton_converges_quadratically(on_drum):
    for step in on_drum.history[1:]:
        iterates = step[-1][1:] if len(step) == 1 else step[-1]
        tail = [h for h in iterates if h < 1e-2]
        assert step[-1][-1] < 1e-9 and all(
            after < 100 * before**2 or after < 1e-12 for before, after in zip(tail, tail[1:])
        )


def test_on_the_drum_the_tangent_stiffness_is_the_derivative_of_the_road_force(model_tire, model_inflated, on_drum):
    lift = on_drum.road_lift * 1e-4
    raised = road_contact.press_on_road(model_tire, model_inflated, on_drum.road_lift + lift, DRUM, 1, on_drum)
    assert np.array_equal(raised.contact, on_drum.contact)
    k_v = road_contact.vertical_stiffness(model_tire, on_drum)
    assert abs((raised.road_force - on_drum.road_force) / lift / k_v - 1) < 1e-3  # first order in the lift


def test_the_drum_tends_to_the_flat_road_like_one_over_its_radius(model_tire, model_inflated, model_state, on_drum):
    larger = road_contact.press_on_road(
        model_tire, model_inflated, model_state.road_lift, make_road("drum", 5.0), steps=1
    )
    flat = model_state.road_force
    assert on_drum.road_force < larger.road_force < flat  # the drum's drop under the footprint unloads it
    assert 3.0 < (flat - on_drum.road_force) / (flat - larger.road_force) < 5.0  # 4: the radii's ratio


@pytest.fixture(scope="module")
def drum_direct(model_tire, on_drum):
    """The drum state linearised, and its footprint transfer by the direct solve at 0, 60 and 120 Hz."""
    linearised = dynamics.linearise(model_tire, on_drum)
    return linearised, footprint_frf_direct(linearised, np.array([0.0, 60.0, 120.0]))


def test_at_rest_the_drum_footprint_s_transfer_is_its_vertical_stiffness(model_tire, on_drum, drum_direct):
    _, direct = drum_direct
    k_v = road_contact.vertical_stiffness(model_tire, on_drum)
    assert abs(direct.H_tot[0] / k_v - 1) < 1e-9 and abs(direct.G_H[0] / k_v + 1) < 1e-9


def test_on_the_drum_the_reduced_solve_is_the_direct_one(drum_direct):
    """The reduced basis with the drum's slide on the curvature term: within 1e-3 of the direct solve."""
    linearised, direct = drum_direct
    reduced = dynamics.footprint_frf(linearised, direct.freqs)
    assert np.abs(reduced.hub - direct.hub).max() < 1e-3 * np.abs(direct.hub).max()
    assert abs(reduced.H_tot[0] / direct.H_tot[0] - 1) < 1e-9


def test_a_load_case_on_the_drum_is_carried_exactly(model_tire, model_inflated, on_drum):
    """From the drum's state a little further, to a load 2 % above its force (the secant's step, then
    Brent's method); a start on another road is refused."""
    load = 1.02 * on_drum.road_force
    state = loading.load_on_road(model_tire, model_inflated, load, 0.007, DRUM, start=on_drum)
    assert abs(state.road_force / load - 1) < loading.LOAD_TOLERANCE and state.road is DRUM and state.stable
    with pytest.raises(ValueError, match="stands on the drum road, not on the flat road"):
        loading.load_on_road(model_tire, model_inflated, load, 0.007, start=on_drum)
