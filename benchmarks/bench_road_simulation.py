"""Benchmark of the road simulation: aggregated per track (FFT) against per tassello, side by side.

Run on demand (never as a timed test)::

    python benchmarks/bench_road_simulation.py

The 195/65 R15's fixed-hub tire (its fits, one input per tassello) on a 2-D rough road at
30 m/s, 9.6 kHz, for 2e5 and 2e6 samples: ``rm.aggregated.road_hub_force`` (one kernel per
track and phase, the inputs never formed) against ``road.input.profile_input`` followed by
``rm.simulation.simulate`` (every modal section on its tassello's input), and python-control's
``forced_response`` on the same inputs (the state space of the fits; at 2e5 samples, at 2e6 too
with ``--forced-response-2e6``: ~10 min, in ten consecutive pieces of 2e5 samples, each starting
from the state the previous one ended in: exact for its first-order hold, and the 1022 states'
history of a piece, 3 GB, fits in memory where the whole record's 30 GB would not). Times are ranges over repeats (the machines are shared);
peak memory is what numpy allocates during the call (tracemalloc), the road itself excluded; the
forces are compared. ``road evaluation`` is the road function alone on the fine grid, the floor of
every method. Run with ``ROADNOISE_MAX_BYTES=8000000000``: the per-tassello inputs need 5 GiB
of the 4 GiB default at 2e6.
"""

from __future__ import annotations

import argparse
import time
import tracemalloc

import control
import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.rm import aggregated, simulation
from roadnoise_utils.road.input import profile_input, road_grid


def _measure(function, repeat: int):
    times, out, peak = [], None, 0
    for _ in range(repeat):
        tracemalloc.start()
        start = time.perf_counter()
        out = function()
        times.append(time.perf_counter() - start)
        peak = max(peak, tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
    return times, peak, out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="195_65R15")
    parser.add_argument("--speed", type=float, default=30.0, help="m/s")
    parser.add_argument("--sample-rate", type=float, default=9600.0)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--forced-response-2e6", action="store_true", help="also at 2e6 samples (~10 min)")
    args = parser.parse_args()
    static = ru.stages.solve_static(args.tire)
    args.system = ru.assemble_fixed_hub(ru.stages.fit_tasselli(args.tire))
    sections = simulation.modal_sections(args.system)
    dt = 1.0 / args.sample_rate
    print(f"{args.tire}: {static.tasselli.n} tasselli, {len(sections.sections)} modal sections, "
          f"memory {aggregated.memory_length(sections, dt)} steps; 2-D road at {args.speed:g} m/s, "
          f"{args.sample_rate:g} Hz")  # fmt: skip
    print("| samples | method | time (s) | peak memory (MB) | speed-up | largest difference |")
    print("|---|---|---|---|---|---|")
    for n in (200_000, 2_000_000):
        _one_size(n, static, sections, args)


def _one_size(n: int, static, sections, args) -> None:
    dt = 1.0 / args.sample_rate
    travel = (n - 1) * args.speed * dt
    rng = np.random.default_rng(1)
    x = np.linspace(-2.0, travel + 2.0, int((travel + 4.0) / 1e-3) + 1)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))

    def profile(s):
        return np.interp(s, x, z)

    def ours():
        return aggregated.road_hub_force(sections, static, profile, args.speed, (0.0, travel), args.sample_rate)

    def per_tassello():
        return simulation.simulate(
            sections, profile_input(static, profile, args.speed, (0.0, travel), args.sample_rate)
        )

    def road_alone():
        where = road_grid(static, profile, args.speed, (0.0, travel), args.sample_rate)
        return [heights(0, where.n_fine) for _, heights in where.track_heights()]

    repeat = args.repeat if n <= 200_000 else 2
    road_t, _, _ = _measure(road_alone, repeat)
    agg_t, agg_m, agg = _measure(ours, repeat)
    per_t, per_m, per = _measure(per_tassello, repeat)
    difference = np.abs(agg.force - per.force).max() / np.abs(per.force).max()
    print(f"| {agg.t.size} | aggregated (FFT per track) | {min(agg_t):.2f} - {max(agg_t):.2f} | "
          f"{agg_m / 1e6:.0f} | {min(per_t) / max(agg_t):.1f} - {max(per_t) / min(agg_t):.1f}x | {difference:.1e} |")  # fmt: skip
    print(f"| {per.t.size} | per tassello (profile_input + simulate) | {min(per_t):.2f} - {max(per_t):.2f} | "
          f"{per_m / 1e6:.0f} | 1 | - |")  # fmt: skip
    if n <= 200_000 or args.forced_response_2e6:
        road = profile_input(static, profile, args.speed, (0.0, travel), args.sample_rate)
        ref_t, ref_m, ref = _measure(lambda: _forced_response_in_pieces(args.system, road.t, road.u), 1)
        difference = np.abs(agg.force - ref).max() / np.abs(ref).max()
        print(f"| {road.t.size} | python-control forced_response (inputs given) | {ref_t[0]:.1f} | {ref_m / 1e6:.0f} | "
              f"{ref_t[0] / max(agg_t):.0f}x slower than aggregated | {difference:.1e} |")  # fmt: skip
    print(f"| {agg.t.size} | road evaluation alone (the floor) | {min(road_t):.2f} - {max(road_t):.2f} | - | - | - |")


def _forced_response_in_pieces(system, t: np.ndarray, u: np.ndarray, piece: int = 200_000) -> np.ndarray:
    """python-control's ``forced_response`` over consecutive pieces sharing their end samples, each from the
    state the previous one ended in (one piece when the record is no longer)."""
    out = np.empty(t.size)
    state = np.zeros(system.nstates)
    start = 0
    while start < t.size - 1:
        stop = min(start + piece, t.size - 1)
        response = control.forced_response(
            system, T=t[start : stop + 1], U=u[:, start : stop + 1], X0=state, return_x=True
        )
        out[start : stop + 1] = np.ravel(response.outputs)
        state = response.states[:, -1]
        start = stop
    return out


if __name__ == "__main__":
    main()
