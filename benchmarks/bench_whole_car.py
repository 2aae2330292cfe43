"""Benchmark of the whole vehicle: 10 s at 120 km/h on four corners, road to all spectra, beside the quarter car.

Run on demand (never as a timed test)::

    python benchmarks/bench_whole_car.py [--repeats 5]

Both on the rough texture's 3-D road (a track per belt strip), at the same sample rate, with the
tire's stages cached. The whole car: one road with the tracks of all four wheels
(:func:`roadnoise_utils.road.two_track.two_track_road`), each wheel's tassello inputs, the four
fixed-hub forces (fast simulation), the car closed through G_H at every corner
(:func:`roadnoise_utils.rm.simulation.response`), and the Welch spectra of its 18 outputs plus
the two axles' left/right coherence. The quarter car: the same steps for one corner (notebook 07).
Reports the range over the repeats (the machine is shared).
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.experiments import whole_car
from roadnoise_utils.road import contact_tracks, profile_input, two_track
from roadnoise_utils.vehicle import car_spectra, full_car, spectra


def _quarter_car(setup, spectrum, speed: float, duration: float, rate: float) -> list[float]:
    length = speed * duration
    marks = [time.perf_counter()]
    profile = ru.textures.generate_field(spectrum, length + 5.0, 0.004, contact_tracks(setup.static), seed=1).as_3d()
    marks.append(time.perf_counter())
    road = profile_input(setup.static, profile, speed, (0.0, length), sample_rate=rate, oversample=1)
    marks.append(time.perf_counter())
    force = ru.simulate(setup.sections, road).force
    marks.append(time.perf_counter())
    outputs = ru.rm.response(setup.model, road.t, force[None, :])
    marks.append(time.perf_counter())
    _ = [spectra.psd(y, road.sample_rate) for y in outputs]
    marks.append(time.perf_counter())
    return list(np.diff(marks))


def _whole_car(setup, spectrum, speed: float, duration: float, rate: float) -> list[float]:
    travel, static, positions = speed * duration, setup.tire.static, setup.car.positions
    marks = [time.perf_counter()]
    road = two_track.two_track_road(spectrum, static, positions, travel, seed=1)
    marks.append(time.perf_counter())
    inputs = two_track.wheel_inputs(static, road, positions, speed, (0.0, travel), sample_rate=rate)
    marks.append(time.perf_counter())
    forces = np.array([ru.simulate(setup.tire.sections, inputs[c]).force for c in full_car.CORNERS])
    marks.append(time.perf_counter())
    outputs = ru.rm.response(setup.model, inputs["FL"].t, forces)
    marks.append(time.perf_counter())
    run = full_car.FullCarRun(inputs["FL"].t, forces, dict(zip(setup.model.output_labels, outputs)))
    car_spectra.car_spectra(run)
    marks.append(time.perf_counter())
    return list(np.diff(marks))


def main() -> None:
    test = whole_car.whole_car_conditions()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speed-kmh", type=float, default=test.speed_kmh)
    parser.add_argument("--duration", type=float, default=test.duration)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    setup = whole_car.whole_car_setup()
    speed, spectrum = args.speed_kmh / 3.6, test.spectrum
    rate = ru.road.sample_rate_for(speed)
    print(f"{setup.tire.tire.name} on {setup.car.name}: {args.duration:g} s at {args.speed_kmh:g} km/h, {rate:.0f} Hz")
    print(f"range over {args.repeats} repeats (s)\n")
    steps = ("road", "tassello inputs", "F_F, fast simulation", "car + its G_H", "spectra")
    print("| model | " + " | ".join(steps) + " | total | goal |")
    print("|---|" + "---|" * (len(steps) + 2))
    runs = {
        "quarter car (1 corner)": (_quarter_car, setup.tire, "< 2"),
        "whole car (4 corners)": (_whole_car, setup, "< 3"),
    }
    for label, (bench, given, goal) in runs.items():
        times = np.array([bench(given, spectrum, speed, args.duration, rate) for _ in range(args.repeats)])
        cells = [f"{lo:.2f}-{hi:.2f}" for lo, hi in zip(times.min(axis=0), times.max(axis=0))]
        total = times.sum(axis=1)
        print(f"| {label} | " + " | ".join(cells) + f" | {total.min():.2f}-{total.max():.2f} | {goal} |")


if __name__ == "__main__":
    main()
