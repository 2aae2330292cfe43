"""Benchmark of the fitting stage: our batched relaxed vector fitting vs scikit-rf, side by side.

Run on demand (never as a timed test)::

    python benchmarks/bench_fitting.py

Fits the direct local FRFs of every tassello (0-250 Hz) at the paper's order (8) and at the
order the pipeline uses, with both implementations in one run; best of ``--repeat`` runs.
"""

from __future__ import annotations

import argparse

import numpy as np

import roadnoise_utils as ru


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    tire = ru.load_tire(args.tire)
    visco = ru.stages.frf_visco(tire)
    order = ru.stages.fit_tasselli(tire).n_poles
    n = visco.H.shape[0]
    print(f"tire {tire.name}: {n} tassello FRFs, 0-250 Hz at 1 Hz")
    print("| poles | method | max rms error | median rms error | time for all fits (s) | goal |")
    print("|---|---|---|---|---|---|")
    for poles in (8, order):
        ours = min(
            (ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles) for _ in range(args.repeat)),
            key=lambda fits: fits.seconds,
        )
        peer = min(
            (ru.rm.fitting_peer.skrf_vector_fit(visco.freqs, visco.H, poles) for _ in range(args.repeat)),
            key=lambda result: result[1],
        )
        goal = "<= 0.2" if poles == order else "-"
        print(
            f"| {poles} | roadnoise (batched relaxed VF) | {ours.rms_errors.max():.4f} | "
            f"{np.median(ours.rms_errors):.4f} | {ours.seconds:.3f} | {goal} |"
        )
        print(
            f"| {poles} | scikit-rf VectorFitting | {peer[0].max():.4f} | {np.median(peer[0]):.4f} | "
            f"{peer[1]:.3f} | - |"
        )


if __name__ == "__main__":
    main()
