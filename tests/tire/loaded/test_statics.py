"""The loaded tire's follower pressure, inflation and flat road, on the small test tire (``conftest``).

The pressure load is the derivative of the pressure's work on the cavity volume and its load
stiffness that of the load; a low pressure inflates the solids as the waveguide tire's linear
inflation; at the file's pressure Newton converges quadratically and the forces balance.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.guards import RoadnoiseWarning
from roadnoise_utils.tire.cross_section.operators import harmonic_operators
from roadnoise_utils.tire.loaded import pressure, road_contact, solid, statics


def _random_free(tire, rng, size):
    v = size * rng.standard_normal(tire.n_dof)
    v[tire.fixed] = 0.0
    return v


def test_the_pressure_load_is_the_work_s_derivative_and_its_stiffness_the_load_s(tire):
    rng = np.random.default_rng(0)
    u, v = _random_free(tire, rng, 1e-3), _random_free(tire, rng, 1.0)
    h = 1e-7
    mesh, surface = tire.mesh, tire.surface
    load = pressure.pressure_load(mesh, surface, u, 1.0)
    d_volume = (pressure.cavity_volume(mesh, surface, u + h * v) - pressure.cavity_volume(mesh, surface, u - h * v)) / (
        2 * h
    )
    assert abs(load @ v / d_volume - 1) < 1e-7
    stiffness = pressure.pressure_stiffness(mesh, surface, u, 1.0)
    fd = (
        pressure.pressure_load(mesh, surface, u + h * v, 1.0) - pressure.pressure_load(mesh, surface, u - h * v, 1.0)
    ) / (2 * h)
    assert np.linalg.norm(stiffness @ v - fd) < 1e-7 * np.linalg.norm(fd)
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    block = stiffness[free][:, free]
    assert abs(block - block.T).max() < 1e-12 * abs(block).max()  # conservative with the beads held
    radial = (mesh.coordinates * np.array([1.0, 0.0, 1.0])).ravel()
    assert pressure.pressure_load(mesh, surface, np.zeros(tire.n_dof), 1.0) @ radial > 0  # pushes outwards


def test_a_low_pressure_inflates_the_solids_as_the_waveguide_tire_s_linear_inflation(tire):
    p = 1e3
    state = statics.inflate(tire, p)
    section = tire.mesh.section
    ops = harmonic_operators(section, tire.spec.laws(), tire.spec.operating.inflation_pressure)
    linear = ops.inflation.reshape(-1, 3) * p / tire.spec.operating.inflation_pressure
    u = state.u.reshape(tire.mesh.theta.size, section.n_nodes, 3)
    theta = tire.mesh.theta[:, None]
    u_r = u[..., 0] * np.sin(theta) - u[..., 2] * np.cos(theta)
    u_t = u[..., 0] * np.cos(theta) + u[..., 2] * np.sin(theta)
    size = np.abs(linear).max()
    assert np.abs(u_t).max() < 1e-9 * size  # axisymmetric: no twist...
    # ... every arc alike (an arc's end and mid rings differ by the arcs' discretisation)
    assert np.abs(u_r[0::2] - u_r[0]).max() < 1e-9 * size and np.abs(u_r[1::2] - u_r[1]).max() < 1e-9 * size
    assert np.abs(u_r - linear[:, 0]).max() < 0.02 * size  # 1.3 % on 6 arcs, 0.26 % on 12
    assert np.abs(u[..., 1] - linear[:, 2]).max() < 0.02 * size


def test_inflation_converges_quadratically_and_balances_the_forces(tire, inflated):
    ((history,),) = inflated.history
    assert history[-1] < statics.TOLERANCE
    tail = [h for h in history if h < 1e-2]
    assert len(tail) >= 2
    for before, after in zip(tail[:-1], tail[1:]):
        assert after < 10 * before**2 or after < 1e-12
    load = pressure.pressure_load(tire.mesh, tire.surface, inflated.u, inflated.pressure).reshape(-1, 3)
    total = load.sum(axis=0) + inflated.reactions.reshape(-1, 3).sum(axis=0)
    assert np.abs(total).max() < 1e-8 * np.abs(load).sum()


def test_a_non_positive_pressure_is_refused(tire):
    with pytest.raises(ValueError, match="inflation pressure"):
        statics.inflate(tire, 0.0)


def test_pressed_on_the_flat_road_the_contact_is_one_sided_symmetric_and_balanced(tire, inflated, loaded):
    assert loaded.road_force > 0.0
    contact = 3 * loaded.contact + 2
    assert np.all(loaded.reactions[contact] >= 0.0)  # the road only pushes...
    road = road_contact.tread_heights(tire, inflated.u).min() + loaded.road_lift
    heights = road_contact.tread_heights(tire, loaded.u)
    np.testing.assert_allclose(heights[np.isin(tire.tread, loaded.contact)], road, rtol=0, atol=1e-12)
    assert heights.min() >= road - 1e-12  # ... and no tread node is below it
    x = tire.mesh.coordinates[loaded.contact, 0]
    np.testing.assert_allclose(np.sort(x), np.sort(-x), atol=1e-12)  # the footprint is symmetric fore and aft
    rim = loaded.reactions[2::3].sum() - loaded.road_force
    assert abs(rim + loaded.road_force) < 1e-9 * loaded.road_force  # the rim carries what the road pushes
    for step in loaded.history:  # on the step's last contact set: quadratic (the constant grows with the
        # cords' compression law, which bends over strains ~1e-4); a step's first entry is the state it
        # starts from, before the road moves (the last step's equilibrium), not one of its iterates
        iterates = step[-1][1:] if len(step) == 1 else step[-1]
        tail = [h for h in iterates if h < 1e-2]
        assert step[-1][-1] < statics.TOLERANCE and all(
            after < 100 * before**2 or after < 1e-12 for before, after in zip(tail[:-1], tail[1:])
        )


def test_the_tangent_vertical_stiffness_is_the_derivative_of_the_road_force(tire, inflated, loaded):
    k_v = road_contact.vertical_stiffness(tire, loaded)
    nudged = road_contact.press_on_road(tire, inflated, loaded.road_lift * (1 + 1e-4), steps=1, start=loaded)
    assert np.array_equal(nudged.contact, loaded.contact)
    secant = (nudged.road_force - loaded.road_force) / (1e-4 * loaded.road_lift)
    assert abs(secant / k_v - 1) < 1e-4


def test_a_road_that_does_not_rise_is_refused(tire, inflated):
    for lift in (0.0, -0.001, float("nan"), "0.005", True):
        with pytest.raises(ValueError, match="lift"):
            road_contact.press_on_road(tire, inflated, lift)


def test_the_loaded_state_does_not_depend_on_the_load_steps(tire, inflated, loaded):
    """Elastic and frictionless: one road step of the whole lift reaches the two steps' equilibrium."""
    one_step = road_contact.press_on_road(tire, inflated, loaded.road_lift, steps=1)
    assert np.array_equal(one_step.contact, loaded.contact)
    assert abs(one_step.road_force / loaded.road_force - 1) < 1e-9
    assert np.abs(one_step.u - loaded.u).max() < 1e-9 * np.abs(loaded.u).max()


def test_started_from_a_guess_the_road_step_reaches_the_same_equilibrium_with_its_contact_set_at_once(
    tire, inflated, loaded
):
    """Newton from the line through the inflated and the loaded state (extrapolated by half) against Newton from
    the loaded state: one equilibrium; the nodes inside the road at the guess held from the first iteration,
    one contact set instead of two, no more iterations (5 against 6 here). A guess that inverts the mesh is
    ignored; one of the wrong size, not finite or with several steps is refused by name."""
    lift = 1.5 * loaded.road_lift
    line = inflated.u + 1.5 * (loaded.u - inflated.u)
    plain, guessed = (
        road_contact.press_on_road(tire, inflated, lift, steps=1, start=loaded, guess=guess) for guess in (None, line)
    )
    assert np.array_equal(guessed.contact, plain.contact)
    assert np.abs(guessed.u - plain.u).max() < 1e-9 * np.abs(plain.u).max()
    assert len(plain.history[-1]) == 2 and len(guessed.history[-1]) == 1  # contact sets tried
    iterations = [sum(len(tries) for tries in state.history[-1]) for state in (plain, guessed)]
    assert iterations[1] <= iterations[0]
    inverting = -2.0 * tire.mesh.coordinates.ravel()  # F = -I: ignored, Newton starts from the loaded state
    ignored = road_contact.press_on_road(tire, inflated, lift, steps=1, start=loaded, guess=inverting)
    assert np.array_equal(ignored.u, plain.u)
    for guess, steps in ((line[:-1], 1), (np.full_like(line, np.nan), 1), (line, 2)):
        with pytest.raises(ValueError, match="guess"):
            road_contact.press_on_road(tire, inflated, lift, steps=steps, start=loaded, guess=guess)


def test_an_inverted_point_is_refused(tire):
    """``det F <= 0`` is no state of a solid: the deformation gradient refuses it instead of giving an energy."""
    reflected = -2.0 * tire.mesh.coordinates.ravel()  # every point to its mirror image through the axle: F = -I
    with pytest.raises(FloatingPointError, match="inverted"):
        solid.deformation_gradient(tire.groups[0], reflected)
    assert np.linalg.det(solid.deformation_gradient(tire.groups[0], -0.4 * tire.mesh.coordinates.ravel())).min() > 0


def test_a_stable_loaded_state_is_recognised_and_a_saddle_is_not(tire, inflated, loaded):
    """At the inflated and the loaded state the tangent is positive definite; the round tire under the
    full pressure (the pressure's load stiffness without the pre-stress it builds) is no minimum."""
    assert loaded.stable is True and road_contact.is_stable(tire, loaded) and road_contact.is_stable(tire, inflated)
    assert not road_contact.is_stable(tire, statics.StaticState(u=np.zeros(tire.n_dof), pressure=inflated.pressure))


def test_a_saddle_reached_by_the_loading_is_reported(tire, inflated, loaded, monkeypatch):
    monkeypatch.setattr(road_contact, "is_stable", lambda tire, state, system=None: False)
    with pytest.warns(RoadnoiseWarning, match="saddle"):
        state = road_contact.press_on_road(tire, inflated, loaded.road_lift, steps=1, start=loaded)
    assert state.stable is False


def test_load_steps_a_lift_that_bottoms_the_tire_or_a_foreign_start_are_refused(tire, inflated, loaded):
    for steps in (0, -1, 2.5, "2"):
        with pytest.raises(ValueError, match="steps"):
            road_contact.press_on_road(tire, inflated, 0.001, steps=steps)
    with pytest.raises(ValueError, match="steps"):
        statics.inflate(tire, steps=0)
    rim = tire.mesh.coordinates[tire.mesh.bead_nodes, 2].min() - road_contact.tread_heights(tire, inflated.u).min()
    assert 0.08 < rim < 0.15  # the 165/65 R14's section height, 107 mm, and the rim's flange
    with pytest.raises(ValueError, match="bottoms"):
        road_contact.press_on_road(tire, inflated, rim)
    softer = statics.StaticState(u=loaded.u, pressure=0.5 * inflated.pressure, road_lift=loaded.road_lift)
    with pytest.raises(ValueError, match="start"):
        road_contact.press_on_road(tire, inflated, 0.006, start=softer)
