"""The stamp of the source a notebook's stored outputs come from, and that every chapter carries a current one."""

from __future__ import annotations

import nbformat

from roadnoise_utils.repro import provenance
from roadnoise_utils.repro.book import chapter_paths


def _notebook(*sources: str) -> nbformat.NotebookNode:
    return nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(s) for s in sources])


def test_a_stamp_follows_the_cells_not_the_outputs(tmp_path):
    nb = provenance.stamp(_notebook("x = 1", "print(x)"))
    path = tmp_path / "a.ipynb"
    nbformat.write(nb, path)
    assert provenance.outputs_are_current(path)
    nb.cells[1].outputs = [nbformat.v4.new_output("stream", text="1\n")]  # outputs do not count
    nbformat.write(nb, path)
    assert provenance.outputs_are_current(path)
    nb.cells[0].source = "x = 2"  # an edited source, outputs kept: stale
    nbformat.write(nb, path)
    assert provenance.stale_notebooks([path]) == [path]
    nbformat.write(_notebook("x = 1"), path)  # never stamped: stale
    assert not provenance.outputs_are_current(path)


def test_the_digest_sees_the_code_and_its_order_not_the_prose():
    code, swapped = _notebook("a", "b"), _notebook("b", "a")
    assert provenance.source_digest(code) != provenance.source_digest(swapped)
    with_prose = _notebook("a", "b")
    with_prose.cells.insert(1, nbformat.v4.new_markdown_cell("a sentence that computes nothing"))
    assert provenance.source_digest(with_prose) == provenance.source_digest(code)


def test_every_chapter_s_stored_outputs_are_from_its_present_source():
    """The book shows the stored outputs: a chapter edited without a reproduction since fails here first."""
    assert provenance.stale_notebooks(chapter_paths()) == [], "run python -m roadnoise_utils, then commit"
