"""Reproduce everything: execute every notebook in order, write the figures and the report.

``python -m roadnoise_utils`` (the README's first command):

1. runs each ready notebook of ``data/collection.toml`` in a fresh kernel, with the inline
   plotting backend whatever ``MPLBACKEND`` says (a per-cell time limit, one retry of a
   stalled notebook), two at a time on two cores (``--workers``; the stage cache's per-key
   locks make a notebook wait for a stage another one is computing, never compute it twice),
   the longest first (``cold_seconds`` in ``data/collection.toml``) but for notebook 00, which
   evaluates every claim and starts last, when the chapters have computed their stages; BLAS runs one thread per kernel then (two pools on
   two cores made notebook 03 run 7-9x slower); a failing notebook stops the run and names its cell;
2. checks that every plot cell (a top-level ``plt.show()``) produced its figure;
3. evaluates every claim of ``data/paper/claims.toml`` (:mod:`.claims`), as the pool's last task, beside the
   overview (both only read the chapters' stages); the claims of the models that only the report
   judges (``overview = false``: the loaded FE tire, whose check tire no chapter loads) have their
   stages computed by the pool's first task, beside the chapters, not alone at the end;
4. only then writes, all at once: the figures (``figures/`` or ``--figures``, PNG, named after
   the notebook, the paper figure they mirror — read from the plot cell's heading comment,
   e.g. ``# Fig. 2 analogue: ...`` — and the caption, listed in ``index.csv``) and the report
   ``reproduction-report.csv`` / ``.md`` are staged in a temporary folder that replaces the
   old one in one rename; the notebooks are rewritten in place (each file atomically) with
   the outputs just computed.

A failure at any step leaves ``figures/`` and the notebooks as they were. The exit status is
non-zero when a notebook fails, a figure is missing, or a claim fails that is not a
documented known deviation.
"""

from __future__ import annotations

import argparse
import base64
import contextlib
import csv
import multiprocessing
import os
import re
import shutil
import tempfile
import time
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, ThreadPoolExecutor, wait
from pathlib import Path

import nbformat
from nbclient.exceptions import CellExecutionError, CellTimeoutError, DeadKernelError
from threadpoolctl import threadpool_limits
from tqdm.auto import tqdm

from . import claims, provenance
from .collection import gallery_markdown, markdown_table, notebooks
from .kernel_client import PatientClient
from .paths import REPO_ROOT, figure_dir

_FIG = re.compile(r"Fig\.\s*(\d+)")
_ANALOGUE = re.compile(r"^Fig\.\s*\d+\s*analogue:?\s*")
#: The backend the notebooks' kernels use, whatever the environment sets (figures are their outputs).
INLINE_BACKEND = "module://matplotlib_inline.backend_inline"
#: Default time limit of one cell (s): a stall's bound, not a budget. The longest cells compute the loaded FE
#: tire's states on a cold cache (two drum states, ~270 s alone; beside the pool's other task, which
#: may hold a stage they wait for, over 300 s: a limit of 300 s killed and restarted that chapter).
CELL_TIMEOUT = 900
#: Notebooks executed at a time: two (the machines this runs on have two cores), fewer on one core.
WORKERS = min(2, os.cpu_count() or 1)
#: The pool's task that computes the report-only models' stages (:func:`_report_only_stages`).
_EARLY_STAGES = "report-only stages"
#: Files of the figures folder that the reproduction writes (anything else in it is kept).
_OWN = re.compile(r".*\.png|index\.csv|reproduction-report\.(csv|md)")


class ReproductionError(RuntimeError):
    """A notebook failed or stalled, or a figure is missing; nothing has been written."""


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-")[:48]


def _heading(cell: nbformat.NotebookNode) -> str:
    """The cell's first comment line (not an nbval marker): the figure's caption."""
    lines = (ln.lstrip("# ").strip() for ln in cell.source.splitlines() if ln.startswith("#"))
    return next((ln for ln in lines if not ln.startswith("NBVAL")), "figure")


def figure_names(nb: nbformat.NotebookNode, stem: str) -> list[tuple[str, str, str, int, int]]:
    """``(file, paper figure, caption, cell, output)`` for every PNG output of a notebook.

    Names are stable: ``<notebook>-[figNN-]<caption slug>.png``, numbered only if a caption repeats.
    """
    out = []
    seen: dict[str, int] = {}
    for c, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        heading = _heading(cell)
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


def missing_figures(nb: nbformat.NotebookNode) -> list[tuple[int, str]]:
    """``(cell number, caption)`` of every plot cell (a top-level ``plt.show()``) without a PNG output."""
    missing = []
    for c, cell in enumerate(nb.cells):
        if cell.cell_type != "code" or "plt.show()" not in cell.source.splitlines():
            continue
        if not any("image/png" in o.get("data", {}) for o in cell.get("outputs", [])):
            missing.append((c, _heading(cell)))
    return missing


def _failed_cell(nb: nbformat.NotebookNode) -> str:
    """``cell N ('caption') failed: Error: message`` of the cell that raised."""
    for c, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            if output.get("output_type") == "error":
                return f"cell {c} ({_heading(cell)!r}) failed: {output['ename']}: {output['evalue']}"
    return "a cell failed"


def execute_notebook(path: Path, timeout: int = CELL_TIMEOUT, retries: int = 1) -> nbformat.NotebookNode:
    """Execute a notebook in a fresh kernel (inline backend, working folder its own) and return it.

    A cell running longer than ``timeout`` s, or a kernel that dies, is retried ``retries``
    times with a new kernel; a cell that raises is not.

    Raises
    ------
    ReproductionError
        The notebook failed or stalled, or a plot cell produced no figure; the message names
        the notebook and the cell.
    """
    env = {**os.environ, "MPLBACKEND": INLINE_BACKEND}
    for attempt in range(retries + 1):
        nb = nbformat.read(path, as_version=4)
        client = PatientClient(  # waits that survive a lost ZeroMQ wake-up (kernel_client)
            nb,
            timeout=timeout,
            kernel_name="python3",
            resources={"metadata": {"path": str(path.parent)}},
            shutdown_kernel="immediate",  # a graceful shutdown interrupts the kernel and logs a KeyboardInterrupt
            coalesce_streams=True,  # one stream output per cell and stream, as a notebook front end shows it
        )
        try:
            client.execute(env=env)
            break
        except CellExecutionError as exc:
            raise ReproductionError(f"{path.name}: {_failed_cell(nb)}") from exc
        except (CellTimeoutError, DeadKernelError) as exc:
            if attempt == retries:
                stalled = "stalled" if isinstance(exc, CellTimeoutError) else "lost its kernel"
                raise ReproductionError(
                    f"{path.name} {stalled} ({exc.__class__.__name__}: a cell ran over the {timeout} s limit "
                    f"or the kernel died) in {attempt + 1} attempts; raise --timeout if a cell needs longer"
                ) from exc
            tqdm.write(f"{path.name}: {type(exc).__name__}, retrying once with a new kernel")
    missing = missing_figures(nb)
    if missing:
        cells = ", ".join(f"cell {c} ({caption!r})" for c, caption in missing)
        raise ReproductionError(f"{path.name}: no figure from {cells}; the inline backend did not draw it")
    return nb


def _write_figures(executed: dict[Path, nbformat.NotebookNode], folder: Path) -> list[dict[str, str]]:
    """Write every PNG output and ``index.csv`` into ``folder``; return the index rows."""
    rows = []
    for path, nb in executed.items():
        for name, paper, caption, c, o in figure_names(nb, path.stem):
            (folder / name).write_bytes(base64.b64decode(nb.cells[c]["outputs"][o]["data"]["image/png"]))
            rows.append({"file": name, "notebook": path.name, "paper_figure": paper, "caption": caption})
    with open(folder / "index.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=["file", "notebook", "paper_figure", "caption"])
        writer.writeheader()
        writer.writerows(rows)
    return rows


def _swap_in(staging: Path, out: Path) -> None:
    """Replace ``out`` by ``staging`` (files in ``out`` that the reproduction does not write are kept)."""
    if out.exists():
        for item in out.iterdir():
            if not _OWN.fullmatch(item.name) and not (staging / item.name).exists():
                (shutil.copytree if item.is_dir() else shutil.copy2)(item, staging / item.name)
        backup = Path(tempfile.mkdtemp(prefix=f".{out.name}.old-", dir=out.parent))
        backup.rmdir()
        out.rename(backup)
        try:
            staging.rename(out)
        except OSError:
            backup.rename(out)
            raise
        shutil.rmtree(backup, ignore_errors=True)
    else:
        staging.rename(out)


def _remove_stale(out: Path, age: float = 3600.0) -> None:
    """Delete staging and backup folders that a killed run left beside ``out`` (older than ``age`` s)."""
    for folder in [*out.parent.glob(f".{out.name}.new-*"), *out.parent.glob(f".{out.name}.old-*")]:
        if time.time() - folder.stat().st_mtime > age:
            shutil.rmtree(folder, ignore_errors=True)


def portable_outputs(nb: nbformat.NotebookNode, root: Path = REPO_ROOT) -> nbformat.NotebookNode:
    """The notebook with the repository's location taken out of its text outputs, in place.

    A warning's or traceback's file name reads ``roadnoise_utils/...`` relative to the
    repository rather than the folder of the machine that ran it, so the stored outputs (and the
    book built from them) are the same wherever the reproduction ran.
    """
    prefix = f"{Path(root).resolve()}{os.sep}"
    for cell in nb.cells:
        for output in cell.get("outputs", []):
            if isinstance(output.get("text"), str):
                output["text"] = output["text"].replace(prefix, "")
            if "traceback" in output:
                output["traceback"] = [line.replace(prefix, "") for line in output["traceback"]]
    return nb


def _write_notebook(nb: nbformat.NotebookNode, path: Path) -> None:
    """Rewrite a notebook atomically (temporary file, then rename)."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}", suffix=".tmp")
    os.close(fd)
    try:
        nbformat.write(nb, tmp)
        os.replace(tmp, path)
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)


#: BLAS thread variables set to 1 in the kernels when notebooks run side by side (two BLAS pools
#: on two cores slow each other down several times).
_ONE_THREAD = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def _timed_execution(path: Path, timeout: int, one_thread: bool) -> tuple[nbformat.NotebookNode, float]:
    if one_thread:
        os.environ.update(dict.fromkeys(_ONE_THREAD, "1"))  # this worker process only; its kernels inherit it
    start = time.perf_counter()
    nb = execute_notebook(path, timeout)
    return nb, time.perf_counter() - start


def start_order(paths: list[Path], seconds: dict[Path, float]) -> list[Path]:
    """The chapters (``paths[1:]``) longest expected ``seconds`` first (ties in order), then the overview ``paths[0]``."""
    return sorted(paths[1:], key=lambda p: -seconds.get(p, 0.0)) + paths[:1]


def _evaluated_claims(one_thread: bool):
    """The claims report (:func:`.claims.report`), in a worker of the notebooks' pool."""
    if not one_thread:
        return claims.report(models=claims.MODELS)
    with threadpool_limits(1):
        return claims.report(models=claims.MODELS)


#: The models only the reproduction's report judges (``overview = false``): no chapter but their own
#: computes the stages their claims read on their second tire, so those claims start with the pool.
REPORT_ONLY_MODELS = tuple(m for m in claims.MODELS if m not in claims.OVERVIEW_MODELS)


def _report_only_stages(one_thread: bool) -> None:
    """The stages of :data:`REPORT_ONLY_MODELS`' claims computed into the cache, in a worker of the pool
    beside the chapters, the last claims first: the claims file ends with those on the check tire
    (the cavity's, the moving hub's), which no chapter computes for these models, and the
    chapter of such a model computes its paper tire's stages, read by the first claims; starting from
    the other end, the two rarely wait for each other's stage (the cache's locks never let them
    compute one twice). The report is evaluated again, from the cache, once every chapter has ended."""
    with threadpool_limits(1) if one_thread else contextlib.nullcontext():
        claims.report(claims=claims.load_claims()[::-1], models=REPORT_ONLY_MODELS)


def _execute_all(
    paths: list[Path], timeout: int, workers: int, seconds: dict[Path, float] | None = None, report: bool = False
) -> tuple[dict[Path, nbformat.NotebookNode], object]:
    """Every notebook executed, ``workers`` at a time; the first failure stops the run.

    The chapters start longest first by their expected ``seconds`` (in order without them: a
    long notebook started last keeps one core busy alone at the end); the overview (first)
    evaluates every claim: started last, it finds the chapters' stages computed. With
    ``report`` the stages of the report-only models' claims start first, beside the chapters
    (:func:`_report_only_stages`), and the claims are evaluated once every chapter and those
    stages have ended, beside the overview (both only read the cache), not after it. Returns the
    executed notebooks and the report (or None).
    """
    done, table = {}, None
    started = start_order(paths, seconds or {})
    chapters = set(started[:-1])
    if workers == 1:  # one at a time: a thread of this process (the kernels are processes of their own)
        executor = ThreadPoolExecutor(max_workers=1)
    else:
        executor = ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("spawn"))
    with executor as pool:
        pending: dict = {}
        if report and REPORT_ONLY_MODELS and len(started) > 1:  # beside chapters; the overview alone: at the end
            pending[pool.submit(_report_only_stages, workers > 1)] = _EARLY_STAGES
            chapters.add(_EARLY_STAGES)  # the report waits for it as for a chapter
        pending.update({pool.submit(_timed_execution, path, timeout, workers > 1): path for path in started})
        claims_due = report
        if claims_due and not started:  # no notebook: the claims alone
            pending[pool.submit(_evaluated_claims, workers > 1)] = None
            claims_due = False
        progress = tqdm(total=len(pending) + int(report), desc="notebooks and claims")
        try:
            while pending:
                finished, _ = wait(pending, return_when=FIRST_COMPLETED)
                for future in finished:
                    path = pending.pop(future)
                    progress.update()
                    if path is _EARLY_STAGES:
                        future.result()
                        chapters.discard(_EARLY_STAGES)
                        tqdm.write(f"the stages of the claims on {', '.join(REPORT_ONLY_MODELS)} computed")
                        continue
                    if path is None:
                        table = future.result()
                        tqdm.write("the paper's claims evaluated")
                        continue
                    nb, elapsed = future.result()
                    done[path] = nb
                    chapters.discard(path)
                    tqdm.write(f"{path.name}: {elapsed:.1f} s")
                if claims_due and not chapters:  # every chapter ended: the stages are in the cache
                    pending[pool.submit(_evaluated_claims, workers > 1)] = None
                    claims_due = False
        except BaseException:
            _stop_workers(pool)
            pool.shutdown(wait=True, cancel_futures=True)
            raise
        finally:
            progress.close()
    return {path: done[path] for path in paths}, table


#: Seconds a terminated worker has to end (its kernel shut down) before it is killed.
STOP_GRACE = 5.0


def _stop_workers(pool) -> None:
    """End a failed run's process pool now: its workers are terminated, not waited for (a worker may be
    minutes into a cold chapter or the report-only stages; a stage it leaves unfinished writes nothing,
    the cache writing each entry whole). A worker executing a notebook does not end on SIGTERM:
    nbclient's handler shuts its kernel down and carries on, and the pool would wait for it for ever;
    so each worker still alive after :data:`STOP_GRACE` s is killed (a kernel ends with its parent).
    A thread pool's one worker cannot be stopped: it ends its task. The workers are the executor's
    ``_processes`` (no public way to end them before Python 3.14's ``terminate_workers``)."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    for process in processes:
        process.terminate()
    deadline = time.monotonic() + STOP_GRACE
    for process in processes:
        process.join(max(0.0, deadline - time.monotonic()))
        if process.is_alive():
            process.kill()


def reproduce(
    paths: list[Path],
    out: Path,
    timeout: int = CELL_TIMEOUT,
    report: bool = True,
    workers: int | None = None,
    seconds: dict[Path, float] | None = None,
) -> tuple[list[dict[str, str]], object]:
    """Execute ``paths`` (``workers`` at a time, default :data:`WORKERS`, longest expected ``seconds``
    first), then write figures, index and (with ``report``) the report.

    Returns the figure index rows and the report table (or ``None``). Raises
    :class:`ReproductionError` before writing anything if a notebook fails or a figure is missing.
    """
    executed, table = _execute_all(paths, timeout, WORKERS if workers is None else workers, seconds, report)
    if executed and not any(figure_names(nb, p.stem) for p, nb in executed.items()):
        raise ReproductionError("the notebooks produced no figure at all")
    out.parent.mkdir(parents=True, exist_ok=True)
    _remove_stale(out)
    staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=out.parent))
    try:
        rows = _write_figures(executed, staging)
        if table is not None:
            claims.write_report(table, staging)
        _swap_in(staging, out)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    for path, nb in executed.items():
        _write_notebook(provenance.stamp(portable_outputs(nb)), path)
    return rows, table


def _summary(table, where: Path) -> int:
    print(f"report: {where / 'reproduction-report.md'} and .csv")
    for line in claims.summary(table).splitlines():
        print(f"  {line}")
    for cid, row in claims.unexpected_failures(table).iterrows():
        for model in claims.models_of(table):
            if row[f"verdict ({model})"] == "fail" and not row[f"deviation ({model})"]:
                print(
                    f"  FAILED on {model}: {cid}: {row['claim']} (paper {row['paper']}, ours {row[f'ours ({model})']})"
                )
    return claims.exit_status(table)


def output_folder_problem(out: Path) -> str:
    """Why the reproduction could not write its figures to ``out`` ("" if it can), found before any
    notebook runs: a file in the way, or a parent folder that cannot be written."""
    existing = next((p for p in (out, *out.parents) if p.exists()), None)
    if existing is None:
        return "no part of the path exists"
    if not existing.is_dir():
        return f"{existing} is a file, not a folder"
    if not os.access(existing, os.W_OK | os.X_OK):
        return f"{existing} cannot be written"
    return ""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Execute every notebook in order, write the figures and the report.")
    parser.add_argument("--notebooks", type=Path, default=REPO_ROOT / "notebooks")
    parser.add_argument("--figures", type=Path, default=None, help="output folder (default figures/)")
    parser.add_argument("--report-only", action="store_true", help="skip the notebooks, only evaluate the claims")
    parser.add_argument(
        "--timeout", type=int, default=CELL_TIMEOUT, help=f"per-cell limit in s (default {CELL_TIMEOUT})"
    )
    parser.add_argument(
        "--workers",
        type=int,
        default=WORKERS,
        help=f"notebooks run at a time (default {WORKERS}: two, one on a single core)",
    )
    parser.add_argument(
        "--print",
        choices=["notebook-table", "gallery"],
        help="only print the README's generated notebook table or the book's figure gallery",
    )
    args = parser.parse_args(argv)
    if args.print:
        print(markdown_table() if args.print == "notebook-table" else gallery_markdown())
        return 0
    if args.timeout <= 0:
        parser.error(f"--timeout = {args.timeout} s: valid range is > 0 s")
    if args.workers < 1:
        parser.error(f"--workers = {args.workers}: valid range is >= 1")
    out = args.figures or figure_dir()
    problem = output_folder_problem(out)
    if problem:
        parser.error(f"--figures {out}: {problem}")
    if args.report_only:
        print("evaluating the paper's claims ...")
        table = claims.report(models=claims.MODELS)
        claims.write_report(table, out)
        return _summary(table, out)
    ready = [nb for nb in notebooks() if nb["status"] == "ready"]
    paths = [args.notebooks / nb["file"] for nb in ready]
    seconds = {args.notebooks / nb["file"]: float(nb.get("cold_seconds", 0.0)) for nb in ready}
    missing = [str(p) for p in paths if not p.is_file()]
    if missing:
        parser.error(f"--notebooks {args.notebooks}: missing {', '.join(missing)}")
    try:
        rows, table = reproduce(paths, out, args.timeout, workers=args.workers, seconds=seconds)
    except ReproductionError as exc:
        print(f"reproduction failed, nothing written: {exc}")
        return 2
    print(f"{len(rows)} figures written to {out}")
    return _summary(table, out)
