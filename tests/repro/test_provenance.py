"""The stamp of the source a notebook's stored outputs come from, and that every chapter carries a current one."""

from __future__ import annotations

import re

import nbformat

from roadnoise_utils.repro import provenance, reproduce
from roadnoise_utils.repro.book import chapter_paths
from roadnoise_utils.repro.paths import REPO_ROOT

#: An absolute path to a file of the package (any machine's).
ABSOLUTE = re.compile(r"(^|[\s'\"(])/\S*/roadnoise_utils/", re.MULTILINE)


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


def test_stored_outputs_name_files_relative_to_the_repository(tmp_path):
    root = tmp_path / "clone"
    warning = f"{root}/roadnoise_utils/rm/order.py:86: RoadnoiseWarning: no order fits\n"
    nb = _notebook("fit()")
    nb.cells[0].outputs = [
        nbformat.v4.new_output("stream", name="stderr", text=warning),
        nbformat.v4.new_output("error", ename="E", evalue="v", traceback=[f"File {root}/roadnoise_utils/x.py:3"]),
    ]
    reproduce.portable_outputs(nb, root)
    assert nb.cells[0].outputs[0].text == "roadnoise_utils/rm/order.py:86: RoadnoiseWarning: no order fits\n"
    assert nb.cells[0].outputs[1].traceback == ["File roadnoise_utils/x.py:3"]


def test_no_chapter_stores_the_location_of_the_machine_that_ran_it():
    for path in chapter_paths():
        for cell in nbformat.read(path, as_version=4).cells:
            for output in cell.get("outputs", []):
                text = output.get("text", "") + "".join(output.get("traceback", []))
                assert str(REPO_ROOT) not in text and not ABSOLUTE.search(text), path.name
