"""The FMU's tables: the road taps reproduce the footprint's own correlation, the file reads back, bad tires are refused."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fmu.tables import read_tables, road_taps, tire_tables, write_tables
from roadnoise_utils.road.input import profile_input

from .conftest import SPEED, knots


@pytest.fixture(scope="module")
def paper():
    tire = "165_65R14"
    return ru.stages.solve_static(tire), ru.stages.fit_tasselli(tire), ru.stages.fit_hub(tire)


def tassello_inputs(tables, heights: np.ndarray) -> np.ndarray:
    """Each tassello's displacement from the taps, the road level with the first sample before it (as the FMU)."""
    n = heights.shape[1]
    u = np.zeros((tables.n_tasselli, n))
    for strip, tassello, weights in zip(tables.row_strip, tables.row_tassello, tables.taps):
        padded = np.concatenate([np.full(weights.size - 1, heights[strip, 0]), heights[strip]])
        u[tassello] += np.convolve(padded, weights, mode="valid")
    return u


@pytest.mark.parametrize("lateral", [False, True])
def test_taps_are_the_footprints_correlation_of_a_road_linear_between_samples(paper, lateral):
    """Second method: profile_input correlates the kernels with the road on its own grid; the taps must give the
    same displacements for a road linear between the leading-edge samples (the FMU's road), to round-off."""
    static, fits, hub = paper
    tables = tire_tables(fits, hub, static, SPEED, lateral=lateral)
    n = 800
    heights = np.cumsum(np.random.default_rng(3).normal(size=(tables.n_strips, n)), axis=1) * 1e-4
    s = knots(tables, n)
    if lateral:
        assert tables.n_strips == np.unique(static.tasselli.node_strip).size > 1

        def profile(x, y):
            return np.interp(x, s, heights[int(np.argmin(np.abs(tables.strip_y - y)))])
    else:

        def profile(x):
            return np.interp(x, s, heights[0])

    expected = profile_input(static, profile, SPEED, (-0.1, -0.1 + SPEED * tables.dt * (n - 1)), 1 / tables.dt).u
    assert np.max(np.abs(tassello_inputs(tables, heights) - expected)) <= 1e-12 * np.max(np.abs(expected))


def test_a_level_road_moves_every_tassello_by_its_height(paper):
    """Closed form: each tassello's kernel integrates to one, so its taps over every strip sum to one."""
    static, fits, hub = paper
    for lateral in (False, True):
        tables = tire_tables(fits, hub, static, SPEED, lateral=lateral)
        sums = np.bincount(tables.row_tassello, weights=tables.taps.sum(axis=1), minlength=tables.n_tasselli)
        np.testing.assert_allclose(sums, 1.0, rtol=1e-12)


def test_the_leading_edge_is_ahead_of_every_tassello(paper):
    static, fits, hub = paper
    tables = tire_tables(fits, hub, static, SPEED)
    front = np.max(static.tasselli.node_x + static.tasselli.node_dx_plus)
    assert front <= tables.leading_edge < front + 3 * SPEED * tables.dt / 4


def test_sections_are_the_moving_hub_model(paper):
    """The sections' states count the moving-hub model's (Eq. 7), the hub's sections are driven by the last input."""
    static, fits, hub = paper
    tables = tire_tables(fits, hub, static, SPEED)
    model = ru.rm.assemble_moving_hub(fits, hub)
    assert tables.n_states == model.nstates
    assert tables.n_tasselli == static.tasselli.n
    hub_states = ru.rm.hub_statespace(hub).nstates
    on_hub = tables.source == tables.n_tasselli
    assert np.sum(np.where(tables.factor[on_hub] == 2.0, 2, 1)) == hub_states
    np.testing.assert_array_equal(tables.direct, np.asarray(model.D)[0])


def test_the_file_reads_back_identical(paper, tmp_path):
    static, fits, hub = paper
    tables = tire_tables(fits, hub, static, SPEED, lateral=True)
    write_tables(tables, tmp_path / "tire.bin", "{guid-of-the-fmu}")
    back, guid = read_tables(tmp_path / "tire.bin")
    assert guid == "{guid-of-the-fmu}"
    for field in dataclasses.fields(tables):
        np.testing.assert_array_equal(getattr(back, field.name), getattr(tables, field.name), err_msg=field.name)


def test_a_damaged_file_is_refused(paper, tmp_path):
    static, fits, hub = paper
    write_tables(tire_tables(fits, hub, static, SPEED), tmp_path / "tire.bin", "{g}")
    data = (tmp_path / "tire.bin").read_bytes()
    (tmp_path / "cut.bin").write_bytes(data[:-20])
    with pytest.raises(ValueError, match="truncated"):
        read_tables(tmp_path / "cut.bin")
    (tmp_path / "long.bin").write_bytes(data[:-8] + b"12345678" + data[-8:])
    with pytest.raises(ValueError, match="more than its header"):
        read_tables(tmp_path / "long.bin")
    (tmp_path / "guid.bin").write_bytes(data[:32] + b"\xff" * 64 + data[96:])
    with pytest.raises(ValueError, match="GUID field is not ASCII"):
        read_tables(tmp_path / "guid.bin")
    with pytest.raises(ValueError, match="at most 63 ASCII"):
        write_tables(tire_tables(fits, hub, static, SPEED), tmp_path / "tire.bin", "g" * 64)


@pytest.mark.parametrize("speed", [0.0, -1.0, float("nan"), 101.0, "10", True])
def test_speed_outside_its_range_is_refused(paper, speed):
    static, fits, hub = paper
    with pytest.raises(ValueError, match="speed"):
        tire_tables(fits, hub, static, speed)


def test_sampling_that_cannot_carry_the_band_is_refused(paper):
    static, fits, hub = paper
    with pytest.raises(ValueError, match="sample_rate"):
        tire_tables(fits, hub, static, SPEED, sample_rate=500.0)
    with pytest.raises(ValueError, match="road step"):
        tire_tables(fits, hub, static, 30.0, sample_rate=5000.0)
    with pytest.raises(ValueError, match="m of road per step"):
        tire_tables(fits, hub, static, 0.5, sample_rate=9600.0)


def test_an_unstable_fit_is_refused_naming_its_input(paper):
    static, fits, hub = paper
    bad = fits.fits[5]
    poles = bad.poles.copy()
    poles[0] = complex(abs(poles[0].real), poles[0].imag)
    poles[1] = np.conj(poles[0])
    unstable = dataclasses.replace(fits, fits=[*fits.fits[:5], dataclasses.replace(bad, poles=poles), *fits.fits[6:]])
    with pytest.raises(ValueError, match=r"tassello 5 has a pole with real part .* >= 0"):
        tire_tables(unstable, hub, static, SPEED)


def test_wrong_types_are_refused(paper):
    static, fits, hub = paper
    with pytest.raises(TypeError, match="static"):
        tire_tables(fits, hub, "flat", SPEED)
    with pytest.raises(TypeError, match="hub"):
        tire_tables(fits, [hub], static, SPEED)
    with pytest.raises(ValueError, match="lateral"):
        tire_tables(fits, hub, static, SPEED, lateral="yes")
    with pytest.raises(ValueError, match="tasselli"):
        tire_tables(dataclasses.replace(fits, fits=fits.fits[:3]), hub, static, SPEED)


def test_taps_cover_the_footprint_at_any_speed(paper):
    """The number of taps is the footprint's length in steps of road (plus the hat's two ends)."""
    static, *_ = paper
    length = np.ptp(np.concatenate([static.tasselli.node_x - static.tasselli.node_dx_minus,
                                    static.tasselli.node_x + static.tasselli.node_dx_plus]))  # fmt: skip
    for speed in (2.0, 8.0, 33.0):
        _, _, n_taps, _ = road_taps(static, speed, 1e-4, False)
        assert length / (speed * 1e-4) <= n_taps <= length / (speed * 1e-4) + 3
