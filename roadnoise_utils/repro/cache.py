"""On-disk stage cache: results keyed by exactly what they depend on.

Each notebook runs alone on a fresh checkout: when it needs an earlier stage it calls the
cached stage function (:mod:`~roadnoise_utils.repro.stages`), which computes the stage or loads it from here.

* **The key** hashes the stage's name, its *fully resolved* arguments (the tire's every
  parameter, the road, the frequencies, the cleat...; so the contents of every data file a
  stage reads are in it, through the values read), and a fingerprint of the code the stage
  runs: the source of the stage function, of the modules of the numerics it calls and of every
  package module those import (:func:`module_closure`), plus the numpy/scipy/python-control
  versions. Editing a figure module or a notebook invalidates no computed stage; editing the
  static solver invalidates every stage downstream of it.
* **Writes are atomic**: a temporary file renamed into place; a ``*.tmp`` left by a killed
  write is removed the next time that key is computed (or after an hour, by any process).
* **One computation per key**: a per-key file lock (POSIX ``flock``, in ``.locks/``) makes a second process
  wait for the first and then read its result instead of computing the stage again.
* **Data files by their contents**: every data file the computation reads (through
  :func:`~roadnoise_utils.repro.paths.read_toml` and the other readers) is recorded with the
  SHA-256 of its contents in the entry; an entry whose files changed since is stale and
  recomputed. So a stage keyed by a file's *name* (a sweep over road textures or vehicles)
  still follows the file's contents, by construction.
* **Never trusted blindly**: each file carries a SHA-256 of its payload and the key it was
  computed for; a truncated, corrupted or unreadable file, or one holding another key's entry
  (a file renamed or copied by hand), is discarded with a warning and the stage recomputed.
* **The same bits wherever it runs**: a stage computes with the BLAS/LAPACK pools held to one
  thread (threadpoolctl; set by the first stage of a process and kept), as in a dask worker or
  a reproduction kernel, so a result does not depend on which process computed it first (two
  threads sum in another order: 1-2 ulp).
* **Never in the way**: a cache folder that cannot be written (read-only, a full disk, a path
  that is a file) gives a warning and the computed result.
* **Trust**: entries are pickles. The digest detects a truncated or corrupted file, not a
  forged one, and unpickling runs code: point ``ROADNOISE_CACHE_DIR`` only at folders you
  trust, as for any pickle. Files get the permissions of the umask (``0644`` usually), so a
  cache folder can be shared read-only with colleagues.

The folder is ``ROADNOISE_CACHE_DIR`` (default ``<repo>/.cache``); ``ROADNOISE_CACHE=off``
bypasses it. :data:`STATS` counts hits and computations per stage (tests use it).
"""

from __future__ import annotations

import ast
import collections
import contextlib
import dataclasses
import functools
import hashlib
import inspect
import json
import os
import pickle
import tempfile
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from types import ModuleType
from typing import Any, TypeVar

import control
import numpy as np
import scipy
from threadpoolctl import ThreadpoolController

from .. import guards, settings
from .paths import cache_dir, changed_files, recording_reads, replay_reads

T = TypeVar("T")
_MAGIC = b"roadnoise-cache-v3\n"
#: The package folder whose modules the code fingerprints cover.
PACKAGE_DIR = Path(__file__).resolve().parents[1]
PACKAGE = PACKAGE_DIR.name
#: Age (s) after which a temporary file of any key is an orphan of a killed write.
STALE_TMP_AGE = 3600.0
#: ``(stage, "hit" | "computed")`` -> count, in this process.
STATS: collections.Counter = collections.Counter()
#: Stage name -> the modules its fingerprint starts from (those of what it runs), as last called.
STAGE_MODULES: dict[str, tuple[str, ...]] = {}


# ---------------------------------------------------------------- what a stage's code is


def _module_file(name: str, package_dir: Path) -> Path | None:
    """File of a dotted module name of the package (``roadnoise_utils.tire.ring.static``), or None."""
    parts = name.split(".")
    if parts[0] != PACKAGE:
        return None
    base = package_dir.joinpath(*parts[1:])
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def _imports(name: str, path: Path, package_dir: Path) -> set[str]:
    """Package modules imported anywhere in a module (top level or inside functions)."""
    stat = path.stat()  # parsed once per version of the file: every stage's fingerprint walks the same modules
    return set(_parsed_imports(name, path, package_dir, stat.st_mtime_ns, stat.st_size))


@functools.cache
def _parsed_imports(name: str, path: Path, package_dir: Path, mtime_ns: int, size: int) -> frozenset[str]:
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names if alias.name.split(".")[0] == PACKAGE}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                module = ".".join(base + ([node.module] if node.module else []))
            else:
                module = node.module or ""
            if module.split(".")[0] != PACKAGE:
                continue
            for alias in node.names:  # "from .x import y": y may be a module of its own
                sub = f"{module}.{alias.name}"
                found.add(sub if _module_file(sub, package_dir) else module)
    return frozenset(found)


def module_closure(modules: Iterable[str], package_dir: Path = PACKAGE_DIR) -> list[str]:
    """The package modules ``modules`` import, directly or through others, themselves included (sorted)."""
    todo, seen = list(modules), set()
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        path = _module_file(name, package_dir)
        if path is None:
            raise ValueError(f"{name!r} is not a module of {PACKAGE} in {package_dir}")
        seen.add(name)
        todo.extend(_imports(name, path, package_dir) - seen)
    return sorted(seen)


@functools.cache
def code_fingerprint(modules: tuple[str, ...], package_dir: Path = PACKAGE_DIR) -> str:
    """SHA-256 of the sources of ``modules`` and everything they import, and of the numeric libraries' versions."""
    digest = hashlib.sha256(f"numpy {np.__version__} scipy {scipy.__version__} control {control.__version__}".encode())
    for name in module_closure(modules, package_dir):
        digest.update(name.encode())
        digest.update(_module_file(name, package_dir).read_bytes())
    return digest.hexdigest()


def _module_name(item: Callable | ModuleType) -> str:
    return item.__name__ if isinstance(item, ModuleType) else item.__module__


def stage_fingerprint(
    stage: Callable | str, runs: Iterable[Callable | ModuleType] = (), name: str | None = None
) -> str:
    """Fingerprint of a stage's code: its own source and the modules (with their imports) of what it ``runs``."""
    own = inspect.getsource(stage) if callable(stage) else ""
    modules = tuple(sorted({_module_name(item) for item in runs}))
    STAGE_MODULES[name or (stage if isinstance(stage, str) else stage.__name__)] = modules
    return hashlib.sha256((own + code_fingerprint(modules)).encode()).hexdigest()


# ---------------------------------------------------------------- keys


def _normalise(value: Any) -> Any:
    """Turn inputs into JSON-able data that identifies them exactly.

    Dataclasses count by their fields, except those whose metadata says ``identity=False``
    (e.g. where a tire file was read from: the same parameters are the same tire).
    """
    if isinstance(value, np.ndarray):
        arr = np.ascontiguousarray(value)
        return {"ndarray": str(arr.dtype), "shape": arr.shape, "sha256": hashlib.sha256(arr.tobytes()).hexdigest()}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        fields = {f.name: getattr(value, f.name) for f in dataclasses.fields(value) if f.metadata.get("identity", True)}
        return {type(value).__name__: _normalise(fields)}
    if isinstance(value, dict):
        return {str(k): _normalise(v) for k, v in sorted(value.items())}
    if isinstance(value, (list, tuple)):
        return [_normalise(v) for v in value]
    if isinstance(value, (np.floating, float)):
        return repr(float(value))  # exact, and inf/nan safe
    if isinstance(value, (np.integer, int, bool, str)) or value is None:
        return value.item() if isinstance(value, np.generic) else value
    raise TypeError(f"cannot build a cache key from {type(value).__name__}")


def cache_key(stage: str, inputs: dict[str, Any], fingerprint: str = "") -> str:
    """Hex key of a stage, its resolved inputs and the fingerprint of its code."""
    blob = json.dumps({"stage": stage, "inputs": _normalise(inputs), "code": fingerprint}, sort_keys=True)
    return hashlib.sha256(blob.encode()).hexdigest()[:32]


# ---------------------------------------------------------------- files


class _EarlierFormat(Exception):
    """A sound entry of the cache's earlier format (result, data files read), without its key."""


def _read(path: Path) -> Any:
    data = path.read_bytes()
    if not data.startswith(_MAGIC):
        raise ValueError("bad header")
    digest, payload = data[len(_MAGIC) : len(_MAGIC) + 64], data[len(_MAGIC) + 64 :]
    if hashlib.sha256(payload).hexdigest().encode() != digest:
        raise ValueError("checksum mismatch")
    entry = pickle.loads(payload)
    if isinstance(entry, tuple) and len(entry) == 2 and isinstance(entry[1], dict):
        raise _EarlierFormat  # written before entries held their key: recomputed without a word
    if not (isinstance(entry, tuple) and len(entry) == 3 and isinstance(entry[1], dict)):
        raise ValueError("not a (result, data files read, key) entry")
    if entry[2] != path.stem.rsplit("-", 1)[-1]:
        raise ValueError(f"it holds the entry of key {entry[2]!r}, not of its name's")
    return entry[:2]


def _try_read(path: Path) -> tuple[bool, Any]:
    """``(True, value)`` from a sound cache file, ``(False, None)`` if absent or discarded."""
    if not path.exists():
        return False, None
    try:
        return True, _read(path)
    except _EarlierFormat:
        with contextlib.suppress(OSError):
            path.unlink()
        return False, None
    except Exception as exc:  # corrupted, truncated or from an incompatible version
        guards.warn(f"discarding unreadable cache file {path.name} ({exc}); recomputing", stacklevel=3)
        with contextlib.suppress(OSError):
            path.unlink()
        return False, None


def _write(path: Path, value: Any) -> None:
    payload = pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".tmp")
    try:
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; a shared cache needs the usual permissions
        with os.fdopen(fd, "wb") as fh:
            fh.write(_MAGIC + hashlib.sha256(payload).hexdigest().encode() + payload)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


@contextlib.contextmanager
def _key_lock(path: Path) -> Iterator[bool]:
    """Hold an exclusive lock on ``path``'s key; yields whether a lock is held.

    No lock where ``fcntl`` is missing (Windows) or the lock file cannot be created (a
    read-only folder): the stage is then computed without one.
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield False
        return
    try:
        locks = path.parent / ".locks"
        locks.mkdir(exist_ok=True)
        handle = open(locks / path.with_suffix(".lock").name, "a+b")  # noqa: SIM115 - held for the block
    except OSError:
        yield False
        return
    with handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:  # another process computes this key: wait for it (logged, see _timed)
            start = time.perf_counter()
            fcntl.flock(handle, fcntl.LOCK_EX)
            _log_line(
                f"{path.name.split('-', 1)[0]} (waited)", time.perf_counter() - start, path.stem.rsplit("-", 1)[-1]
            )
        try:
            yield True
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def _remove_orphans(path: Path, locked: bool) -> None:
    """Delete temporary files a killed write of this key left (all of them when we hold its lock)."""
    now = time.time()
    for tmp in path.parent.glob(f"{path.name}*.tmp"):
        with contextlib.suppress(OSError):
            if locked or now - tmp.stat().st_mtime > STALE_TMP_AGE:
                tmp.unlink()


@functools.cache
def _sweep_stale(folder: Path) -> None:
    """Once per process and folder: delete temporary files older than :data:`STALE_TMP_AGE`."""
    now = time.time()
    for tmp in folder.glob("*.tmp"):
        with contextlib.suppress(OSError):
            if now - tmp.stat().st_mtime > STALE_TMP_AGE:
                tmp.unlink()


def _usable_folder() -> Path | None:
    folder = cache_dir()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        guards.warn(f"stage cache {folder} cannot be used ({exc}); computing without it", stacklevel=4)
        return None
    _sweep_stale(folder)
    return folder


# ---------------------------------------------------------------- the cache


def cache_enabled() -> bool:
    """Whether the cache is on: ``ROADNOISE_CACHE`` unset or on (``off``/``0``/``false``/``no`` turn it
    off; any other value is an error naming the valid ones)."""
    return settings.flag("ROADNOISE_CACHE", True)


#: Stages computing in this process, and the lock of that count.
_depth = 0
_depth_lock = threading.Lock()


@functools.cache
def _blas() -> ThreadpoolController:
    return ThreadpoolController()


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """BLAS/LAPACK on one thread while a stage computes: set as a stage starts with none running,
    and not lifted after. threadpoolctl's control of OpenBLAS belongs to the thread that first set
    a limit; a limit lifted by one thread while another still computes a stage (or set by a thread
    that does not own it) would let a stage compute on two threads, in another summation order.
    The reproduction's kernels, the test workers and dask's workers run on one thread anyway."""
    global _depth
    with _depth_lock:
        if _depth == 0:
            _blas().limit(limits=1)
        _depth += 1
    try:
        yield
    finally:
        with _depth_lock:
            _depth -= 1


def _timed(name: str, compute: Callable[[], T], key: str = "-") -> T:
    """``compute()`` on one BLAS thread; with ``ROADNOISE_STAGE_LOG`` set, a line appended to that file per stage
    run: the stage's name, its wall time (s), the process id and the cache key (``-`` with the cache off)."""
    start = time.perf_counter()
    with one_blas_thread():
        value = compute()
    _log_line(name, time.perf_counter() - start, key)
    return value


def _log_line(name: str, seconds: float, key: str) -> None:
    """With ``ROADNOISE_STAGE_LOG`` set, append ``name, seconds, process id, key`` to that file (tab-separated).

    A diagnostic never fails a computation: a log that cannot be written is reported once per
    process and file (a warning) and the stage's result is kept.
    """
    log = settings.path("ROADNOISE_STAGE_LOG", None)  # unset or blank: no log
    if log is None:
        return
    try:
        with open(log, "a") as out:
            out.write(f"{name}\t{seconds:.2f}\t{os.getpid()}\t{key}\n")
    except OSError as exc:
        _warn_log_once(str(log), str(exc))


@functools.cache
def _warn_log_once(log: str, reason: str) -> None:
    guards.warn(f"ROADNOISE_STAGE_LOG = {log!r} cannot be written ({reason}): the stages run without their log", 5)


def cached(
    stage: Callable | str,
    inputs: dict[str, Any],
    compute: Callable[[], T],
    runs: Iterable[Callable | ModuleType] = (),
    name: str | None = None,
) -> T:
    """The result of ``stage`` for ``inputs``, from the cache or computed (and stored).

    Parameters
    ----------
    stage : callable or str
        The stage function (its name names the cache files; its source is in the key) or a name.
    name : str, optional
        The stage's name instead of the function's (a tire model's method caching a stage of the
        pipeline, e.g. ``"solve_static"``: :data:`STATS` and the files carry the stage's name).
    inputs : dict
        Every resolved argument the result depends on (numbers, arrays, dataclasses such as
        :class:`~roadnoise_utils.tire.ring.spec.TireSpec`).
    compute : callable
        Computes the result when it is not cached.
    runs : iterable of functions or modules
        The numerics the stage calls: their modules, and every package module those import,
        are fingerprinted into the key.
    """
    name = name or (stage if isinstance(stage, str) else stage.__name__)
    if not cache_enabled():
        STATS[name, "computed"] += 1
        return _timed(name, compute)
    key = cache_key(name, inputs, stage_fingerprint(stage, runs, name))
    folder = _usable_folder()
    if folder is None:
        STATS[name, "computed"] += 1
        return _timed(name, compute)
    path = folder / f"{name}-{key}.pkl"
    found, value = _current(path, name)
    if found:
        return value
    with _key_lock(path) as locked:
        found, value = _current(path, name)  # another process may have written it while we waited
        if found:
            return value
        _remove_orphans(path, locked)
        with recording_reads() as reads:
            value = _timed(name, compute, key)
        STATS[name, "computed"] += 1
        try:
            _write(path, (value, reads, key))
        except OSError as exc:
            guards.warn(f"stage cache not written ({exc}); returning the computed {name}", stacklevel=2)
        return value


def _current(path: Path, name: str) -> tuple[bool, Any]:
    """``(True, value)`` from a sound cache file whose data files are unchanged since it was computed.

    An entry records the contents (digests) of every data file its computation read
    (:func:`~roadnoise_utils.repro.paths.record_read`): a road texture, a vehicle, a tire
    file edited since is a stale entry, recomputed; a current entry's reads pass on to the
    stage around it, so an outer stage's entry records them too.
    """
    found, entry = _try_read(path)
    if not found:
        return False, None
    value, reads = entry
    changed = changed_files(reads)
    if changed:
        STATS[name, "stale"] += 1
        return False, None
    replay_reads(reads)
    STATS[name, "hit"] += 1
    return True, value
