"""Where the collection keeps its data, its cache and its figures.

Every location can be overridden by an environment variable, so the package works from an
editable install in the repository (the normal case) and from anywhere else.
"""

from __future__ import annotations

import os
from pathlib import Path

#: The repository root (the folder holding ``roadnoise_utils/`` and ``data/``).
REPO_ROOT = Path(__file__).resolve().parents[1]


def data_dir() -> Path:
    """Folder of the data files (``ROADNOISE_DATA_DIR``, default ``<repo>/data``)."""
    return Path(os.environ.get("ROADNOISE_DATA_DIR", REPO_ROOT / "data"))


def cache_dir() -> Path:
    """Folder of the stage cache (``ROADNOISE_CACHE_DIR``, default ``<repo>/.cache``)."""
    return Path(os.environ.get("ROADNOISE_CACHE_DIR", REPO_ROOT / ".cache"))


def figure_dir() -> Path:
    """Folder the reproduction writes figures to (``ROADNOISE_FIGURE_DIR``, default ``<repo>/figures``)."""
    return Path(os.environ.get("ROADNOISE_FIGURE_DIR", REPO_ROOT / "figures"))
