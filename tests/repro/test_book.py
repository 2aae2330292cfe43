"""The book's staging of the chapters and the checks of a built site (the build itself: .ci/book)."""

from __future__ import annotations

import nbformat
import pytest

from roadnoise_utils.repro import book


def test_module_links_turn_package_paths_into_api_references():
    code = "`tire/ring/` (spec, mechanics), `repro/claims.py`; figures `figures/overview.py`"
    assert book.module_links(code) == (
        "{py:mod}`roadnoise_utils.tire.ring` (spec, mechanics), {py:mod}`roadnoise_utils.repro.claims`; "
        "figures {py:mod}`roadnoise_utils.figures.overview`"
    )


def test_a_staged_chapter_says_its_widgets_are_static_links_its_pages_and_ends_with_its_code(tmp_path):
    widget = nbformat.v4.new_code_cell("interact(f)")
    widget.outputs = [nbformat.v4.new_output("display_data", data={book.WIDGET_MIME: {}, "text/plain": "w"})]
    table = nbformat.v4.new_code_cell("table()")
    table.outputs = [nbformat.v4.new_output("display_data", data={"text/markdown": "[next](01-fe-tire-model.ipynb)"})]
    path = tmp_path / "00-demo.ipynb"
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x = 1"), widget, table]), path)
    staged = book.staged_chapter(path, "`tire/model.py`")
    sources = [c.source for c in staged.cells]
    assert sources[1] == book.WIDGET_NOTE and sources[2] == "interact(f)"
    assert staged.cells[3].outputs[0]["data"]["text/markdown"] == "[next](01-fe-tire-model.html)"
    assert staged.cells[-1].source == "**The code of this chapter:** {py:mod}`roadnoise_utils.tire.model`."
    assert len(staged.cells) == 5


def _page(site, name: str, body: str) -> None:
    (site / name).parent.mkdir(parents=True, exist_ok=True)
    (site / name).write_text(f"<html><body>{body}</body></html>")


def test_the_site_check_finds_broken_links_missing_images_and_raw_errors(tmp_path):
    site = tmp_path / "html"
    _page(site, "index.html", '<a href="notebooks/a.html#s1">a</a> <a href="https://example.org">x</a>')
    _page(site, "notebooks/a.html", '<h1 id="s1">A</h1> <img src="../figures/f.png"> <a href="#s1">top</a>')
    (site / "figures").mkdir()
    (site / "figures" / "f.png").write_bytes(b"png")
    assert book.check_site(site) == []
    _page(site, "notebooks/b.html", '<a href="missing.html">m</a> <img src="gone.png"> <div class="traceback">x</div>')
    assert book.check_site(site) == [
        "notebooks/b.html: broken link missing.html",
        "notebooks/b.html: broken image gone.png",
        "notebooks/b.html: a raw error output",
    ]
    assert book.check_site(tmp_path / "nowhere") == [f"{tmp_path / 'nowhere'}: no index.html"]


def test_the_build_refuses_notebooks_whose_outputs_are_stale(monkeypatch, tmp_path):
    stale = tmp_path / "03-stale.ipynb"
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("x")]), stale)
    monkeypatch.setattr(book, "chapter_paths", lambda: [stale])
    with pytest.raises(book.BookError, match="stored outputs not from the present source: 03-stale.ipynb"):
        book.build(tmp_path / "out")


def test_the_site_check_finds_a_link_to_an_anchor_its_page_lacks(tmp_path):
    site = tmp_path / "html"
    _page(site, "index.html", '<a href="report.html#ring-x">r</a> <a href="#here">h</a> <p id="here"></p>')
    _page(site, "report.html", '<a id="ring-x"></a> <a href="#nowhere">n</a> <a href="index.html#here">i</a>')
    assert book.check_site(site) == ["report.html: broken link #nowhere (no such anchor)"]


def test_sphinx_warnings_and_docstring_errors_are_found_in_the_build_output():
    output = (
        "reading sources... [ 50%] api\n"
        "\x1b[91m/x/stages.py:docstring of m:20: ERROR: Malformed table.\x1b[39;49;00m\n"
        "\x1b[91mapi.md:3: WARNING: more than one target found for cross-reference 'cavity'\x1b[39;49;00m\n"
        "build succeeded, 2 warnings.\n"
    )
    assert book.build_warnings(output) == [
        "/x/stages.py:docstring of m:20: ERROR: Malformed table.",
        "api.md:3: WARNING: more than one target found for cross-reference 'cavity'",
    ]
    assert book.build_warnings("build succeeded.\n") == []
