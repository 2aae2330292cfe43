"""Benchmark of the fitting stage: our batched relaxed vector fitting vs scikit-rf, side by side.

Run on demand (never as a timed test)::

    python benchmarks/bench_fitting.py

Fits the direct local FRFs of every tassello (0-250 Hz) at the paper's order (8) and at the
order the pipeline uses, with both implementations in one run; best of ``--repeat`` runs. Then
our fits with BLAS limited to one thread (as ``fit_tasselli`` runs them) and with the library's
default threads, ranges over the repeats; ``--contend`` keeps one core busy meanwhile (two
notebooks at once, as the reproduction runs them), where the threads fight.
"""

from __future__ import annotations

import argparse
import subprocess
import sys

import numpy as np
from threadpoolctl import threadpool_info, threadpool_limits

import roadnoise_utils as ru


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument(
        "--contend", action="store_true", help="keep one core busy with another process (as a second notebook would)"
    )
    args = parser.parse_args()
    busy = subprocess.Popen([sys.executable, "-c", "while True: pass"]) if args.contend else None
    try:
        _run(args)
    finally:
        if busy is not None:
            busy.kill()


def _run(args) -> None:
    tire = ru.load_tire(args.tire)
    visco = ru.stages.frf_visco(tire)
    order = ru.stages.fit_tasselli(tire).n_poles
    n = visco.H.shape[0]
    print(f"tire {tire.name}: {n} tassello FRFs, 0-250 Hz at 1 Hz")
    print("| poles | method | max rms error | median rms error | time for all fits (s) | goal |")
    print("|---|---|---|---|---|---|")
    blas_rows = []
    for poles in (8, order):
        ours = min(
            (ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles) for _ in range(args.repeat)),
            key=lambda fits: fits.seconds,
        )
        peer = min(
            (ru.rm.fitting_peer.skrf_vector_fit(visco.freqs, visco.H, poles) for _ in range(args.repeat)),
            key=lambda result: result[1],
        )
        with threadpool_limits(None, user_api="blas"):  # BLAS threads back to the library's default
            ru.rm.fitting.FIT_THREADS, saved = None, ru.rm.fitting.FIT_THREADS
            try:
                threaded = [ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles).seconds for _ in range(args.repeat)]
            finally:
                ru.rm.fitting.FIT_THREADS = saved
        one = [ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles).seconds for _ in range(args.repeat)]
        blas_rows.append(f"| {poles} | {min(one):.3f} - {max(one):.3f} | {min(threaded):.3f} - {max(threaded):.3f} |")
        goal = "<= 0.2" if poles == order else "-"
        print(
            f"| {poles} | roadnoise (batched relaxed VF) | {ours.rms_errors.max():.4f} | "
            f"{np.median(ours.rms_errors):.4f} | {ours.seconds:.3f} | {goal} |"
        )
        print(
            f"| {poles} | scikit-rf VectorFitting | {peer[0].max():.4f} | {np.median(peer[0]):.4f} | "
            f"{peer[1]:.3f} | - |"
        )

    beside = ", one core kept busy by another process" if args.contend else ""
    print(f"\nBLAS threads inside our fits ({threadpool_info()[0].get('num_threads', '?')} by default here{beside}), "
          f"time for all fits over {args.repeat} repeats (s):")  # fmt: skip
    print("| poles | 1 thread (FIT_THREADS) | library default |")
    print("|---|---|---|")
    print("\n".join(blas_rows))


if __name__ == "__main__":
    main()
