"""Reproduce everything: execute every notebook in order, write the figures and the report.

``python -m roadnoise_utils`` (the README's first command):

1. runs each notebook of ``data/collection.toml`` in a fresh kernel, in order, in place (so
   the stored outputs are the ones just computed); a failing notebook stops the run;
2. writes every figure to ``figures/`` (``ROADNOISE_FIGURE_DIR`` or ``--figures``) as PNG,
   named after the notebook, the paper figure it corresponds to (read from the plot cell's
   heading comment, e.g. ``# Fig. 2 analogue: ...``) and its caption, listed in
   ``figures/index.csv``;
3. evaluates every claim of ``data/paper/claims.toml`` (:mod:`.claims`) and writes
   ``reproduction-report.csv`` and ``.md`` next to the figures.

The exit status is non-zero when a notebook fails or a claim fails that is not a documented
known deviation.
"""

from __future__ import annotations

import argparse
import base64
import csv
import re
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from tqdm.auto import tqdm

from . import claims
from .collection import gallery_markdown, markdown_table, notebooks
from .paths import REPO_ROOT, figure_dir

_FIG = re.compile(r"Fig\.\s*(\d+)")
_ANALOGUE = re.compile(r"^Fig\.\s*\d+\s*analogue:?\s*")


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:48]


def figure_names(nb: nbformat.NotebookNode, stem: str) -> list[tuple[str, str, str, int, int]]:
    """``(file, paper figure, caption, cell, output)`` for every PNG output of a notebook.

    Names are stable: ``<notebook>-[figNN-]<caption slug>.png``, numbered only if a caption repeats.
    """
    out = []
    seen: dict[str, int] = {}
    for c, cell in enumerate(nb.cells):
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
        for o, output in enumerate(cell.get("outputs", [])):
            if "image/png" not in output.get("data", {}):
                continue
            match = _FIG.search(heading)
            paper = f"Fig. {match.group(1)}" if match else ""
            tag = f"fig{int(match.group(1)):02d}-" if match else ""
            base = f"{stem}-{tag}{_slug(_ANALOGUE.sub('', heading))}"
            seen[base] = seen.get(base, 0) + 1
            name = base + ("" if seen[base] == 1 else f"-{seen[base]}") + ".png"
            out.append((name, paper, heading, c, o))
    return out


def extract_figures(nb: nbformat.NotebookNode, stem: str, out_dir: Path) -> list[dict[str, str]]:
    """Write the PNG outputs of an executed notebook; return one index row per figure."""
    rows = []
    for name, paper, caption, c, o in figure_names(nb, stem):
        data = nb.cells[c]["outputs"][o]["data"]["image/png"]
        (out_dir / name).write_bytes(base64.b64decode(data))
        rows.append({"file": name, "notebook": f"{stem}.ipynb", "paper_figure": paper, "caption": caption})
    return rows


def run_notebooks(notebook_dir: Path, out_dir: Path, timeout: int = 1800) -> list[dict[str, str]]:
    """Execute the ready notebooks in order; write their figures and the figure index."""
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
    parser = argparse.ArgumentParser(description="Execute every notebook in order, write the figures and the report.")
    parser.add_argument("--notebooks", type=Path, default=REPO_ROOT / "notebooks")
    parser.add_argument("--figures", type=Path, default=None, help="output folder (default figures/)")
    parser.add_argument("--report-only", action="store_true", help="skip the notebooks, only evaluate the claims")
    parser.add_argument(
        "--print",
        choices=["notebook-table", "gallery"],
        help="only print the README's generated notebook table or figure gallery",
    )
    args = parser.parse_args(argv)
    if args.print:
        print(markdown_table() if args.print == "notebook-table" else gallery_markdown())
        return 0
    out = args.figures or figure_dir()
    if not args.report_only:
        figures = run_notebooks(args.notebooks, out)
        print(f"{len(figures)} figures written to {out}")
    print("evaluating the paper's claims ...")
    table = claims.report()
    csv_path, md_path = claims.write_report(table, out)
    failures = claims.unexpected_failures(table)
    deviations = table[(table["verdict"] == "fail") & (table["known deviation"] != "")]
    print(
        f"report: {md_path} and {csv_path.name}: {int((table['verdict'] == 'pass').sum())} of {len(table)} claims "
        f"reproduced, {len(deviations)} documented deviations, {len(failures)} unexpected failures"
    )
    for cid in failures.index:
        print(
            f"  FAILED: {cid}: {table.loc[cid, 'claim']} (paper {table.loc[cid, 'paper']}, ours {table.loc[cid, 'ours']})"
        )
    return claims.exit_status(table)
