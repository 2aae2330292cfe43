"""The map of the collection (``data/collection.toml``): notebook table for the README and notebook 00.

``python -m roadnoise_utils --print notebook-table`` prints the Markdown table that the README
carries between its ``<!-- notebook-table -->`` markers, ``--print gallery`` the figure gallery of
the book's gallery page between its ``<!-- gallery -->`` markers (tests keep them identical).
"""

from __future__ import annotations

import csv
from pathlib import Path

import pandas as pd

from .paths import data_dir, figure_dir, read_toml, record_read


def notebooks() -> list[dict[str, str]]:
    """The notebooks in reading order, with title, paper section, figures and status."""
    return read_toml(data_dir() / "collection.toml")["notebook"]


def stages() -> list[dict[str, str]]:
    """The stages of the RM pipeline in order, each with its text, notebook, paper reference and part (Fig. 1 map)."""
    return read_toml(data_dir() / "collection.toml")["stage"]


def notebook_table(link_prefix: str = "notebooks/") -> pd.DataFrame:
    """Notebook → paper section / figures / the package modules it uses, as a table."""
    rows = [
        {
            "notebook": f"[{nb['file']}]({link_prefix}{nb['file']})" if nb["status"] == "ready" else nb["file"],
            "title": nb["title"],
            "paper section": nb["paper"],
            "paper figures": nb["figures"],
            "code (roadnoise_utils/)": nb.get("code", ""),
            "status": nb["status"],
        }
        for nb in notebooks()
    ]
    return pd.DataFrame(rows)


def markdown_table(link_prefix: str = "notebooks/") -> str:
    """The notebook table as GitHub Markdown."""
    table = notebook_table(link_prefix)
    lines = ["| " + " | ".join(table.columns) + " |", "|" + "---|" * len(table.columns)]
    lines += ["| " + " | ".join(str(v) for v in row) + " |" for row in table.itertuples(index=False)]
    return "\n".join(lines)


def gallery_markdown(index_csv: Path | None = None, prefix: str = "figures/", columns: int = 3) -> str:
    """A Markdown/HTML table of our figures that mirror the paper's, one per paper figure, in order.

    Built from the ``index.csv`` the reproduction writes; the book's gallery page (``book/gallery.md``)
    carries it between its ``<!-- gallery -->`` markers (a test keeps the two identical).
    """
    index_csv = index_csv or figure_dir() / "index.csv"
    record_read(index_csv)
    with open(index_csv, newline="") as fh:
        rows = [r for r in csv.DictReader(fh) if r["paper_figure"]]
    first: dict[int, dict[str, str]] = {}
    for r in rows:
        first.setdefault(int(r["paper_figure"].split()[-1]), r)
    cells = [
        f'<img src="{prefix}{r["file"]}" width="280"><br><b>{r["paper_figure"]}</b> — '
        f"{r['caption'].split(':', 1)[-1].strip()} ({r['notebook'].split('-')[0]})"
        for _, r in sorted(first.items())
    ]
    lines = ["<table>"]
    for k in range(0, len(cells), columns):
        lines.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells[k : k + columns]) + "</tr>")
    lines.append("</table>")
    return "\n".join(lines)
