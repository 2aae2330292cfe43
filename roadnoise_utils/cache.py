"""On-disk stage cache: results keyed by a hash of every input that matters.

Each notebook runs alone on a fresh checkout: when it needs an earlier stage it calls the
pipeline function (:mod:`.pipeline`), which computes the stage or loads it from here.

* The key hashes the stage name, all its inputs (tire parameters, road, frequencies, options)
  and a fingerprint of the package source, so editing the code invalidates old results.
* Files are written to a temporary file and renamed (atomic on POSIX and Windows), so a
  crash never leaves a half-written entry.
* Each file carries a SHA-256 of its payload; a file that is truncated, corrupted or
  unreadable is discarded and the stage recomputed, never trusted.

The folder is ``ROADNOISE_CACHE_DIR`` (default ``<repo>/.cache``); set
``ROADNOISE_CACHE=off`` to bypass it.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
import os
import pickle
import tempfile
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

from .paths import cache_dir

T = TypeVar("T")
_MAGIC = b"roadnoise-cache-v1\n"


@functools.lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """SHA-256 of the package's source files (changes whenever the code does)."""
    digest = hashlib.sha256()
    for path in sorted(Path(__file__).parent.glob("*.py")):
        digest.update(path.name.encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def _normalise(value: Any) -> Any:
    """Turn inputs into JSON-able data that identifies them exactly."""
    if isinstance(value, np.ndarray):
        arr = np.ascontiguousarray(value)
        return {"ndarray": str(arr.dtype), "shape": arr.shape, "sha256": hashlib.sha256(arr.tobytes()).hexdigest()}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        from .tire_spec import TireSpec, to_dict

        if isinstance(value, TireSpec):
            return {"TireSpec": _normalise(to_dict(value))}
        return {type(value).__name__: _normalise(dataclasses.asdict(value))}
    if isinstance(value, dict):
        return {str(k): _normalise(v) for k, v in sorted(value.items())}
    if isinstance(value, (list, tuple)):
        return [_normalise(v) for v in value]
    if isinstance(value, (np.floating, float)):
        return repr(float(value))  # exact, and inf/nan safe
    if isinstance(value, (np.integer, int, bool, str)) or value is None:
        return value.item() if isinstance(value, np.generic) else value
    raise TypeError(f"cannot build a cache key from {type(value).__name__}")


def cache_key(stage: str, inputs: dict[str, Any]) -> str:
    """Hex key of a stage and its inputs (and the code fingerprint)."""
    blob = json.dumps({"stage": stage, "inputs": _normalise(inputs), "code": code_fingerprint()}, sort_keys=True)
    return hashlib.sha256(blob.encode()).hexdigest()[:32]


def _path(stage: str, key: str) -> Path:
    return cache_dir() / f"{stage}-{key}.pkl"


def _read(path: Path) -> Any:
    data = path.read_bytes()
    if not data.startswith(_MAGIC):
        raise ValueError("bad header")
    digest, payload = data[len(_MAGIC) : len(_MAGIC) + 64], data[len(_MAGIC) + 64 :]
    if hashlib.sha256(payload).hexdigest().encode() != digest:
        raise ValueError("checksum mismatch")
    return pickle.loads(payload)


def _write(path: Path, value: Any) -> None:
    payload = pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(_MAGIC + hashlib.sha256(payload).hexdigest().encode() + payload)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def cached(stage: str, inputs: dict[str, Any], compute: Callable[[], T]) -> T:
    """Return the cached result of ``stage`` for ``inputs``, computing and storing it if needed."""
    if os.environ.get("ROADNOISE_CACHE", "on").lower() in ("off", "0", "false", "no"):
        return compute()
    path = _path(stage, cache_key(stage, inputs))
    if path.exists():
        try:
            return _read(path)
        except Exception as exc:  # corrupted, truncated or from an incompatible version
            warnings.warn(f"discarding unreadable cache file {path.name} ({exc}); recomputing", stacklevel=2)
            path.unlink(missing_ok=True)
    value = compute()
    _write(path, value)
    return value
