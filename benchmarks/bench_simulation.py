"""Benchmark of the time-domain stage: our block-diagonal simulation vs python-control, side by side.

Run on demand (never as a timed test)::

    python benchmarks/bench_simulation.py            # full: 200 000 steps for both
    python benchmarks/bench_simulation.py --steps 20000

Drives the fixed-hub tire with random tassello displacements (the cost does not depend on the
signal) for ``--steps`` samples at 10 kHz: the paper-sized model (8 poles per tassello) and
ours (the order of notebook 03). Both simulators use the same FOH assumption; their outputs
are compared.
"""

from __future__ import annotations

import argparse
import time

import control
import numpy as np

import roadnoise_utils as ru


def timed(fn, *args, **kwargs):
    t0 = time.perf_counter()
    out = fn(*args, **kwargs)
    return time.perf_counter() - t0, out


def ours(system, road):
    return ru.simulate(ru.rm.modal_sections(system), road).force


def reference(system, t, u):
    return control.forced_response(system, T=t, U=u).outputs


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--steps", type=int, default=200_000)
    args = parser.parse_args()
    tire = ru.load_tire(args.tire)
    visco = ru.stages.frf_visco(tire)
    rng = np.random.default_rng(0)
    print(f"tire {tire.name}, {args.steps} steps at 10 kHz, random inputs")
    print("| model | states | ours (s) | python-control forced_response (s) | speed-up | max rel. difference |")
    print("|---|---|---|---|---|---|")
    for poles in (8, ru.stages.fit_tasselli(tire).n_poles):
        system = ru.assemble_fixed_hub(ru.fit_tasselli(visco.freqs, visco.H, n_poles=poles, f_max=250.0))
        t = np.arange(args.steps) / 10_000.0
        u = 1e-3 * rng.standard_normal((system.ninputs, args.steps))
        road = ru.RoadInput(t=t, distance=t, u=u, speed=1.0, description="random")
        t_ours, fast = timed(ours, system, road)
        t_ref, ref = timed(reference, system, t, u)
        diff = np.max(np.abs(fast - ref)) / np.max(np.abs(ref))
        print(
            f"| {poles} poles per tassello | {system.nstates} | {t_ours:.3f} | {t_ref:.1f} | "
            f"{t_ref / t_ours:.0f}x | {diff:.1e} |"
        )


if __name__ == "__main__":
    main()
