"""Cleat test: road input, fast simulation and their properties (paper stage 8)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.road import contact_tracks, texture_input

CAR = "midsize_195_65R15"


def test_road_input_excerpt_and_padding(drum_tire):
    static, _, _ = drum_tire
    road = ru.cleat_input(static, 30 / 3.6)
    part = road.excerpt(10, 10_000)
    assert part.t[0] == 0.0 and part.t.size == road.t.size - 10 and np.array_equal(part.u, road.u[:, 10:])
    long = road.padded(road.t.size + 50)
    assert np.array_equal(long.u[:, : road.t.size], road.u) and not long.u[:, road.t.size :].any()
    assert np.allclose(np.diff(long.distance), road.speed * road.dt) and long.distance[0] == road.distance[0]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"speed": 0.0}, "speed"),
        ({"speed": -3.0}, "speed"),
        ({"speed": 8.0, "sample_rate": 1000.0}, "too coarse"),
        ({"speed": 50.0, "sample_rate": 10000.0}, "road step"),
    ],
)
def test_bad_inputs(flat, kwargs, message):
    with pytest.raises(ValueError, match=message):
        ru.cleat_input(flat, **kwargs)


def test_texture_input_tracks_and_seed(flat):
    """One track per belt strip in contact; the seed fixes the road, another seed changes it."""
    assert np.array_equal(contact_tracks(flat), np.unique(flat.tasselli.node_y))
    spectrum = ru.textures.load_texture("rough")
    a = texture_input(flat, spectrum, 20.0, 0.2, seed=3)
    b = texture_input(flat, spectrum, 20.0, 0.2, seed=3)
    c = texture_input(flat, spectrum, 20.0, 0.2, seed=4)
    assert a.u.shape == (flat.tasselli.n, a.t.size)
    assert np.array_equal(a.u, b.u) and not np.allclose(a.u, c.u)


@pytest.mark.parametrize("speed", [30 / 3.6, 120 / 3.6])
def test_a_2d_road_is_one_correlation_equal_to_the_per_strip_one(flat, speed):
    """A road uniform across the width is correlated once with every strip's kernels; the same road
    given as a 3-D road (``profile(s, y)``, one correlation per strip) gives the same inputs to round-off."""
    from roadnoise_utils.road.input import profile_input

    rng = np.random.default_rng(7)
    x = np.linspace(-1.0, 40.0, 40001)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))
    uniform = profile_input(flat, lambda s: np.interp(s, x, z), speed, (0.0, 30.0))
    per_strip = profile_input(flat, lambda s, y: np.interp(s, x, z), speed, (0.0, 30.0))
    assert np.abs(uniform.u - per_strip.u).max() < 1e-12 * np.abs(per_strip.u).max()
    assert np.unique(flat.tasselli.node_strip).size > 1  # several strips: the per-strip path is a real loop
