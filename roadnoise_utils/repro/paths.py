"""Where the collection keeps its data, its cache and its figures.

Every location can be overridden by an environment setting (:mod:`roadnoise_utils.settings`), so
the package works from an editable install in the repository (the normal case) and from anywhere
else.
"""

from __future__ import annotations

import contextlib
import contextvars
import hashlib
import os
import tempfile
import tomllib
from collections.abc import Iterator
from pathlib import Path

from .. import settings
from ..settings import REPO_ROOT


def data_dir() -> Path:
    """Folder of the data files (``ROADNOISE_DATA_DIR``, default ``<repo>/data``); it must hold a ``tires`` folder."""
    folder = settings.path("ROADNOISE_DATA_DIR", REPO_ROOT / "data")
    if not (folder / "tires").is_dir():
        raise FileNotFoundError(
            f"ROADNOISE_DATA_DIR = {str(folder)!r} has no tires/ folder: point it at a copy of the repository's data/ "
            "(tires/, roads/, vehicles/, conditions/, paper/) or unset it"
        )
    return folder


def cache_dir() -> Path:
    """Folder of the stage cache (``ROADNOISE_CACHE_DIR``, default ``<repo>/.cache``)."""
    return settings.path("ROADNOISE_CACHE_DIR", REPO_ROOT / ".cache")


def figure_dir() -> Path:
    """Folder the reproduction writes figures to (``ROADNOISE_FIGURE_DIR``, default ``<repo>/figures``)."""
    return settings.path("ROADNOISE_FIGURE_DIR", REPO_ROOT / "figures")


def data_file(name: str | Path, folder: str, what: str) -> Path:
    """Resolve a data file: a stem in ``data/<folder>/`` (``"165_65R14"``) or a path to a TOML file.

    Raises
    ------
    FileNotFoundError
        Neither exists; the message lists the available stems. ``what`` names the kind of
        file in that message (``"tire file"``, ``"road texture"``...).
    """
    if not isinstance(name, (str, Path)):
        raise TypeError(f"{what}: give a name (str) or a path to a .toml file, got {type(name).__name__}")
    path = Path(name)
    if path.suffix == ".toml" and path.exists():
        return path
    if path.suffix and path.exists():
        raise ValueError(f"{what} {str(name)!r}: a {what} is a .toml file, got a {path.suffix!r} file")
    candidate = data_dir() / folder / f"{name}.toml"
    if candidate.exists():
        return candidate
    available = sorted(p.stem for p in (data_dir() / folder).glob("*.toml"))
    raise FileNotFoundError(f"no {what} {str(name)!r}: give a path to a .toml file or one of {available}")


@contextlib.contextmanager
def atomic_output(path: str | Path, overwrite: bool = False, parameter: str = "path") -> Iterator[Path]:
    """A temporary file beside ``path`` to write into; on success it replaces ``path`` (``os.replace``).

    Nothing is written half-way: if the block raises, the temporary file is removed and ``path``
    is left as it was. An existing ``path`` is refused unless ``overwrite`` (``FileExistsError``
    naming ``parameter`` and the ``overwrite`` argument); a missing folder is refused before any work.
    """
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"{parameter} = {str(path)!r} is a folder: give a file name")
    if not path.parent.is_dir():
        raise FileNotFoundError(f"{parameter} = {str(path)!r}: the folder {str(path.parent)!r} does not exist")
    if path.exists() and not overwrite:
        raise FileExistsError(f"{parameter} = {str(path)!r} exists: pass overwrite=True to replace it")
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(fd)
    os.chmod(tmp, 0o644)  # mkstemp's 0600 would carry over to the result
    try:
        yield Path(tmp)
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)


def read_toml(path: Path) -> dict:
    """A TOML file as nested dicts; a file that is not valid TOML is refused with its name and the reason."""
    record_read(path)
    with open(path, "rb") as fh:
        try:
            return tomllib.load(fh)
        except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
            raise ValueError(f"{Path(path).name}: not a valid TOML file ({exc})") from None


# ---------------------------------------------------------------- the data files a computation reads

#: The open records of :func:`recording_reads`, innermost last (per thread and task).
_RECORDS: contextvars.ContextVar[tuple[dict[str, str], ...]] = contextvars.ContextVar("roadnoise_reads", default=())
_DIGESTS: dict[tuple[str, int, int], str] = {}


def file_digest(path: str | Path) -> str:
    """SHA-256 of a file's bytes ("" for a missing file), memoised on its modification time and size."""
    try:
        stat = os.stat(path)
    except OSError:
        return ""
    memo = (str(path), stat.st_mtime_ns, stat.st_size)
    if memo not in _DIGESTS:
        _DIGESTS[memo] = hashlib.sha256(Path(path).read_bytes()).hexdigest()
    return _DIGESTS[memo]


def record_read(path: str | Path) -> None:
    """Note that the running computation read ``path``: every reader of a data file calls this.

    Each open :func:`recording_reads` (a cached stage and the stages around it) gets the file's
    resolved path and the digest of its contents.
    """
    records = _RECORDS.get()
    if records:
        resolved = str(Path(path).resolve())
        digest = file_digest(resolved)
        for record in records:
            record[resolved] = digest


@contextlib.contextmanager
def recording_reads() -> Iterator[dict[str, str]]:
    """Collect ``{path: digest}`` of every file :func:`record_read` sees inside the block."""
    record: dict[str, str] = {}
    token = _RECORDS.set((*_RECORDS.get(), record))
    try:
        yield record
    finally:
        _RECORDS.reset(token)


def replay_reads(reads: dict[str, str]) -> None:
    """Pass the reads of a result served from the cache on to the open records around it."""
    for record in _RECORDS.get():
        record.update(reads)


def changed_files(reads: dict[str, str]) -> list[str]:
    """The files of ``reads`` whose contents differ from (or are missing since) when they were read."""
    return [path for path, digest in reads.items() if file_digest(path) != digest]
