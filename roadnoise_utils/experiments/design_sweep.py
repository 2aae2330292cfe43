"""Design sweeps: a grid or a sample of tire-file parameters -> one table row per design, on dask.

::

    table = ru.experiments.sweep(
        {"tread.normal_stiffness_per_area": [0.9e9, 1.2e9, 1.5e9], "operating.inflation_pressure": [2.0e5, 2.6e5]},
        outputs=["K_v", "f1", "zeta1", "cleat"],
    )

Each design is a tire file with some parameters overridden (:mod:`.design`: the names are the
file's own dotted keys, checked with every value before any work); its outputs come from the
package's experiments and are cached per design, so a sweep interrupted half-way resumes where it
stopped (a second call computes only what the first did not finish).

Where the designs run (``scheduler``):

* ``None`` (default): a local dask cluster of processes, one single-threaded worker per core
  the process may use (at most one per design), BLAS limited to one thread in each, closed
  when the sweep ends;
* an address (``"tcp://host:8786"``) or a :class:`distributed.Client`: that cluster (its
  workers need the package installed and, to share the cache, the same
  ``ROADNOISE_CACHE_DIR``);
* ``"serial"``: one after the other in this process (no dask).

A design that fails does not stop the others (their results are cached): the sweep then raises
:class:`SweepError` naming each failed design, its parameters and the error, with the table of
the designs that succeeded; ``errors="record"`` instead returns the failed rows with NaN outputs
and the message in an ``error`` column.
"""

from __future__ import annotations

import contextlib
import logging
import os
import time
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import dask
import numpy as np
import pandas as pd
from scipy.stats import qmc
from threadpoolctl import threadpool_limits
from tqdm.auto import tqdm

from .. import guards
from ..repro import stages
from .design import (
    CHEAP_OUTPUTS,
    Design,
    DesignResult,
    Spec,
    SweepConditions,
    check_outputs,
    column,
    evaluate_design,
    make_designs,
    output_columns,
    sweep_conditions,
    sweep_parameters,
)

#: What ``scheduler`` may name besides an address or a client.
SERIAL = "serial"
#: What ``errors`` may be.
ERROR_MODES = ("raise", "record")


class SweepError(RuntimeError):
    """Designs of a sweep failed; the others were computed (and cached).

    Attributes
    ----------
    failures : dict of int to BaseException
        Design index -> the exception it raised.
    table : pandas.DataFrame
        The sweep's table with the failed designs' outputs NaN and their message in ``error``.
    """

    def __init__(self, message: str, failures: dict[int, BaseException], table: pd.DataFrame) -> None:
        super().__init__(message)
        self.failures = failures
        self.table = table


def usable_cores() -> int:
    """Cores this process may run on (its CPU affinity where the system tells it, else the CPU count)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - macOS, Windows
        return os.cpu_count() or 1


def sample(ranges: Mapping[str, tuple[float, float]], n: int, seed: int = 0) -> pd.DataFrame:
    """A Latin-hypercube sample of ``n`` designs over ``ranges`` (name -> (low, high), SI units).

    :class:`scipy.stats.qmc.LatinHypercube` seeded by ``seed``; pass the result to :func:`sweep`
    as its ``parameters``. The ranges are checked against the tire file by :func:`sweep`.
    """
    n = guards.integer("n", n, 1)
    if not ranges:
        raise ValueError("ranges: give at least one parameter, name -> (low, high)")
    bounds = {name: guards.interval(f"ranges[{name!r}]", pair, unit="") for name, pair in ranges.items()}
    unit = qmc.LatinHypercube(d=len(bounds), rng=np.random.default_rng(guards.seed(seed))).random(n)
    lows, highs = (np.array([b[k] for b in bounds.values()]) for k in (0, 1))
    return pd.DataFrame(qmc.scale(unit, lows, highs), columns=list(bounds))


def _task(spec: Spec, outputs: tuple[str, ...], conditions: SweepConditions, cache: bool) -> DesignResult:
    """One design on a worker: BLAS on one thread (the cluster runs one design per core)."""
    with threadpool_limits(1, user_api="blas"):
        return evaluate_design(spec, outputs, conditions, cache)


def _describe_error(design: Design, exc: BaseException) -> str:
    return f"{design.describe()}: {type(exc).__name__}: {exc}"


def _run_serial(designs: list[Design], run: tuple, bar: tqdm) -> dict[int, DesignResult | BaseException]:
    found: dict[int, DesignResult | BaseException] = {}
    for design in designs:
        try:
            found[design.index] = evaluate_design(design.spec, *run)
        except Exception as exc:  # reported with its design once every design has run
            found[design.index] = exc
        bar.update()
    return found


def _client(scheduler: Any, n_workers: int) -> tuple[Any, Any]:
    """``(client, cluster)`` this call opens and must close: a local cluster of ``n_workers`` processes and its
    client for ``None``; a client of the given address (no cluster); nothing for a given client (the caller's)."""
    from distributed import Client, LocalCluster

    if isinstance(scheduler, Client):
        return None, None
    if scheduler is None:
        with _glibc_trim_threshold():
            cluster = LocalCluster(
                n_workers=n_workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",  # any free port: several sweeps (or users) on one machine would fight for :8787
                silence_logs=logging.ERROR,
            )
        return Client(cluster), cluster
    return Client(scheduler), None


@contextlib.contextmanager
def _glibc_trim_threshold():
    """Spawn workers without distributed's ``MALLOC_TRIM_THRESHOLD_`` of 64 KiB.

    Set, it makes glibc hand every freed block above 64 KiB back to the system (and fixes its mmap
    threshold), so each frequency's sparse factorisation faults its pages in again: a design took
    4.6 s in a worker against 2.9 s in this process (measured, 165/65 R14, ``K_v, f1, zeta1``);
    without it 3.3 s against 3.4 s. The value is taken out of the config the nannies spawn with and,
    for the spawn, out of this process's environment, where an earlier cluster's nannies leave it
    (``os.environ.update`` in ``distributed.nanny``); a value of the user's own is kept. The BLAS and
    OpenMP thread limits stay.
    """
    spawn = dask.config.get("distributed.nanny.pre-spawn-environ", {}) or {}
    injected = str(spawn.get(_TRIM, ""))
    environ = {k: v for k, v in spawn.items() if k != _TRIM}
    left = os.environ.get(_TRIM)
    if left is not None and left == injected:
        del os.environ[_TRIM]
    try:
        with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
            yield
    finally:
        if left is not None and _TRIM not in os.environ:
            os.environ[_TRIM] = left


_TRIM = "MALLOC_TRIM_THRESHOLD_"


def _run_dask(
    designs: list[Design], run: tuple, bar: tqdm, scheduler: Any, n_workers: int
) -> dict[int, DesignResult | BaseException]:
    from distributed import as_completed

    own, cluster = _client(scheduler, n_workers)
    client = scheduler if own is None else own
    found: dict[int, DesignResult | BaseException] = {}
    try:
        futures = {
            client.submit(_task, d.spec, *run, key=f"roadnoise-design-{d.index}-{os.getpid()}-{time.time_ns()}"): d
            for d in designs
        }
        for future in as_completed(futures):
            design = futures[future]
            if future.status == "error":
                found[design.index] = future.exception()
            else:
                found[design.index] = future.result()
            future.release()
            bar.update()
    finally:
        if own is not None:
            own.close()
        if cluster is not None:
            cluster.close()
    return found


def sweep(
    parameters: Mapping[str, Sequence[float]] | pd.DataFrame | Sequence[Mapping[str, float]],
    outputs: str | Iterable[str] = CHEAP_OUTPUTS,
    *,
    tire: str | Spec = "165_65R14",
    conditions: SweepConditions | None = None,
    scheduler: Any = None,
    n_workers: int | None = None,
    progress: bool = True,
    errors: str = "raise",
    cache: bool = True,
) -> pd.DataFrame:
    """Run a design sweep: one row per design, its parameters and outputs (SI units in the column names).

    Parameters
    ----------
    parameters : mapping, DataFrame or list of mappings
        Dotted tire-file names (``"operating.inflation_pressure"``;
        :func:`~.design.sweep_parameters` lists them) with their values: a mapping of lists is
        the full grid (the last name varying fastest), a DataFrame (e.g. :func:`sample`) or a
        list of mappings one design per row.
    outputs : str or iterable of str
        Any of :data:`~.design.OUTPUTS`: ``"K_v"``, ``"footprint"``, ``"f1"``, ``"zeta1"``,
        ``"cleat"`` (linear RM chain on the drum), ``"one_sided"`` (the FE tire with contact loss,
        ~20 s a ring design), ``"hub_acceleration"`` (quarter car on the road test). Default
        :data:`~.design.CHEAP_OUTPUTS`.
    tire : str or spec
        The tire file the designs start from (ring or cross-section), default the paper's.
    conditions : SweepConditions, optional
        The tests the outputs run; default :func:`~.design.sweep_conditions` (the paper's).
    scheduler : None, "serial", str or distributed.Client
        Where the designs run (module notes): a local cluster, this process, or a given cluster.
    n_workers : int, optional
        Workers of the local cluster; default one per usable core, at most one per design.
    progress : bool
        A progress bar over the designs (:mod:`tqdm.auto`).
    errors : {"raise", "record"}
        A failed design raises :class:`SweepError` once all have run, or is recorded in the table.
    cache : bool
        Cache each design's result (resume after an interruption); False recomputes every
        design (its stages still come from the stage cache).

    Returns
    -------
    pandas.DataFrame
        Index ``design`` (0, 1, ...); the parameter columns (``"<name> (<unit>)"``), the output
        columns and ``warnings`` (what each design's computation warned about, "" if nothing).
        ``attrs``: ``computed`` and ``from_cache`` (designs computed in this call and read from
        the cache), ``seconds`` (wall time), ``scheduler``, ``design_seconds`` and
        ``design_cpu_seconds`` (each design's wall and CPU time where it ran, s).

    Raises
    ------
    ValueError
        Bad parameters, outputs or options, before any work (:func:`~.design.make_designs`).
    SweepError
        Designs failed (``errors="raise"``); the others are in its ``table`` and in the cache.
    """
    start = time.perf_counter()
    guards.flag("progress", progress)
    guards.flag("cache", cache)
    spec = stages.load_tire(tire)
    outputs = check_outputs(outputs)
    if errors not in ERROR_MODES:
        raise ValueError(f"errors = {errors!r}: valid values are {list(ERROR_MODES)}")
    designs = make_designs(spec, parameters)
    if isinstance(scheduler, str) and scheduler != SERIAL and "://" not in scheduler and ":" not in scheduler:
        raise ValueError(f"scheduler = {scheduler!r}: valid values are None, {SERIAL!r}, an address or a Client")
    workers = min(usable_cores(), len(designs)) if n_workers is None else guards.integer("n_workers", n_workers, 1)
    conditions = sweep_conditions() if conditions is None else conditions
    run = (outputs, conditions, bool(cache))
    with tqdm(total=len(designs), desc="designs", unit="design", disable=not progress) as bar:
        if scheduler == SERIAL:
            found = _run_serial(designs, run, bar)
        else:
            found = _run_dask(designs, run, bar, scheduler, workers)
    table = _table(designs, found, output_columns(outputs), spec)
    results = [r for r in found.values() if isinstance(r, DesignResult)]
    table.attrs.update(
        parameters=[column(k, units) for k, units in _units(designs, spec).items()],
        outputs=output_columns(outputs),
        computed=sum(r.computed for r in results),
        from_cache=sum(not r.computed for r in results),
        seconds=time.perf_counter() - start,
        scheduler=SERIAL if scheduler == SERIAL else ("local" if scheduler is None else str(scheduler)),
        design_seconds=[r.seconds if isinstance(r, DesignResult) else float("nan") for _, r in sorted(found.items())],
        design_cpu_seconds=[
            r.cpu_seconds if isinstance(r, DesignResult) else float("nan") for _, r in sorted(found.items())
        ],
    )
    failures = {i: r for i, r in found.items() if isinstance(r, BaseException)}
    warned = int((table["warnings"] != "").sum())
    if warned:
        guards.warn(f"{warned} of {len(designs)} designs gave warnings: see the table's 'warnings' column", 2)
    if failures and errors == "raise":
        lines = "\n".join(_describe_error(designs[i], exc) for i, exc in sorted(failures.items()))
        error = SweepError(f"{len(failures)} of {len(designs)} designs failed:\n{lines}", failures, table)
        raise error from next(iter(failures.values()))
    return table


def _table(
    designs: list[Design], found: dict[int, DesignResult | BaseException], outputs: list[str], spec: Spec
) -> pd.DataFrame:
    units = _units(designs, spec)
    rows = []
    for design in designs:
        result = found[design.index]
        row: dict[str, Any] = {column(k, units[k]): v for k, v in design.overrides.items()}
        if isinstance(result, DesignResult):
            row.update(result.values, warnings="; ".join(result.warnings))
        else:
            row.update(dict.fromkeys(outputs, float("nan")), warnings="")
            row["error"] = f"{type(result).__name__}: {result}"
        rows.append(row)
    table = pd.DataFrame(rows, index=pd.Index([d.index for d in designs], name="design"))
    order = [column(k, units[k]) for k in designs[0].overrides] + outputs + ["warnings"]
    if "error" in table:
        table["error"] = table["error"].fillna("")
        order.append("error")
    return table[order]


def _units(designs: list[Design], spec: Spec) -> dict[str, str]:
    units = sweep_parameters(spec)["unit"]
    return {name: units[name] for name in designs[0].overrides}


def effects(
    table: pd.DataFrame, parameters: Sequence[str] | None = None, outputs: Sequence[str] | None = None
) -> pd.DataFrame:
    """Relative change of each output from the lowest to the highest value of each parameter, the others held.

    For every parameter column, the designs at its highest value are paired with those at its
    lowest value that share all the other parameters (a grid has one pair per combination of
    the others); the table gives ``high / low - 1`` averaged over the pairs (NaN without a pair,
    as in a random sample). Finite differences of the table, nothing fitted.

    Parameters
    ----------
    table : pandas.DataFrame
        A :func:`sweep` table.
    parameters, outputs : sequence of str, optional
        Its parameter and output columns; default those the sweep recorded in ``table.attrs``.

    Returns
    -------
    pandas.DataFrame
        Rows ``"<parameter column>: <low> -> <high>"``, columns the outputs (relative changes, -).
    """
    parameters = list(table.attrs["parameters"] if parameters is None else parameters)
    outputs = list(table.attrs["outputs"] if outputs is None else outputs)
    rows = {}
    for name in parameters:
        others = [p for p in parameters if p != name]
        lo, hi = table[name].min(), table[name].max()
        low, high = table[table[name] == lo], table[table[name] == hi]
        pairs = (
            low.merge(high, on=others, suffixes=(" low", " high"))
            if others
            else low.merge(high, how="cross", suffixes=(" low", " high"))
        )
        change = {
            o: float((pairs[f"{o} high"] / pairs[f"{o} low"] - 1.0).mean()) if len(pairs) else float("nan")
            for o in outputs
        }
        rows[f"{name}: {lo:.4g} -> {hi:.4g}"] = change
    return pd.DataFrame.from_dict(rows, orient="index", columns=outputs)
