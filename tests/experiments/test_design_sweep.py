"""Design sweeps: the table, the per-design cache (resume), failures, serial against dask, properties."""

from __future__ import annotations

import pickle

import numpy as np
import pandas as pd
import pytest

import roadnoise_utils as ru
from roadnoise_utils.experiments import design, design_sweep
from roadnoise_utils.guards import RoadnoiseWarning

PRESSURE = "operating.inflation_pressure"
K_V = "K_v (N/m)"


@pytest.fixture
def fresh_cache(tmp_path, monkeypatch):
    """An empty stage cache for this test (a local cluster's workers inherit it)."""
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


@pytest.fixture
def counted(monkeypatch):
    """Count the designs actually computed in this process (serial sweeps)."""
    calls = []
    original = design.design_outputs

    def counting(spec, outputs, conditions):
        calls.append(spec.operating.inflation_pressure)
        return original(spec, outputs, conditions)

    monkeypatch.setattr(design, "design_outputs", counting)
    return calls


def test_the_table_has_the_parameters_and_outputs_in_si_units(fresh_cache):
    table = ru.experiments.sweep({PRESSURE: [2.0e5, 2.6e5]}, ["K_v"], scheduler="serial", progress=False)
    assert list(table.columns) == [f"{PRESSURE} (Pa)", K_V, "warnings"]
    assert table.index.name == "design" and list(table.index) == [0, 1]
    assert table[f"{PRESSURE} (Pa)"].tolist() == [2.0e5, 2.6e5] and (table["warnings"] == "").all()
    assert table.attrs["computed"] == 2 and table.attrs["from_cache"] == 0 and table.attrs["scheduler"] == "serial"
    assert table.attrs["parameters"] == [f"{PRESSURE} (Pa)"] and table.attrs["outputs"] == [K_V]
    back = pickle.loads(pickle.dumps(table))  # plain numbers and strings, no python-control objects
    pd.testing.assert_frame_equal(back, table)
    assert back.attrs == table.attrs


def test_an_interrupted_sweep_resumes_computing_only_what_is_missing(fresh_cache, counted):
    grid = {PRESSURE: [1.9e5, 2.2e5, 2.5e5]}
    first = ru.experiments.sweep({PRESSURE: grid[PRESSURE][:2]}, ["K_v"], scheduler="serial", progress=False)
    assert counted == [1.9e5, 2.2e5]  # the sweep stopped after two designs
    again = ru.experiments.sweep(grid, ["K_v"], scheduler="serial", progress=False)
    assert counted == [1.9e5, 2.2e5, 2.5e5]  # only the missing design computed
    assert again.attrs["computed"] == 1 and again.attrs["from_cache"] == 2
    pd.testing.assert_frame_equal(again.iloc[:2], first)
    third = ru.experiments.sweep(grid, ["K_v"], scheduler="serial", progress=False)
    assert len(counted) == 3 and third.attrs["computed"] == 0
    ru.experiments.sweep(grid, ["K_v", "footprint"], scheduler="serial", progress=False)
    assert len(counted) == 6  # other outputs: another key


def test_a_failed_design_is_named_and_the_others_are_kept(fresh_cache, monkeypatch, counted):
    original = design.design_outputs

    def failing(spec, outputs, conditions):
        if spec.operating.inflation_pressure == 2.2e5:
            raise FloatingPointError("no convergence")
        return original(spec, outputs, conditions)

    monkeypatch.setattr(design, "design_outputs", failing)
    grid = {PRESSURE: [1.9e5, 2.2e5, 2.5e5]}
    with pytest.raises(
        design_sweep.SweepError,
        match=r"1 of 3 designs failed:\ndesign 1 \(operating.inflation_pressure = 220000\): FloatingPointError: no convergence",
    ) as info:
        ru.experiments.sweep(grid, ["K_v"], scheduler="serial", progress=False)
    assert set(info.value.failures) == {1} and np.isnan(info.value.table.loc[1, K_V])
    recorded = ru.experiments.sweep(grid, ["K_v"], scheduler="serial", progress=False, errors="record")
    assert recorded.loc[1, "error"] == "FloatingPointError: no convergence" and recorded.loc[0, "error"] == ""
    assert recorded.attrs["computed"] == 0  # designs 0 and 2 were cached by the failed sweep
    monkeypatch.setattr(design, "design_outputs", original)
    fixed = ru.experiments.sweep(grid, ["K_v"], scheduler="serial", progress=False)
    assert fixed.attrs["computed"] == 1 and np.isfinite(fixed[K_V]).all()


def test_warnings_are_kept_per_design_and_reported_once(fresh_cache, monkeypatch):
    original = design.design_outputs

    def warning(spec, outputs, conditions):
        ru.guards.warn("doubtful design")
        return original(spec, outputs, conditions)

    monkeypatch.setattr(design, "design_outputs", warning)
    with pytest.warns(RoadnoiseWarning, match="2 of 2 designs gave warnings"):
        table = ru.experiments.sweep({PRESSURE: [2.0e5, 2.6e5]}, ["K_v"], scheduler="serial", progress=False)
    assert (table["warnings"] == "doubtful design").all()
    with pytest.warns(RoadnoiseWarning, match="2 of 2"):  # read back from the cache with its warnings
        again = ru.experiments.sweep({PRESSURE: [2.0e5, 2.6e5]}, ["K_v"], scheduler="serial", progress=False)
    assert again.attrs["computed"] == 0 and (again["warnings"] == "doubtful design").all()


def test_bad_options_are_refused_before_any_work(counted):
    grid = {PRESSURE: [2.0e5]}
    with pytest.raises(ValueError, match=r"errors = 'ignore': valid values are \['raise', 'record'\]"):
        ru.experiments.sweep(grid, ["K_v"], errors="ignore")
    with pytest.raises(ValueError, match="scheduler = 'threads': valid values are None, 'serial'"):
        ru.experiments.sweep(grid, ["K_v"], scheduler="threads")
    with pytest.raises(ValueError, match="n_workers = 0"):
        ru.experiments.sweep(grid, ["K_v"], n_workers=0)
    with pytest.raises(ValueError, match="valid range is"):
        ru.experiments.sweep({PRESSURE: [2.0e5, 6.0e5]}, ["K_v"], scheduler="serial")
    assert counted == []


def test_serial_and_a_dask_cluster_give_the_same_table(tmp_path, monkeypatch):
    """A cluster given by its address (a user's), then by its client: the same table, to the bit, as in
    this process on two BLAS threads (the workers run on one; a stage computes on one wherever it runs)."""
    from distributed import Client, LocalCluster
    from threadpoolctl import threadpool_limits

    grid = {PRESSURE: [2.0e5, 2.6e5], "tread.normal_stiffness_per_area": [1.2e9]}
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path / "serial"))
    with threadpool_limits(2):
        serial = ru.experiments.sweep(grid, ["K_v", "footprint"], scheduler="serial", progress=False)
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path / "dask"))  # the workers compute every stage afresh
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0") as cluster:
        parallel = ru.experiments.sweep(grid, ["K_v", "footprint"], scheduler=cluster.scheduler_address, progress=False)
        assert parallel.attrs["scheduler"] == cluster.scheduler_address and parallel.attrs["computed"] == 2
        assert list((tmp_path / "dask").glob("evaluate_design-*.pkl"))  # the workers wrote the per-design cache
        pd.testing.assert_frame_equal(parallel, serial, check_exact=True)
        with Client(cluster) as client:
            again = ru.experiments.sweep(grid, ["K_v", "footprint"], scheduler=client, progress=False)
            assert again.attrs["computed"] == 0 and client.status == "running"  # the caller's client stays open
        pd.testing.assert_frame_equal(again, serial, check_exact=True)


def test_k_v_rises_and_the_footprint_shortens_with_pressure(fresh_cache):
    pressures = [1.8e5, 2.3e5, 2.8e5]
    table = ru.experiments.sweep({PRESSURE: pressures}, ["K_v", "footprint"], scheduler="serial", progress=False)
    k_v = table[K_V].to_numpy()
    assert np.all(np.diff(k_v) > 0.05 * k_v[0])  # the pneumatic foundation scales with p (ring model)
    assert np.all(np.diff(table["footprint_length (m)"]) < 0)
    assert 170e3 <= k_v[1] <= 220e3  # the paper tire at its own pressure: the calibration target (N/m)


def test_a_latin_hypercube_sample_is_seeded_and_stratified():
    ranges = {PRESSURE: (2.0e5, 2.6e5), "belt.bending_stiffness": (3.0, 8.0)}
    first, again = design_sweep.sample(ranges, 8, seed=3), design_sweep.sample(ranges, 8, seed=3)
    pd.testing.assert_frame_equal(first, again)
    assert not first.equals(design_sweep.sample(ranges, 8, seed=4))
    for name, (lo, hi) in ranges.items():
        bins = np.floor((first[name] - lo) / (hi - lo) * 8).astype(int)
        assert sorted(bins) == list(range(8)), name  # one design in each eighth of every range
    with pytest.raises(ValueError, match="n = 0"):
        design_sweep.sample(ranges, 0)
    assert len(design.make_designs("165_65R14", first)) == 8  # a sample is a sweep's parameters


def test_effects_are_the_relative_changes_across_each_parameter_the_others_held():
    grid = pd.DataFrame({"a (m)": [1.0, 1.0, 2.0, 2.0], "b (Pa)": [10.0, 20.0, 10.0, 20.0]})
    table = grid.assign(**{"y (N)": grid["a (m)"] ** 2 * grid["b (Pa)"]})  # y = a^2 b
    found = design_sweep.effects(table, ["a (m)", "b (Pa)"], ["y (N)"])
    assert list(found.index) == ["a (m): 1 -> 2", "b (Pa): 10 -> 20"]
    np.testing.assert_allclose(found["y (N)"], [3.0, 1.0])  # 2^2 - 1 and 2 - 1
    scattered = table.assign(**{"b (Pa)": [10.0, 20.0, 15.0, 25.0]})  # no pair shares b
    assert np.isnan(design_sweep.effects(scattered, ["a (m)", "b (Pa)"], ["y (N)"]).loc["a (m): 1 -> 2", "y (N)"])


def test_the_default_cluster_workers_keep_glibc_s_own_trim_threshold():
    """distributed's 64 KiB MALLOC_TRIM_THRESHOLD_ made every design ~1.6x slower in a worker (each frequency's
    sparse factorisation faulting its pages in again); the default cluster's workers run without it, one BLAS
    thread each unless the environment asks for more (OMP_NUM_THREADS, kept as the user's own)."""
    import os

    from roadnoise_utils.experiments import design_sweep

    client, cluster = design_sweep._client(None, 1)
    try:
        seen = client.run(lambda: (os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OMP_NUM_THREADS")))
    finally:
        client.close()
        cluster.close()
    assert list(seen.values()) == [(None, os.environ.get("OMP_NUM_THREADS", "1"))]


def test_a_warning_from_elsewhere_in_the_process_is_not_the_design_s(fresh_cache, monkeypatch):
    """A file collected during a design (a ResourceWarning) or a library's deprecation is not kept as the design's
    warning; the design's own (a RoadnoiseWarning) is."""
    import warnings

    original = design.design_outputs

    def noisy(spec, outputs, conditions):
        warnings.warn("unclosed file", ResourceWarning, stacklevel=2)
        warnings.warn("old call", DeprecationWarning, stacklevel=2)
        if spec.operating.inflation_pressure == 2.2e5:
            ru.guards.warn("a doubtful fit")
        return original(spec, outputs, conditions)

    monkeypatch.setattr(design, "design_outputs", noisy)
    with pytest.warns(ru.guards.RoadnoiseWarning, match="1 of 2 designs gave warnings"):
        table = ru.experiments.sweep({PRESSURE: [1.9e5, 2.2e5]}, ["K_v"], scheduler="serial", progress=False)
    assert table["warnings"].tolist() == ["", "a doubtful fit"]
