"""Reproduce everything: execute every notebook in order and write their figures.

``python -m roadnoise_utils.reproduce`` runs each ready notebook of ``data/collection.toml``
in a fresh kernel (in place, so the stored outputs are the ones you just computed) and writes
every figure to ``figures/`` (``ROADNOISE_FIGURE_DIR``) as PNG, named after the notebook, the
figure's order and the paper figure it corresponds to (read from the plot cell's heading
comment, e.g. ``# Fig. 2 analogue: ...``). It lists the figures in ``figures/index.csv``.
A notebook that fails stops the run with a non-zero exit status.
"""

from __future__ import annotations

import argparse
import base64
import csv
import re
import sys
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from tqdm.auto import tqdm

from .collection import notebooks
from .paths import REPO_ROOT, figure_dir

_FIG = re.compile(r"Fig\.\s*(\d+)")
_ANALOGUE = re.compile(r"^Fig\.\s*\d+\s*analogue:?\s*")


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:48]


def extract_figures(nb: nbformat.NotebookNode, stem: str, out_dir: Path) -> list[dict[str, str]]:
    """Write the PNG outputs of an executed notebook; return one index row per figure."""
    rows = []
    count = 0
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        heading = next(
            (
                ln.lstrip("# ").strip()
                for ln in cell.source.splitlines()
                if ln.startswith("#") and not ln.startswith("# NBVAL")
            ),
            "figure",
        )
        for output in cell.get("outputs", []):
            data = output.get("data", {})
            if "image/png" not in data:
                continue
            count += 1
            match = _FIG.search(heading)
            paper = f"Fig. {match.group(1)}" if match else ""
            tag = f"-fig{int(match.group(1)):02d}" if match else ""
            caption = _ANALOGUE.sub("", heading)
            name = f"{stem}-{count:02d}{tag}-{_slug(caption)}.png"
            (out_dir / name).write_bytes(base64.b64decode(data["image/png"]))
            rows.append({"file": name, "notebook": f"{stem}.ipynb", "paper_figure": paper, "caption": heading})
    return rows


def run(notebook_dir: Path, out_dir: Path, timeout: int = 1200) -> list[dict[str, str]]:
    """Execute the ready notebooks in order; write figures and their index."""
    out_dir.mkdir(parents=True, exist_ok=True)
    for old in out_dir.glob("*.png"):
        old.unlink()
    index = []
    ready = [nb["file"] for nb in notebooks() if nb["status"] == "ready"]
    for name in tqdm(ready, desc="notebooks"):
        path = notebook_dir / name
        nb = nbformat.read(path, as_version=4)
        start = time.perf_counter()
        NotebookClient(
            nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(notebook_dir)}}
        ).execute()
        nbformat.write(nb, path)
        index += extract_figures(nb, path.stem, out_dir)
        tqdm.write(f"{name}: {time.perf_counter() - start:.1f} s")
    with open(out_dir / "index.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=["file", "notebook", "paper_figure", "caption"])
        writer.writeheader()
        writer.writerows(index)
    return index


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Execute every notebook in order and write the figures.")
    parser.add_argument("--notebooks", type=Path, default=REPO_ROOT / "notebooks")
    parser.add_argument("--figures", type=Path, default=None, help="output folder (default figures/)")
    args = parser.parse_args(argv)
    figures = run(args.notebooks, args.figures or figure_dir())
    print(f"{len(figures)} figures written to {args.figures or figure_dir()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
