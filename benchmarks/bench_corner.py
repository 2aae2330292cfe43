"""Benchmark of the vehicle stage: 10 s at 120 km/h sampled at 10 kHz, road to spectra.

Run on demand (never as a timed test)::

    python benchmarks/bench_corner.py

Times each step for a 2D road and a laterally varying 3D road (one track per belt strip) on
the 195/65 R15 front corner, with the tire's stages cached (they are computed once per tire).
For comparison, the same corner response is also computed by python-control on the full
coupled state vector (tire + car, Eq. 8) for the first second of road.
"""

from __future__ import annotations

import argparse
import time

import control
import numpy as np

import roadnoise_utils as ru
from roadnoise_utils import textures
from roadnoise_utils.road import contact_tracks, profile_input
from roadnoise_utils.vehicle import corner, quarter_car, spectra


def main() -> None:
    road_test = ru.experiments.road_test_conditions()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--vehicle", default=ru.experiments.corner.PAPER_CAR)
    parser.add_argument("--speed-kmh", type=float, default=road_test.speed_kmh)
    parser.add_argument("--duration", type=float, default=road_test.duration)
    args = parser.parse_args()
    setup = ru.experiments.corner_setup(args.vehicle)
    car, tire, static, fits, hub = setup.vehicle, setup.tire, setup.static, setup.fits, setup.hub
    rim_side = setup.tire_hub_mass
    speed = args.speed_kmh / 3.6
    length = args.duration * speed
    spectrum = textures.load_texture("rough")
    strips = contact_tracks(static)
    print(f"{tire.name} on {car.name}: {args.duration:g} s at {args.speed_kmh:g} km/h, 10 kHz")
    print(
        "| road | generate road (s) | tassello inputs (s) | F_F, fast simulation (s) | corner + spectra (s) | total (s) | goal |"
    )
    print("|---|---|---|---|---|---|---|")
    for kind in ("2D", "3D"):
        t0 = time.perf_counter()
        model = corner.corner_model(car, hub, rim_side)
        sections = ru.rm.modal_sections(ru.assemble_fixed_hub(fits))
        if kind == "2D":
            profile = textures.generate_profile(spectrum, length + 5.0, 0.004, seed=1).as_2d()
        else:
            profile = textures.generate_field(spectrum, length + 5.0, 0.004, strips, seed=1).as_3d()
        t1 = time.perf_counter()
        road = profile_input(static, profile, speed, (0.0, length), sample_rate=10000, oversample=1)
        t2 = time.perf_counter()
        force = ru.simulate(sections, road).force
        t3 = time.perf_counter()
        outputs = ru.rm.response(model, road.t, force[None, :])
        _ = [spectra.psd(y, road.sample_rate) for y in outputs[1:]]
        t4 = time.perf_counter()
        print(f"| {kind} | {t1 - t0:.2f} | {t2 - t1:.2f} | {t3 - t2:.2f} | {t4 - t3:.2f} | {t4 - t0:.2f} | < 2 |")
    # the full Eq. 8 state vector (moving-hub tire + car) with python-control, first second only
    tire_m = ru.rm.assemble_moving_hub(fits, hub)
    car_ss = quarter_car.vehicle_statespace(quarter_car.with_extra_hub_mass(car, rim_side))
    n_tasselli = len(fits)
    full = control.interconnect(
        [
            control.ss(tire_m, inputs=[f"u{i}" for i in range(n_tasselli)] + ["z_hub"], outputs=["F"], name="tire"),
            control.ss(car_ss, inputs=["F"], outputs=["z_hub", "a_hub", "a_mount"], name="car"),
        ],
        inplist=[f"u{i}" for i in range(n_tasselli)],
        outlist=["a_hub", "a_mount"],
    )
    n = int(1.0 * 10000)
    t0 = time.perf_counter()
    ref = control.forced_response(full, T=road.t[:n], U=road.u[:, :n]).outputs
    t_full = time.perf_counter() - t0
    t0 = time.perf_counter()
    ours = ru.rm.response(
        model,
        road.t[:n],
        ru.simulate(sections, road.excerpt(0, n)).force[None, :],
    )
    t_ours = time.perf_counter() - t0
    diff = np.max(np.abs(ours[1:] - ref)) / np.max(np.abs(ref))
    print(
        f"first 1 s, full Eq. 8 state vector ({full.nstates} states) with python-control: {t_full:.1f} s; "
        f"ours {t_ours:.2f} s; max relative difference {diff:.1e}"
    )


if __name__ == "__main__":
    main()
