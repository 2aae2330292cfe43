"""Benchmark of the cross-section FE tire beside the ring model, in one run.

Run on demand (never as a timed test)::

    python benchmarks/bench_cross_section.py               # 3 repeats
    python benchmarks/bench_cross_section.py --repeats 5

Times, as ranges over the repeats (shared machines are noisy), of both tire models of the
165/65 R14: building the model, the loaded static solve on the flat road, and the footprint
FRFs 0-400 Hz every 1 Hz (cross-section: the footprint receptance and hub transfer of
:mod:`roadnoise_utils.tire.cross_section.footprint`; ring: :func:`roadnoise_utils.tire.ring.frf.frf_visco`,
the direct sweep of the same quantity), and the paper's modal reduction (Fig. 4) with the
modal FRFs it gives in place of the direct sweep. "x ring" is each cross-section step's best
time over the ring's best for the same step, timed in the same run. Then the cross-section's
footprint FRFs beside the same solve with every harmonic evaluated at every frequency
(``interpolate=False``, the reference of the harmonics interpolated in frequency): both times, their
ratio and the largest deviations (per tassello relative to its peak; H_tot at every frequency). Peak memory by ``tracemalloc`` (Python allocations,
numpy arrays included) of the last repeat of each step.
"""

from __future__ import annotations

import argparse
import resource
import time
import tracemalloc

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import footprint as section_footprint
from roadnoise_utils.tire.cross_section import modal as section_modal
from roadnoise_utils.tire.cross_section import static as section_static
from roadnoise_utils.tire.ring import frf, modal_reduction, static


def timed(repeats: int, fn, *args, **kwargs) -> tuple[list[float], object, float]:
    """Wall times of ``repeats`` calls, the last result and its peak traced memory (MB)."""
    times, out = [], None
    for i in range(repeats):
        if i == repeats - 1:
            tracemalloc.start()
        t0 = time.perf_counter()
        out = fn(*args, **kwargs)
        times.append(time.perf_counter() - t0)
    peak = tracemalloc.get_traced_memory()[1] / 1e6
    tracemalloc.stop()
    return times, out, peak


def span(times: list[float]) -> str:
    return f"{min(times):.2f} - {max(times):.2f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ring", default="165_65R14")
    parser.add_argument("--cross-section", default="165_65R14_cross_section")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    freqs = np.arange(0.0, 401.0, 1.0)
    rows = []

    spec = ru.load_tire(args.cross_section)
    t, tire, peak = timed(args.repeats, section_static.build_section_tire, spec)
    rows.append(("cross-section", "build (mesh, harmonic matrices, inflation)", t, peak))
    t, state, peak = timed(args.repeats, section_static.solve_section_static, tire)
    rows.append(("cross-section", f"loaded static solve ({state.contact.sum()} points in contact)", t, peak))
    t, direct, peak = timed(args.repeats, section_footprint.footprint_frf, tire, state, freqs)
    rows.append(("cross-section", "footprint receptance + hub transfer, 0-400 Hz at 1 Hz", t, peak))
    visco = direct.to_frf_result()
    t, reduced, peak = timed(args.repeats, section_modal.section_modal_reduction, tire, state, visco)
    n_modes = reduced.model.eigenvalues.size
    rows.append(("cross-section", f"modal reduction, band 250 Hz ({n_modes} loaded modes, synthesis)", t, peak))
    t, _, peak = timed(args.repeats, reduced.model.frf, freqs)
    rows.append(("cross-section", "modal FRFs (H_i, H_tot, G_H), 0-400 Hz at 1 Hz", t, peak))

    ring = ru.load_tire(args.ring)
    t, fet, peak = timed(args.repeats, ru.build_fet, ring)
    rows.append(("ring", "build (8103 DOF)", t, peak))
    t, ring_state, peak = timed(args.repeats, static.solve_static, fet)
    rows.append(("ring", f"loaded static solve ({ring_state.contact.sum()} points in contact)", t, peak))
    t, ring_visco, peak = timed(args.repeats, frf.frf_visco, fet, ring_state, freqs, progress=False)
    rows.append(("ring", "direct FRF sweep (H_i, H_tot), 0-400 Hz at 1 Hz", t, peak))
    t, ring_reduced, peak = timed(args.repeats, modal_reduction.modal_reduction, fet, ring_state, visco=ring_visco)
    n_modes = ring_reduced.model.eigenvalues.size
    rows.append(("ring", f"modal reduction, band 250 Hz ({n_modes} loaded modes, symmetric subspace)", t, peak))
    t, _, peak = timed(args.repeats, ring_reduced.model.frf, freqs)
    rows.append(("ring", "modal FRFs (H_i, H_tot, G_H), 0-400 Hz at 1 Hz", t, peak))

    half = len(rows) // 2  # the cross-section's steps, then the ring's same steps in the same order
    ratios = [min(a[2]) / min(b[2]) for a, b in zip(rows[:half], rows[half:])] + [1.0] * half
    print(f"{'model':14s} {'step':62s} {'time (s)':>14s} {'x ring':>8s} {'peak (MB)':>10s}")
    for (model, step, t, peak), ratio in zip(rows, ratios):
        print(f"{model:14s} {step:62s} {span(t):>14s} {ratio:8.1f} {peak:10.0f}")
    t_ref, reference, peak_ref = timed(
        args.repeats, section_footprint.footprint_frf, tire, state, freqs, interpolate=False
    )
    t_fast = rows[2][2]
    fast_i, ref_i = direct.H_tasselli(), reference.H_tasselli()
    per_tassello = np.max(np.abs(fast_i - ref_i).max(axis=0) / np.abs(ref_i).max(axis=0))
    total = np.max(np.abs(direct.H_tot - reference.H_tot) / np.abs(reference.H_tot))
    print(
        f"\ncross-section footprint FRFs 0-400 Hz at 1 Hz, the same run: smooth harmonics interpolated "
        f"{span(t_fast)} s, every harmonic at every frequency {span(t_ref)} s ({peak_ref:.0f} MB); "
        f"x {min(t_ref) / min(t_fast):.2f} (best), {max(t_ref) / max(t_fast):.2f} (worst); "
        f"max |dH_i| / max|H_i| {per_tassello:.1e}, max |dH_tot| / |H_tot| {total:.1e}"
    )
    print(f"process peak resident memory: {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")


if __name__ == "__main__":
    main()
