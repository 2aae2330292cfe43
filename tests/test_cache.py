"""Stage cache: keys follow every input, writes are atomic, corrupted files are recomputed."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from roadnoise_utils import cache, pipeline
from roadnoise_utils.tire_spec import _SECTIONS, Compound


@pytest.fixture
def cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("ROADNOISE_CACHE", raising=False)
    return tmp_path


def _all_parameters(spec):
    for section, cls in _SECTIONS.items():
        for f in dataclasses.fields(cls):
            yield f"{section}.{f.name}", getattr(getattr(spec, section), f.name), f.metadata["range"]
    for name, compound in spec.compounds.items():
        for f in dataclasses.fields(Compound):
            yield f"compounds.{name}.{f.name}", getattr(compound, f.name), f.metadata["range"]


def test_key_changes_when_any_parameter_changes(tire):
    base = cache.cache_key("static", {"tire": tire, "road": "flat"})
    keys = {base}
    count = 0
    for name, value, (lo, hi) in _all_parameters(tire):
        new = value + 1 if isinstance(value, int) else value * 1.01 if value != 0 else 0.1 * hi
        if not lo <= new <= hi:
            new = value - 1 if isinstance(value, int) else value * 0.99
        try:
            changed = tire.replace(**{name: new})
        except ValueError:  # a cross-field rule; any other valid value would do
            continue
        keys.add(cache.cache_key("static", {"tire": changed, "road": "flat"}))
        count += 1
    assert count == len(list(_all_parameters(tire)))  # every parameter could be changed
    assert len(keys) == count + 1  # every change gave its own key


def test_key_changes_with_options_and_code(tire, monkeypatch):
    a = cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0)})
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(11.0)})
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0) + 1e-9})
    assert a != cache.cache_key("modes", {"tire": tire, "freqs": np.arange(10.0)})
    monkeypatch.setattr(cache, "code_fingerprint", lambda: "edited")
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0)})


def test_cached_stage_is_reused_and_corruption_recomputed(cache_dir):
    calls = []

    def compute():
        calls.append(1)
        return {"value": np.arange(5.0)}

    first = cache.cached("demo", {"x": 1.0}, compute)
    again = cache.cached("demo", {"x": 1.0}, compute)
    assert len(calls) == 1 and np.array_equal(first["value"], again["value"])
    (path,) = cache_dir.glob("demo-*.pkl")
    data = path.read_bytes()
    path.write_bytes(data[:-7] + b"garbage")  # same length, wrong checksum
    with pytest.warns(UserWarning, match="discarding"):
        recomputed = cache.cached("demo", {"x": 1.0}, compute)
    assert len(calls) == 2 and np.array_equal(recomputed["value"], first["value"])
    path.write_bytes(data[: len(data) // 2])  # truncated
    with pytest.warns(UserWarning, match="discarding"):
        cache.cached("demo", {"x": 1.0}, compute)
    assert len(calls) == 3
    assert not list(cache_dir.glob("*.tmp"))  # atomic writes leave no temporary files


def test_failed_compute_writes_nothing(cache_dir):
    def boom():
        raise RuntimeError("stage failed")

    with pytest.raises(RuntimeError):
        cache.cached("demo", {"x": 2.0}, boom)
    assert not list(cache_dir.iterdir())


def test_pipeline_stage_round_trip(cache_dir, coarse_tire):
    st1 = pipeline.static_state(coarse_tire, "flat")
    st2 = pipeline.static_state(coarse_tire, "flat")
    assert len(list(cache_dir.glob("static-*.pkl"))) == 1
    assert np.array_equal(st1.contact_force, st2.contact_force)
    other = pipeline.static_state(coarse_tire, "flat", load=3000.0)
    assert len(list(cache_dir.glob("static-*.pkl"))) == 2 and other.load == 3000.0
