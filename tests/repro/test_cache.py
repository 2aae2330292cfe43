"""Stage cache: keys follow every input and the code a stage runs, writes are atomic, faults never lose a result."""

from __future__ import annotations

import ast
import concurrent.futures
import dataclasses
import multiprocessing
import os
import shutil
import time

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.guards import RoadnoiseWarning
from roadnoise_utils.repro import cache
from roadnoise_utils.tire.ring.spec import SECTIONS, Compound


@pytest.fixture
def cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(tmp_path))
    monkeypatch.delenv("ROADNOISE_CACHE", raising=False)
    return tmp_path


def _all_parameters(spec):
    for section, cls in SECTIONS.items():
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


def test_key_changes_with_options_and_code(tire):
    a = cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0)}, "code")
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(11.0)}, "code")
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0) + 1e-9}, "code")
    assert a != cache.cache_key("modes", {"tire": tire, "freqs": np.arange(10.0)}, "code")
    assert a != cache.cache_key("frf", {"tire": tire, "freqs": np.arange(10.0)}, "edited code")
    # where the tire was read from is not part of its identity
    moved = dataclasses.replace(tire, source="elsewhere.toml")
    assert a == cache.cache_key("frf", {"tire": moved, "freqs": np.arange(10.0)}, "code")


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
    with pytest.warns(RoadnoiseWarning, match="discarding"):
        recomputed = cache.cached("demo", {"x": 1.0}, compute)
    assert len(calls) == 2 and np.array_equal(recomputed["value"], first["value"])
    path.write_bytes(data[: len(data) // 2])  # truncated
    with pytest.warns(RoadnoiseWarning, match="discarding"):
        cache.cached("demo", {"x": 1.0}, compute)
    assert len(calls) == 3
    assert not list(cache_dir.glob("*.tmp"))  # atomic writes leave no temporary files


def test_failed_compute_writes_nothing(cache_dir):
    def boom():
        raise RuntimeError("stage failed")

    with pytest.raises(RuntimeError):
        cache.cached("demo", {"x": 2.0}, boom)
    assert not list(cache_dir.glob("*.pkl")) and not list(cache_dir.glob("*.tmp"))


def test_stage_round_trip(cache_dir, coarse_tire):
    st1 = ru.stages.solve_static(coarse_tire, "flat")
    st2 = ru.stages.solve_static(coarse_tire, "flat")
    assert len(list(cache_dir.glob("solve_static-*.pkl"))) == 1
    assert np.array_equal(st1.contact_force, st2.contact_force)
    other = ru.stages.solve_static(coarse_tire, "flat", load=3000.0)
    assert len(list(cache_dir.glob("solve_static-*.pkl"))) == 2 and other.load == 3000.0


# ---------------------------------------------------------------- faults: nothing lost, nothing in the way


def test_unwritable_cache_warns_and_returns_the_result(tmp_path, monkeypatch):
    """A path that is a file, and a folder that refuses writes (simulated: root ignores permissions)."""
    not_a_folder = tmp_path / "file"
    not_a_folder.write_text("x")
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(not_a_folder))
    monkeypatch.delenv("ROADNOISE_CACHE", raising=False)
    with pytest.warns(RoadnoiseWarning, match="cannot be used"):
        assert cache.cached("demo", {"x": 3.0}, lambda: 42) == 42
    read_only = tmp_path / "read-only"
    read_only.mkdir()
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(read_only))
    if os.geteuid() == 0:  # root writes anyway: make the write itself fail as it would
        monkeypatch.setattr(cache.tempfile, "mkstemp", _refuse)
    else:
        read_only.chmod(0o500)
    try:
        with pytest.warns(RoadnoiseWarning, match="not written"):
            assert cache.cached("demo", {"x": 4.0}, lambda: 43) == 43
    finally:
        read_only.chmod(0o700)
    assert not list(read_only.glob("*.pkl"))


def _refuse(*args, **kwargs):
    raise PermissionError(13, "Permission denied")


def test_orphan_temporary_files_are_removed(cache_dir):
    """A killed write leaves ``<entry>*.tmp``: the next computation of that key deletes it; old ones go anyway."""
    stale = cache_dir / "other-0123.pkl9x.tmp"
    stale.write_bytes(b"half")
    os.utime(stale, (time.time() - 2 * cache.STALE_TMP_AGE,) * 2)
    cache._sweep_stale.cache_clear()
    cache.cached("demo", {"x": 5.0}, lambda: 1)
    assert not stale.exists()
    (entry,) = cache_dir.glob("demo-*.pkl")
    entry.unlink()
    orphan = cache_dir / f"{entry.name}abc.tmp"
    orphan.write_bytes(b"half")  # fresh, but nobody holds the key's lock: an orphan
    assert cache.cached("demo", {"x": 5.0}, lambda: 2) == 2
    assert not orphan.exists() and entry.exists()


def _slow_stage(folder: str, log: str) -> int:
    os.environ["ROADNOISE_CACHE_DIR"] = folder

    def compute() -> int:
        with open(log, "a") as fh:
            fh.write("computed\n")
        time.sleep(1.0)
        return 7

    return cache.cached("locked_demo", {"x": 1.0}, compute)


def test_two_processes_compute_a_stage_once(tmp_path):
    log = tmp_path / "log.txt"
    context = multiprocessing.get_context("fork")
    with concurrent.futures.ProcessPoolExecutor(2, mp_context=context) as pool:
        results = list(pool.map(_slow_stage, [str(tmp_path)] * 2, [str(log)] * 2))
    assert results == [7, 7]
    assert log.read_text().count("computed") == 1


# ---------------------------------------------------------------- what a stage's code is


def test_module_closure_follows_imports_but_not_figures():
    closure = cache.module_closure(["roadnoise_utils.tire.ring.static"])
    assert "roadnoise_utils.tire.ring.mechanics" in closure and "roadnoise_utils.tire.tasselli" in closure
    assert "roadnoise_utils.repro.paths" in closure  # through the tire spec reader
    assert not [m for m in closure if ".figures" in m or ".experiments" in m or ".response" in m]


def test_fingerprints_follow_the_code_each_stage_runs(tmp_path, tire):
    """Editing a figure module changes no stage's fingerprint; editing the static solver changes every stage downstream."""
    ru.stages.solve_static(tire)
    ru.stages.fit_tasselli(tire)
    ru.stages.modal_reduction(tire)
    copy = tmp_path / "roadnoise_utils"
    shutil.copytree(cache.PACKAGE_DIR, copy, ignore=shutil.ignore_patterns("__pycache__"))
    stages = {name: cache.STAGE_MODULES[name] for name in ("solve_static", "fit_tasselli", "modal_reduction")}

    def fingerprints():
        return {name: cache.code_fingerprint(modules, copy) for name, modules in stages.items()}

    before = fingerprints()
    assert before == {name: cache.code_fingerprint(m) for name, m in stages.items()}  # the copy is the package
    for figure in (copy / "figures").glob("*.py"):
        figure.write_text(figure.read_text() + "\n# edited\n")
    (copy / "repro" / "claims.py").write_text((copy / "repro" / "claims.py").read_text() + "\n# edited\n")
    cache.code_fingerprint.cache_clear()
    assert fingerprints() == before
    solver = copy / "tire" / "ring" / "static.py"
    solver.write_text(solver.read_text() + "\n# edited\n")
    cache.code_fingerprint.cache_clear()
    after = fingerprints()
    assert all(after[name] != before[name] for name in stages)
    cache.code_fingerprint.cache_clear()


def test_a_full_disk_warns_and_leaves_no_partial_file(cache_dir, monkeypatch):
    """ENOSPC in the middle of a write: the result is returned, the temporary file removed, nothing trusted later."""

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(cache.os, "fsync", full)
    with pytest.warns(RoadnoiseWarning, match="No space left on device"):
        assert cache.cached("demo", {"x": 9.0}, lambda: 5) == 5
    assert not list(cache_dir.glob("*.tmp")) and not list(cache_dir.glob("*.pkl"))
    monkeypatch.undo()
    monkeypatch.setenv("ROADNOISE_CACHE_DIR", str(cache_dir))
    assert cache.cached("demo", {"x": 9.0}, lambda: 6) == 6  # computed again, then stored
    assert cache.cached("demo", {"x": 9.0}, lambda: 7) == 6


def test_cache_files_are_readable_by_the_group(cache_dir):
    cache.cached("demo", {"x": 10.0}, lambda: 1)
    (entry,) = cache_dir.glob("demo-*.pkl")
    assert entry.stat().st_mode & 0o044 == 0o044 & ~cache._umask()


def test_an_edited_data_file_makes_every_entry_that_read_it_stale(cache_dir, tmp_path):
    texture = tmp_path / "texture.toml"
    texture.write_text("height = 1.0\n")
    calls = []

    def inner():
        calls.append("inner")
        return ru.repro.paths.read_toml(texture)["height"]

    def outer():
        calls.append("outer")
        return 10.0 * cache.cached("inner", {"name": "texture"}, inner)  # keyed by the name only

    assert cache.cached("outer", {"name": "texture"}, outer) == 10.0
    assert cache.cached("outer", {"name": "texture"}, outer) == 10.0 and calls == ["outer", "inner"]
    # the outer entry recomputed over the inner one served from the cache still records the file
    for path in cache_dir.glob("outer-*.pkl"):
        path.unlink()
    assert cache.cached("outer", {"name": "texture"}, outer) == 10.0 and calls == ["outer", "inner", "outer"]
    texture.write_text("height = 4.5\n")  # the same name, new contents
    assert cache.cached("outer", {"name": "texture"}, outer) == 45.0
    assert calls == ["outer", "inner", "outer", "outer", "inner"]
    assert cache.STATS["outer", "stale"] >= 1 and cache.STATS["inner", "stale"] >= 1
    texture.unlink()  # a file gone since is a change too
    with pytest.raises(FileNotFoundError):
        cache.cached("outer", {"name": "texture"}, outer)


def _file_reads(function: ast.FunctionDef) -> list[str]:
    """The calls in ``function`` that read a file: ``open`` for reading, pandas, numpy, pyuff, pycrg, tomllib."""
    found = []
    for node in ast.walk(function):
        if not isinstance(node, ast.Call):
            continue
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        if name == "open":
            mode = (
                node.args[1] if len(node.args) > 1 else next((k.value for k in node.keywords if k.arg == "mode"), None)
            )
            text = mode.value if isinstance(mode, ast.Constant) else "r"
            if isinstance(node.func, ast.Name) and not any(c in text for c in "wax"):
                found.append("open")
            elif isinstance(node.func, ast.Attribute) and ast.unparse(node.func.value).endswith("DataSet"):
                found.append("DataSet.open")
        elif (
            name in ("read_csv", "loadtxt", "read_sets", "load")
            and ast.unparse(node.func).split(".")[0]
            in (
                "pd",
                "np",
                "tomllib",
                "pyuff",
            )
            or name == "read_sets"
        ):
            found.append(name)
    return found


def test_every_reader_of_data_files_records_what_it_reads():
    """So that a cached stage's entry follows the contents of every data file, by construction."""
    readers = 0
    for path in sorted(cache.PACKAGE_DIR.rglob("*.py")):
        if path.name == "cache.py":  # the cache's own files are its payload, not data
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef) and _file_reads(node):
                readers += 1
                calls = {
                    getattr(c.func, "id", getattr(c.func, "attr", ""))
                    for c in ast.walk(node)
                    if isinstance(c, ast.Call)
                }
                assert "record_read" in calls, f"{path.name}:{node.name} reads a file ({_file_reads(node)}) unrecorded"
    assert readers >= 5  # read_toml, the road CSV, OpenCRG, UFF 58 and the footprint CSV at least


def test_an_entry_under_another_key_s_name_is_refused(cache_dir):
    """A file copied or renamed by hand to another key's name would serve the other inputs' result."""
    cache.cached("demo", {"x": 1.0}, lambda: "one")
    (one,) = cache_dir.glob("demo-*.pkl")
    cache.cached("demo", {"x": 2.0}, lambda: "two")
    (two,) = set(cache_dir.glob("demo-*.pkl")) - {one}
    shutil.copy(one, two)
    with pytest.warns(RoadnoiseWarning, match="holds the entry of key"):
        assert cache.cached("demo", {"x": 2.0}, lambda: "two, recomputed") == "two, recomputed"
    assert cache.cached("demo", {"x": 1.0}, lambda: "not called") == "one"


def _blas_threads() -> list[int]:
    from threadpoolctl import threadpool_info

    return [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]


def test_a_stage_computes_on_one_blas_thread_whoever_raised_the_pools_before(cache_dir):
    """The limit is set as a stage starts (and kept: lifting it from one thread while another computes a
    stage would let that stage sum on two threads)."""
    from threadpoolctl import threadpool_limits

    with threadpool_limits(2):
        inside = cache.cached("demo", {"x": 3.0}, lambda: cache.cached("inner", {"y": 1}, _blas_threads))
        after = _blas_threads()
    assert set(inside) == {1} and set(after) == {1}


def test_a_stage_gives_the_same_bits_whatever_blas_threads_its_caller_runs(monkeypatch):
    """Two BLAS threads sum in another order: the loaded state differed by 1-2 ulp (2.4e-8 Pa of a
    0.3 MPa contact pressure) between a caller on two threads and one on one (a dask worker)."""
    from threadpoolctl import threadpool_limits

    monkeypatch.setenv("ROADNOISE_CACHE", "off")
    with threadpool_limits(2):
        two = ru.stages.solve_static("165_65R14")
    with threadpool_limits(1):
        one = ru.stages.solve_static("165_65R14")
    np.testing.assert_array_equal(two.node_pressure, one.node_pressure)
    assert two.deflection == one.deflection


def test_an_entry_of_the_earlier_format_is_recomputed_without_a_warning(cache_dir, recwarn):
    cache.cached("demo", {"x": 4.0}, lambda: "new")
    (path,) = cache_dir.glob("demo-*.pkl")
    cache._write(path, ("old", {}))  # a sound file as written before entries held their key
    assert cache.cached("demo", {"x": 4.0}, lambda: "recomputed") == "recomputed"
    assert not [w for w in recwarn if issubclass(w.category, RoadnoiseWarning)]


@pytest.mark.parametrize("value", ["of", "enabled", " "])
def test_an_unrecognised_cache_setting_is_an_error_naming_the_valid_values(monkeypatch, value):
    monkeypatch.setenv("ROADNOISE_CACHE", value)
    with pytest.raises(ValueError, match="ROADNOISE_CACHE = .*valid values are on/off, 1/0, true/false, yes/no"):
        cache.cached("demo", {"x": 5.0}, lambda: 1)


@pytest.mark.parametrize(("value", "on"), [("OFF", False), ("0", False), ("no", False), ("On", True), ("true", True)])
def test_the_cache_setting_s_valid_values(monkeypatch, value, on):
    monkeypatch.setenv("ROADNOISE_CACHE", value)
    assert cache.cache_enabled() is on


def test_a_stage_log_that_cannot_be_written_warns_once_and_keeps_every_result(cache_dir, monkeypatch, tmp_path):
    monkeypatch.setenv("ROADNOISE_STAGE_LOG", str(tmp_path / "no such folder" / "stages.log"))
    cache._warn_log_once.cache_clear()
    with pytest.warns(RoadnoiseWarning, match="ROADNOISE_STAGE_LOG = .* cannot be written") as record:
        values = [cache.cached("demo", {"x": float(k)}, lambda k=k: k) for k in range(3)]
    assert values == [0, 1, 2] and len([w for w in record if "STAGE_LOG" in str(w.message)]) == 1
