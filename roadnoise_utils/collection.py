"""The map of the collection (``data/collection.toml``): notebook table for the README and notebook 00.

``python -m roadnoise_utils.collection`` prints the Markdown table that the README carries
between its ``<!-- notebook-table -->`` markers (a test keeps the two identical).
"""

from __future__ import annotations

import tomllib

import pandas as pd

from .paths import data_dir


def notebooks() -> list[dict[str, str]]:
    """The notebooks in reading order, with title, paper section, figures and status."""
    with open(data_dir() / "collection.toml", "rb") as fh:
        return tomllib.load(fh)["notebook"]


def notebook_table(link_prefix: str = "notebooks/") -> pd.DataFrame:
    """Notebook → paper section / figures, as a table."""
    rows = [
        {
            "notebook": f"[{nb['file']}]({link_prefix}{nb['file']})" if nb["status"] == "ready" else nb["file"],
            "title": nb["title"],
            "paper section": nb["paper"],
            "paper figures": nb["figures"],
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


if __name__ == "__main__":
    print(markdown_table())
