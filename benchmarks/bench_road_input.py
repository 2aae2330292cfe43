"""Benchmark of the road input on a 2-D road: one correlation for every strip against one per strip.

Run on demand (never as a timed test)::

    python benchmarks/bench_road_input.py

A road uniform across the width puts one track under every belt strip, so ``profile_input``
correlates it once with all the strips' kernels. The same road given as a
3-D road, ``profile(s, y)``, takes the per-strip path (one correlation per strip). Both run on
the 195/65 R15 at 120 km/h over the rough-road test's length and sample rate; the times are
ranges over repeats (the machines are shared), the inputs equal to round-off.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.road import profile_input


def _times(function, repeat: int) -> tuple[list[float], object]:
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = function()
        times.append(time.perf_counter() - start)
    return times, out


def main() -> None:
    road_test = ru.experiments.road_test_conditions()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="195_65R15")
    parser.add_argument("--speed-kmh", type=float, default=120.0)
    parser.add_argument("--duration", type=float, default=road_test.duration)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    static = ru.stages.solve_static(args.tire)
    speed = args.speed_kmh / 3.6
    length = args.duration * speed
    rng = np.random.default_rng(1)
    x = np.linspace(-1.0, length + 1.0, int(length / 1e-3) + 1)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))
    fs = ru.road.input.sample_rate_for(speed)
    strips = np.unique(static.tasselli.node_strip).size
    one, uniform = _times(
        lambda: profile_input(static, lambda s: np.interp(s, x, z), speed, (0.0, length)), args.repeat
    )
    each, per_strip = _times(
        lambda: profile_input(static, lambda s, y: np.interp(s, x, z), speed, (0.0, length)), args.repeat
    )
    difference = np.abs(uniform.u - per_strip.u).max() / np.abs(per_strip.u).max()
    print(f"{args.tire}, {args.speed_kmh:g} km/h, {args.duration:g} s at {fs:g} Hz: {uniform.u.shape[1]} samples "
          f"x {uniform.u.shape[0]} tasselli, {strips} belt strips")  # fmt: skip
    print(f"2-D road, one correlation:      {min(one):.3f} - {max(one):.3f} s")
    print(f"same road per strip (3-D form): {min(each):.3f} - {max(each):.3f} s "
          f"({min(each) / max(one):.1f} - {max(each) / min(one):.1f}x)")  # fmt: skip
    print(f"largest difference: {difference:.1e} of the largest input")


if __name__ == "__main__":
    main()
