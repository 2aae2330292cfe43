"""Benchmark of the design sweep: designs per minute, in this process against a local dask cluster.

Run on demand (never as a timed test)::

    python benchmarks/bench_sweep.py [--designs 8] [--repeat 2] [--outputs K_v f1 zeta1]

The same grid of ring designs (inflation pressure x tread stiffness around the paper's tire)
runs with ``scheduler="serial"`` and on the default local cluster (one single-threaded worker
process per usable core), each repeat on an empty stage cache so every design computes all its
stages (static state, direct FRF, ...). The cluster's time includes starting and closing it (and
the workers' imports); its start-up alone is timed apart; "one design's own time" is the mean
wall time of a design where it ran (``table.attrs["design_seconds"]``): about the same in both
modes when a core is free for each worker, longer on the cluster when the host's cores are
taken by other work (the 1-minute load average is printed; "CPU / wall" is the share of a core a
design had, below 1 when it waited for one). Both must give the same table.
Ranges over the repeats: the machines are shared; the speed-up of the cluster is the ratio of
the two wall times of each repeat (run one after the other).
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np
import pandas as pd

import roadnoise_utils as ru
from roadnoise_utils.experiments.design_sweep import usable_cores


def _grid(n: int) -> dict[str, list[float]]:
    """``n`` designs (an even number): n/2 pressures around 2.3 bar x two tread stiffnesses."""
    pressures = np.linspace(2.0e5, 2.6e5, max(n // 2, 1)).round(-2).tolist()
    return {"operating.inflation_pressure": pressures, "tread.normal_stiffness_per_area": [1.2e9, 1.5e9]}


def _timed_sweep(grid: dict, outputs: list[str], scheduler) -> tuple[float, pd.DataFrame]:
    with tempfile.TemporaryDirectory(prefix="bench-sweep-") as cache:
        os.environ["ROADNOISE_CACHE_DIR"] = cache  # the cluster's workers inherit it
        start = time.perf_counter()
        table = ru.experiments.sweep(grid, outputs, scheduler=scheduler, progress=False)
        return time.perf_counter() - start, table


def _cluster_start() -> float:
    from distributed import Client, LocalCluster

    start = time.perf_counter()
    with LocalCluster(n_workers=usable_cores(), threads_per_worker=1, dashboard_address=":0") as cluster:
        with Client(cluster) as client:
            client.run(lambda: __import__("roadnoise_utils") is not None)  # the workers' imports
            return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--designs", type=int, default=8)
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--outputs", nargs="+", default=list(ru.experiments.design.CHEAP_OUTPUTS))
    args = parser.parse_args()
    grid = _grid(args.designs)
    n = int(np.prod([len(v) for v in grid.values()]))
    times: dict[str, list[float]] = {"serial": [], "dask": []}
    each: dict[str, list[float]] = {"serial": [], "dask": []}
    share: dict[str, list[float]] = {"serial": [], "dask": []}
    tables = {}
    load = [os.getloadavg()[0]]
    for _ in range(args.repeat):
        for name, scheduler in (("serial", "serial"), ("dask", None)):
            seconds, tables[name] = _timed_sweep(grid, args.outputs, scheduler)
            times[name].append(seconds)
            each[name].append(float(np.mean(tables[name].attrs["design_seconds"])))
            share[name].append(
                float(np.sum(tables[name].attrs["design_cpu_seconds"]) / np.sum(tables[name].attrs["design_seconds"]))
            )
    load.append(os.getloadavg()[0])
    start = [_cluster_start() for _ in range(args.repeat)]
    pd.testing.assert_frame_equal(tables["serial"], tables["dask"])
    print(f"{n} ring designs of 165_65R14, outputs {args.outputs}, {usable_cores()} usable cores, empty cache each run")
    print(f"host load average (1 min) before and after: {load[0]:.1f}, {load[1]:.1f}")
    print(
        "| run | wall time (s) | designs per minute | wall time per design (s) | one design's own time (s) | CPU / wall of a design |"
    )
    print("|---|---|---|---|---|---|")
    for name, label in (("serial", "serial (this process)"), ("dask", f"dask, local cluster of {usable_cores()}")):
        t, e, c = np.array(times[name]), np.array(each[name]), np.array(share[name])
        print(
            f"| {label} | {t.min():.1f} - {t.max():.1f} | {60 * n / t.max():.1f} - {60 * n / t.min():.1f} "
            f"| {t.min() / n:.2f} - {t.max() / n:.2f} | {e.min():.2f} - {e.max():.2f} | {c.min():.2f} - {c.max():.2f} |"
        )
    speedup = np.array(times["serial"]) / np.array(times["dask"])  # each repeat ran both, one after the other
    print(f"serial over dask wall time, per repeat: {speedup.min():.2f} - {speedup.max():.2f}x")
    print(f"cluster start-up with the workers' imports, and close: {min(start):.1f} - {max(start):.1f} s")
    print("tables equal: yes")


if __name__ == "__main__":
    main()
