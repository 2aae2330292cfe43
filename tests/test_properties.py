"""Property-based tests (hypothesis): linearity and delay invariance of the simulation, superposition
of the road input, finite results for any valid random road, vector fitting recovering random stable
rational functions. Few examples each, so the whole module runs in well under a minute."""

from __future__ import annotations

import control
import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import roadnoise_utils as ru

FEW = settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])

# a stable continuous-time system: lightly damped pairs (Hz, damping ratio) and a direct term
pairs = st.lists(
    st.tuples(st.floats(20.0, 240.0), st.floats(0.005, 0.2)), min_size=1, max_size=4, unique_by=lambda p: round(p[0])
)


def _system(modes, n_inputs=2, seed=0) -> control.StateSpace:
    rng = np.random.default_rng(seed)
    blocks = []
    for f, zeta in modes:
        w = 2 * np.pi * f
        blocks.append(np.array([[-zeta * w, w * np.sqrt(1 - zeta**2)], [-w * np.sqrt(1 - zeta**2), -zeta * w]]))
    a = np.block([[blocks[i] if i == j else np.zeros((2, 2)) for j in range(len(blocks))] for i in range(len(blocks))])
    b = rng.standard_normal((a.shape[0], n_inputs))
    c = rng.standard_normal((1, a.shape[0]))
    return control.ss(a, b, c, rng.standard_normal((1, n_inputs)))


def _road(u: np.ndarray, dt: float = 1e-4) -> ru.RoadInput:
    t = dt * np.arange(u.shape[1])
    return ru.RoadInput(t=t, distance=t, u=u, speed=1.0, description="random")


@FEW
@given(modes=pairs, a=st.floats(-3, 3), b=st.floats(-3, 3), seed=st.integers(0, 2**16))
def test_simulation_is_linear_and_equals_python_control(modes, a, b, seed):
    system = _system(modes, seed=seed)
    rng = np.random.default_rng(seed)
    u1, u2 = rng.standard_normal((2, 2, 400))
    y1, y2 = ru.simulate(system, _road(u1)).force, ru.simulate(system, _road(u2)).force
    both = ru.simulate(system, _road(a * u1 + b * u2)).force
    scale = np.abs(y1).max() + np.abs(y2).max()
    assert np.allclose(both, a * y1 + b * y2, rtol=0, atol=1e-9 * scale * (1 + abs(a) + abs(b)))
    reference = control.forced_response(system, T=_road(u1).t, U=u1).outputs
    assert np.allclose(y1, reference, rtol=0, atol=1e-8 * np.abs(reference).max())


@FEW
@given(modes=pairs, shift=st.integers(1, 150), seed=st.integers(0, 2**16))
def test_simulation_is_delay_invariant(modes, shift, seed):
    system = _system(modes, seed=seed)
    u = np.random.default_rng(seed).standard_normal((2, 300))
    u[:, 0] = 0.0  # from rest: under a first-order hold a jump at the first sample would be a ramp once delayed
    late = np.pad(u, ((0, 0), (shift, 0)))  # the same input, starting later
    y = ru.simulate(system, _road(u)).force
    y_late = ru.simulate(system, _road(late)).force
    assert np.allclose(y_late[shift:], y, rtol=0, atol=1e-9 * np.abs(y).max())
    assert np.allclose(y_late[:shift], 0.0, atol=1e-12 * np.abs(y).max())


@FEW
@given(a=st.floats(-2, 2), b=st.floats(-2, 2), k1=st.floats(2.0, 30.0), k2=st.floats(2.0, 30.0))
def test_the_road_input_superposes(flat, a, b, k1, k2):
    """u[a z1 + b z2] = a u[z1] + b u[z2]: each tassello's input is a weighted average of the road."""
    z1 = lambda s: 1e-3 * np.sin(2 * np.pi * k1 * s)  # noqa: E731
    z2 = lambda s: 1e-3 * np.cos(2 * np.pi * k2 * s)  # noqa: E731
    run = lambda z: ru.road.profile_input(flat, z, 10.0, (0.0, 0.1), oversample=2).u  # noqa: E731
    both = run(lambda s: a * z1(s) + b * z2(s))
    assert np.allclose(both, a * run(z1) + b * run(z2), rtol=0, atol=1e-15)


@FEW
@given(
    seed=st.integers(0, 2**31 - 1),
    speed=st.floats(5.0, 45.0),
    lateral=st.booleans(),
    texture=st.sampled_from(["rough", "smooth"]),
)
def test_any_valid_random_road_gives_finite_inputs(flat, seed, speed, lateral, texture):
    road = ru.road.texture_input(flat, ru.textures.load_texture(texture), speed, 0.05, seed, lateral=lateral)
    assert road.u.shape == (flat.tasselli.n, road.t.size) and np.all(np.isfinite(road.u))
    assert 0 < np.abs(road.u).max() < ru.road.textures.MAX_HEIGHT


@settings(max_examples=20, deadline=None)
@given(modes=pairs, direct=st.floats(-1e3, 1e3), seed=st.integers(0, 2**16))
def test_vector_fitting_recovers_random_stable_rational_functions(modes, direct, seed):
    system = _system(modes, n_inputs=1, seed=seed)
    f = np.arange(0.0, 251.0)
    h = np.asarray(system(2j * np.pi * f)).ravel()
    h = h - system.D[0, 0] + direct
    fit = ru.vector_fit(f, h, n_poles=2 * len(modes))
    assert fit.rms_error < 1e-6
    assert np.all(fit.poles.real < 0)
