"""Which source a notebook's stored outputs come from: a digest of its code, stamped by the reproduction.

The reproduction executes each notebook and writes it back with ``metadata.roadnoise.source_digest``,
the SHA-256 of its code cells' sources, in order, at execution. A notebook whose code was edited
since (its jupytext twin synced into it with the old outputs kept) no longer matches its stamp:
the book, built from the stored outputs without executing anything, refuses it rather than show
outputs of another source. The prose (markdown cells) is not in the digest: it computes nothing,
so a corrected sentence leaves every output true.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import nbformat

#: The notebook metadata key the stamp lives under.
METADATA_KEY = "roadnoise"


def source_digest(nb: nbformat.NotebookNode) -> str:
    """SHA-256 (hex) of the notebook's code cells' sources in order (prose, outputs and metadata excluded)."""
    code = [cell.source for cell in nb.cells if cell.cell_type == "code"]
    return hashlib.sha256(json.dumps(code, ensure_ascii=False).encode("utf-8")).hexdigest()


def stamp(nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The executed notebook with the digest of the source it ran (in place; returned for chaining)."""
    nb.metadata.setdefault(METADATA_KEY, {})["source_digest"] = source_digest(nb)
    return nb


def outputs_are_current(path: Path) -> bool:
    """Whether the notebook at ``path`` carries a stamp and the stamp matches its present cells."""
    nb = nbformat.read(path, as_version=4)
    stamped = nb.metadata.get(METADATA_KEY, {}).get("source_digest")
    return stamped is not None and stamped == source_digest(nb)


def stale_notebooks(paths: list[Path]) -> list[Path]:
    """The notebooks among ``paths`` whose stored outputs are not from their present source."""
    return [path for path in paths if not outputs_are_current(path)]
