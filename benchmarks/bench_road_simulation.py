"""Benchmark of the road simulation against its floor and its peers, side by side in one run.

Run on demand (never as a timed test)::

    python benchmarks/bench_road_simulation.py                # 2e5 and 2e6 samples, 2-D and 3-D roads
    python benchmarks/bench_road_simulation.py --sizes 200000 --repeat 5

The 195/65 R15's fixed-hub tire (its fits, one input per tassello, 520 modal sections) on a rough
road at 30 m/s, 9.6 kHz, uniform across the width (2-D, one track) or varying across it (3-D, one
track per belt strip in contact). Timed in the same run, each a range over ``--repeat`` repeats
(the machines are shared: compare the ratios, not the seconds):

* ``road_hub_force``, first call: the tire's and the speed's path built (the kernels of every track
  and phase and their spectra, ``rm.aggregated.road_path``), then the road;
* ``road_hub_force``, repeated call: the same tire and speed, the path kept;
* the floor: the road evaluated on exactly the grid ``road_hub_force`` reads (every track and phase)
  plus one FFT convolution (scipy's overlap-add ``oaconvolve``) of each track's and phase's heights
  with a kernel of the impulse responses' length;
* per tassello: ``road.input.profile_input`` then ``rm.simulation.simulate`` (every modal section on its
  tassello's input), at 2e5 samples (at 2e6 with ``--per-tassello-2e6`` and
  ``ROADNOISE_MAX_BYTES=8000000000``: the inputs need 5 GiB);
* python-control's ``forced_response`` on the same inputs (the fits' state space, 1022 states), at 2e5
  samples on the 2-D road (its cost does not depend on the road).

The forces are compared with the per-tassello simulation's (largest difference relative to the
largest force). Peak memory is what numpy allocates during a call (tracemalloc), the road itself excluded.
"""

from __future__ import annotations

import argparse
import time
import tracemalloc

import control
import numpy as np
from scipy.signal import oaconvolve

import roadnoise_utils as ru
from roadnoise_utils.rm import aggregated, simulation
from roadnoise_utils.road.input import profile_input, road_grid


def _measure(function, repeat: int, before=None):
    times, out, peak = [], None, 0
    for _ in range(repeat):
        if before is not None:
            before()
        tracemalloc.start()
        start = time.perf_counter()
        out = function()
        times.append(time.perf_counter() - start)
        peak = max(peak, tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
    return np.array(times), peak, out


def _range(values) -> str:
    return f"{np.min(values):.3g} - {np.max(values):.3g}"


def _ratio(slow, fast) -> str:
    """The range of ``slow / fast`` over the repeats' extremes."""
    return f"{np.min(slow) / np.max(fast):.3g} - {np.max(slow) / np.min(fast):.3g}"


def _road(travel: float, lateral: bool):
    rng = np.random.default_rng(1)
    x = np.linspace(-2.0, travel + 2.0, int((travel + 4.0) / 1e-3) + 1)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))
    if lateral:  # the tracks see the road shifted by their lateral position: as many different tracks as strips
        return lambda s, y: np.interp(s + 5.0 * y, x, z)
    return lambda s: np.interp(s, x, z)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="195_65R15")
    parser.add_argument("--speed", type=float, default=30.0, help="m/s")
    parser.add_argument("--sample-rate", type=float, default=9600.0)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--sizes", type=int, nargs="+", default=[200_000, 2_000_000])
    parser.add_argument("--per-tassello-2e6", action="store_true", help="also the per-tassello simulation at 2e6")
    parser.add_argument("--no-forced-response", action="store_true", help="skip python-control (~1 min)")
    args = parser.parse_args()
    static = ru.stages.solve_static(args.tire)
    args.system = ru.assemble_fixed_hub(ru.stages.fit_tasselli(args.tire))
    sections = simulation.modal_sections(args.system)
    dt = 1.0 / args.sample_rate
    args.memory = aggregated.memory_length(sections, dt)
    print(f"{args.tire}: {static.tasselli.n} tasselli, {len(sections.sections)} modal sections, "
          f"memory {args.memory} steps; {args.speed:g} m/s, {args.sample_rate:g} Hz, {args.repeat} repeats")  # fmt: skip
    print("| samples | road | method | time (s) | peak memory (MB) | against the floor | largest difference |")
    print("|---|---|---|---|---|---|---|")
    for n in args.sizes:
        for lateral in (False, True):
            _one_size(n, lateral, static, sections, args)


def _floor(static, profile, args, travel: float):
    """The road on the grid road_hub_force reads, and one overlap-add convolution per track and phase."""
    # the grid alone (no inputs are formed: profile_input's memory check does not apply)
    where = road_grid(static, profile, args.speed, (0.0, travel), args.sample_rate, check_memory=lambda *_: None)
    o = where.oversample
    kernel = np.random.default_rng(0).standard_normal(args.memory)

    def run():
        total = np.zeros(where.t.size + args.memory - 1)
        for _, heights in where.track_heights():
            z = heights(0, o * (where.t.size + 64)).reshape(-1, o).T
            for phase in z:
                total += oaconvolve(phase, kernel)[: total.size]
        return total

    return run


def _one_size(n: int, lateral: bool, static, sections, args) -> None:
    travel = (n - 1) * args.speed / args.sample_rate
    profile = _road(travel, lateral)
    name = "3-D" if lateral else "2-D"

    def ours():
        return aggregated.road_hub_force(sections, static, profile, args.speed, (0.0, travel), args.sample_rate)

    floor_t, _, _ = _measure(_floor(static, profile, args, travel), args.repeat)
    first_t, first_m, first = _measure(ours, args.repeat, before=aggregated._PATHS.clear)
    again_t, again_m, again = _measure(ours, args.repeat)
    difference = "-"
    per_t = None
    if n <= 200_000 or args.per_tassello_2e6:

        def per_tassello():
            return simulation.simulate(sections, profile_input(static, profile, args.speed, (0.0, travel),
                                                               args.sample_rate))  # fmt: skip

        per_t, per_m, per = _measure(per_tassello, 1)
        error = np.abs(again.force - per.force).max() / np.abs(per.force).max()
        difference = f"{error:.1e} (vs per tassello)"
    rows = [
        ("road_hub_force, first call", first_t, first_m, difference),
        ("road_hub_force, repeated call", again_t, again_m, difference),
        ("the floor: road + one FFT convolution per track and phase", floor_t, 0, "-"),
    ]
    if per_t is not None:
        rows.append(("per tassello: profile_input + simulate", per_t, per_m, "-"))
    for method, times, memory, diff in rows:
        print(
            f"| {n} | {name} | {method} | {_range(times)} | {memory / 1e6:.0f} | {_ratio(times, floor_t)}x | {diff} |"
        )
    if n <= 200_000 and not lateral and not args.no_forced_response:
        road = profile_input(static, profile, args.speed, (0.0, travel), args.sample_rate)
        forced_t, forced_m, response = _measure(
            lambda: control.forced_response(args.system, T=road.t, U=road.u).outputs, 1
        )
        error = np.abs(again.force - np.ravel(response)).max() / np.abs(response).max()
        print(f"| {n} | {name} | python-control forced_response (inputs given) | {_range(forced_t)} | "
              f"{forced_m / 1e6:.0f} | {_ratio(forced_t, floor_t)}x | {error:.1e} |")  # fmt: skip
        print(f"| {n} | {name} | forced_response / road_hub_force | first call {_ratio(forced_t, first_t)}x, "
              f"repeated call {_ratio(forced_t, again_t)}x | - | - | - |")  # fmt: skip


if __name__ == "__main__":
    main()
