"""The aggregated road simulation against the per-tassello one."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro import stages
from roadnoise_utils.rm import aggregated, simulation
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.road.input import profile_input

TIRE = "195_65R15"


@pytest.fixture(scope="module")
def tire():
    static = stages.solve_static(TIRE)
    sections = simulation.modal_sections(ru.assemble_fixed_hub(stages.fit_tasselli(TIRE)))
    return static, sections


def _rough(seed: int):
    rng = np.random.default_rng(seed)
    x = np.linspace(-2.0, 40.0, 42001)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))
    return x, z


@pytest.mark.parametrize(("speed_kmh", "sample_rate"), [(30.0, 9600.0), (100.0, 12000.0)])
@pytest.mark.parametrize("road", ["2-D", "3-D"])
def test_the_aggregated_hub_force_is_the_per_tassello_simulation(tire, speed_kmh, sample_rate, road):
    """One kernel per track and phase, by FFT, with the inputs before the first sample taken out and
    the start-up state's free response added: the per-tassello simulation of the same road to 1e-10."""
    static, sections = tire
    x, z = _rough(3)
    profile = (lambda s: np.interp(s, x, z)) if road == "2-D" else (lambda s, y: np.interp(s + 5.0 * y, x, z))
    speed = speed_kmh / 3.6
    reference = simulation.simulate(sections, profile_input(static, profile, speed, (0.0, 30.0), sample_rate))
    result = aggregated.road_hub_force(sections, static, profile, speed, (0.0, 30.0), sample_rate)
    assert np.abs(result.force - reference.force).max() < 1e-10 * np.abs(reference.force).max()
    np.testing.assert_array_equal(result.t, reference.t)


def test_the_cleat_on_the_drum_and_a_record_shorter_than_the_memory():
    """The cleat (a road starting flat, then the impact) on the drum, over a record shorter than the
    slowest mode's memory (the impulse responses cut at the record's end)."""
    static = stages.solve_static("165_65R14", "drum", drum_radius=1.25)  # the paper's cleat test
    fits = stages.fit_tasselli("165_65R14", "drum", drum_radius=1.25)
    sections = simulation.modal_sections(ru.assemble_fixed_hub(fits))
    profile = cleat_profile(0.015, 0.015, "triangle")
    speed = 30 / 3.6
    reference = simulation.simulate(sections, profile_input(static, profile, speed, (-0.1, 0.5)))
    result = aggregated.road_hub_force(sections, static, profile, speed, (-0.1, 0.5))
    assert result.t.size < aggregated.memory_length(sections, result.t[1] - result.t[0])
    assert np.abs(result.force - reference.force).max() < 1e-10 * np.abs(reference.force).max()


def test_a_slow_run_is_refused(tire):
    static, sections = tire
    with pytest.raises(ValueError, match="road per step"):
        aggregated.road_hub_force(sections, static, lambda s: 0.0 * s, 0.5, (0.0, 1.0), 9600.0)


def test_a_crawling_road_is_refused_before_allocating(tire):
    """1e-6 m/s over 0.6 m: the estimate of the aggregated simulation's arrays names the cause first."""
    from roadnoise_utils.guards import ResourceLimitError

    static, sections = tire
    with pytest.raises(ResourceLimitError, match="speed and distance: the aggregated simulation"):
        aggregated.road_hub_force(sections, static, lambda s: 0.0 * s, 1e-6, (0.0, 0.6))


def test_many_blocks_read_the_road_once(tire, monkeypatch):
    """Overlap-save blocks far shorter than the record (forced small) give the same force, and every point of
    the fine road grid is read once (the start's few points twice): the memory does not grow with the road."""
    static, sections = tire
    x, z = _rough(4)
    read = []

    def profile(s):
        read.append(s.size)
        return np.interp(s, x, z)

    speed = 60 / 3.6
    reference = aggregated.road_hub_force(sections, static, profile, speed, (0.0, 30.0), 9600.0)
    one_block = sum(read)
    monkeypatch.setattr(aggregated, "block_size", lambda kernel: kernel + 997)  # ~18 blocks
    read.clear()
    blocks = aggregated.road_hub_force(sections, static, profile, speed, (0.0, 30.0), 9600.0)
    assert len(read) > 10 and sum(read) == one_block
    where = ru.road.input.road_grid(static, profile, speed, (0.0, 30.0), 9600.0)
    width = -(-where.parts[0][2].shape[1] // where.oversample)
    assert one_block == where.n_fine + where.oversample * width
    assert np.abs(blocks.force - reference.force).max() < 1e-12 * np.abs(reference.force).max()


def test_the_impulse_responses_are_the_simulation_of_a_unit_sample(tire):
    """g_i + f_i (the start-up state's free response) is what the simulation gives for a unit first sample on input i:
    the sums of exponentials against the per-section IIR filters."""
    _, sections = tire
    dt, n = 1.0 / 9600.0, 3000
    g, f = aggregated.impulse_responses(sections, dt, n)
    for i in (0, 17, sections.n_inputs - 1):
        u = np.zeros((sections.n_inputs, n))
        u[i, 0] = 1.0
        t = dt * np.arange(n)
        reference = simulation.simulate(sections, simulation.RoadInput(t, t, u, 1.0, "unit sample")).force
        assert np.abs(g[i] + f[i] - reference).max() < 1e-10 * np.abs(reference).max()


def test_a_repeated_call_reuses_the_path_and_gives_the_same_force(tire):
    """The second call for the same tire, speed and sample rate takes the kept path (kernels and their spectra)
    and gives the first call's force to the last bit; another speed builds another path."""
    static, sections = tire
    x, z = _rough(5)
    profile = lambda s: np.interp(s, x, z)  # noqa: E731
    aggregated._PATHS.clear()
    first = aggregated.road_hub_force(sections, static, profile, 25.0, (0.0, 8.0), 9600.0)
    assert len(aggregated._PATHS) == 1
    again = aggregated.road_hub_force(sections, static, profile, 25.0, (0.0, 8.0), 9600.0)
    assert len(aggregated._PATHS) == 1
    np.testing.assert_array_equal(first.force, again.force)
    aggregated.road_hub_force(sections, static, profile, 20.0, (0.0, 8.0), 9600.0)
    assert len(aggregated._PATHS) == 2


def test_a_static_state_of_the_wrong_type_is_refused_naming_it(tire):
    _, sections = tire
    with pytest.raises(TypeError, match="static must be a Footprint .* got str"):
        aggregated.road_hub_force(sections, "flat", lambda s: 0.0 * s, 30.0, (0.0, 1.0))
