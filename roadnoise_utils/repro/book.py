"""The collection as a Jupyter Book, built from the notebooks' stored outputs, and the checks of the built site.

``python -m roadnoise_utils.repro.book`` stages the book's pages (``book/``), the executed notebooks
(``notebooks/*.ipynb``, as the reproduction wrote them: nothing is executed) and the figures and
report (``figures/``) into a temporary source folder, builds it with Jupyter Book 1 (Sphinx,
myst-nb, autodoc with numpydoc for the API pages) into ``build/book/``, and checks the site: every
internal link and image resolves, no page shows a raw error output. It refuses to build from a
notebook whose stored outputs are not from its present source (:mod:`.provenance`).

Each staged chapter gains two things the notebooks themselves do not carry: a closing cell
linking the modules it teaches (``code`` of ``data/collection.toml``) to their API pages, and, above
each widget, a note that the book shows it as a static output.
"""

from __future__ import annotations

import argparse
import html.parser
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from urllib.parse import unquote, urlparse

import nbformat

from . import provenance
from .collection import notebooks
from .paths import REPO_ROOT, figure_dir

#: The book's own pages and configuration.
BOOK_SOURCES = REPO_ROOT / "book"
#: Where the site is written (``build/book/_build/html``).
BUILD_DIR = REPO_ROOT / "build" / "book"
#: The MIME type of a stored ipywidgets view: shown by the book as its static fallback.
WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
WIDGET_NOTE = (
    "*In the book this widget is a static output: its controls do not move. Run the notebook "
    "(JupyterLab, or Binder: see the README) to use them.*"
)


class BookError(RuntimeError):
    """The book cannot be built, or the built site fails a check; the message names every problem."""


def chapter_paths() -> list[Path]:
    """The ready notebooks of ``data/collection.toml``, in reading order."""
    return [REPO_ROOT / "notebooks" / row["file"] for row in notebooks() if row["status"] == "ready"]


def module_links(code: str) -> str:
    """``code`` of a collection row with each backticked package path (``tire/ring/``, ``repro/claims.py``)
    turned into a MyST cross-reference to its API page."""

    def link(match: re.Match) -> str:
        path = match.group(1).removesuffix(".py").strip("/")
        return "{py:mod}`roadnoise_utils." + path.replace("/", ".") + "`"

    return re.sub(r"`([a-z_]+(?:/[a-z_]+)*(?:\.py|/)?)`", link, code)


#: A link to a chapter's notebook, as a generated table in an output writes it.
NOTEBOOK_LINK = re.compile(r"\b(\d\d-[a-z0-9-]+)\.ipynb\b")


def _link_pages(output: nbformat.NotebookNode) -> None:
    """Links to chapters in a markdown or HTML output pointed at their book pages (``.html``)."""
    for mime in ("text/markdown", "text/html"):
        if mime in output.get("data", {}):
            output["data"][mime] = NOTEBOOK_LINK.sub(r"\1.html", output["data"][mime])


def staged_chapter(path: Path, code: str) -> nbformat.NotebookNode:
    """The notebook at ``path`` as the book shows it: a note above each widget, links in generated tables
    pointed at the book's pages, a closing cell on its code."""
    nb = nbformat.read(path, as_version=4)
    cells = []
    for cell in nb.cells:
        outputs = cell.get("outputs", []) if cell.cell_type == "code" else []
        if any(WIDGET_MIME in output.get("data", {}) for output in outputs):
            cells.append(nbformat.v4.new_markdown_cell(WIDGET_NOTE))
        for output in outputs:
            _link_pages(output)
        cells.append(cell)
    if code:
        cells.append(nbformat.v4.new_markdown_cell(f"**The code of this chapter:** {module_links(code)}."))
    nb.cells = cells
    return nb


def stage(source: Path) -> None:
    """Copy the book's pages, the staged chapters and the figures into ``source``."""
    shutil.copytree(BOOK_SOURCES, source, dirs_exist_ok=True)
    (source / "notebooks").mkdir(exist_ok=True)
    for row in notebooks():
        if row["status"] == "ready":
            nb = staged_chapter(REPO_ROOT / "notebooks" / row["file"], row.get("code", ""))
            nbformat.write(nb, source / "notebooks" / row["file"])
    shutil.copytree(figure_dir(), source / "figures", dirs_exist_ok=True)


def build(out: Path = BUILD_DIR) -> Path:
    """Build the book into ``out`` (its site in ``out/_build/html``) and check the site; returns that folder.

    Raises
    ------
    BookError
        A notebook's stored outputs are not from its present source, the build fails, or the
        site has broken links, missing images or raw error outputs.
    """
    stale = provenance.stale_notebooks(chapter_paths())
    if stale:
        names = ", ".join(p.name for p in stale)
        raise BookError(
            f"stored outputs not from the present source: {names}; run the reproduction "
            "(python -m roadnoise_utils) to execute them, then build the book"
        )
    with tempfile.TemporaryDirectory(prefix="roadnoise-book-") as tmp:
        source = Path(tmp) / "book"
        stage(source)
        out.mkdir(parents=True, exist_ok=True)
        command = [_jupyter_book(), "build", str(source), "--path-output", str(out)]
        result = subprocess.run(command, capture_output=True, text=True)
        if result.returncode != 0:
            raise BookError(f"jupyter-book build failed:\n{result.stdout[-4000:]}\n{result.stderr[-4000:]}")
        warnings = build_warnings(result.stdout + result.stderr)
        if warnings:
            shown = "\n".join(line.replace(f"{source}/", "") for line in warnings[:50])
            raise BookError(f"{len(warnings)} warnings in the build (fix the page or docstring):\n{shown}")
    site = out / "_build" / "html"
    # pages that show figures in HTML (the gallery's table) point at figures/, which Sphinx does not copy
    shutil.copytree(figure_dir(), site / "figures", dirs_exist_ok=True)
    problems = check_site(site)
    if problems:
        raise BookError(f"{len(problems)} problems in the built book:\n" + "\n".join(problems[:50]))
    return site


def _jupyter_book() -> str:
    """The ``jupyter-book`` command of this environment (``requirements-book.txt``)."""
    beside = Path(sys.executable).with_name("jupyter-book")
    found = str(beside) if beside.is_file() else shutil.which("jupyter-book")
    if found is None:
        raise BookError("jupyter-book is not installed: pip install -r requirements-book.txt")
    return found


class _References(html.parser.HTMLParser):
    """The ``href`` and ``src`` values of a page, and the classes of its elements."""

    def __init__(self) -> None:
        super().__init__()
        self.links: list[str] = []
        self.images: list[str] = []
        self.classes: list[str] = []
        self.anchors: set[str] = set()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        for key in ("id", "name"):
            if values.get(key):
                self.anchors.add(values[key])
        if tag == "a" and values.get("href"):
            self.links.append(values["href"])
        if tag == "img" and values.get("src"):
            self.images.append(values["src"])
        if values.get("class"):
            self.classes.extend(values["class"].split())


#: Classes myst-nb gives an error output (a traceback, an ``ename``) in the page.
ERROR_CLASSES = {"traceback", "output_error"}


def _parsed(page: Path) -> tuple[_References, str]:
    parser = _References()
    text = page.read_text(encoding="utf-8")
    parser.feed(text)
    return parser, text


def check_site(site: Path) -> list[str]:
    """Broken internal links (a missing page or a missing ``#anchor`` on it), missing images and raw
    error outputs in the built ``site`` (one line each)."""
    if not (site / "index.html").is_file():
        return [f"{site}: no index.html"]
    pages = {page.resolve(): _parsed(page) for page in sorted(site.rglob("*.html"))}
    problems = []
    for page, (parser, text) in pages.items():
        where = page.relative_to(site.resolve())
        for kind, targets in (("link", parser.links), ("image", parser.images)):
            for target in targets:
                url = urlparse(target)
                if url.scheme or url.netloc or target.startswith(("mailto:", "data:")):
                    continue
                resolved = (page.parent / unquote(url.path)).resolve() if url.path else page
                if not resolved.exists():
                    problems.append(f"{where}: broken {kind} {target}")
                elif kind == "link" and url.fragment and resolved in pages:
                    if unquote(url.fragment) not in pages[resolved][0].anchors:
                        problems.append(f"{where}: broken link {target} (no such anchor)")
        if ERROR_CLASSES & set(parser.classes) or "Traceback (most recent call last)" in text:
            problems.append(f"{where}: a raw error output")
    return problems


#: Colour codes in Sphinx's console output.
_ANSI = re.compile(r"\x1b\[[0-9;]*m")


def build_warnings(output: str) -> list[str]:
    """The lines of a Sphinx build's console ``output`` that report a warning or an error
    (a docstring that does not parse, an ambiguous reference...), colour codes removed."""
    lines = (_ANSI.sub("", line) for line in output.splitlines())
    return [line for line in lines if "WARNING:" in line or "ERROR:" in line]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Build the collection's Jupyter Book from the stored outputs.")
    parser.add_argument("--out", type=Path, default=BUILD_DIR, help=f"output folder (default {BUILD_DIR})")
    args = parser.parse_args(argv)
    try:
        site = build(args.out)
    except BookError as exc:
        print(f"book: {exc}", file=sys.stderr)
        return 2
    print(f"book: {site / 'index.html'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
