"""Benchmark of the loaded FE tire beside the waveguide tire of the same file and section, in one run.

Run on demand (never as a timed test; the nonlinear loading takes minutes)::

    python benchmarks/bench_loaded_tire.py                      # 20 mm arcs, loaded to the file's load
    python benchmarks/bench_loaded_tire.py --arcs 0.02 0.01     # two footprint arc lengths
    python benchmarks/bench_loaded_tire.py --no-nonlinear       # the linearised comparison alone

Both tires discretise the 165/65 R14 file's section at ``--crown`` and ``--sidewall`` elements;
the swept solids take arcs of ``--arcs`` (m) over the footprint sector (+-0.28 rad), growing to
60 mm. For each loaded mesh:

1. build, inflation and the tread's compliance about the inflated state (times);
2. the flat road on the solids linearised about the inflated state (the geometric nonlinearity
   switched off) beside the waveguide tire, both by the same contact solve, at 1-4.5 kN:
   deflection and tangent K_v, and their ratio;
3. the nonlinear loading in road steps of ``--step`` (m) up to the file's load: per step the
   road force, the tangent K_v, the footprint (length x width of the held nodes), the
   linearised tire's force at the same lift, and the time.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import static as section_static
from roadnoise_utils.tire.loaded import linearised, statics
from roadnoise_utils.tire.loaded.mesh import graded_arcs

LOADS = (1000.0, 2000.0, 3000.0, 4512.0)


def footprint(tire: statics.LoadedTire, state: statics.StaticState) -> tuple[float, float]:
    """Length and width (m) of the held nodes' deformed positions."""
    x = tire.mesh.coordinates[state.contact] + state.u.reshape(-1, 3)[state.contact]
    return float(np.ptp(x[:, 0])), float(np.ptp(x[:, 1]))


def waveguide(spec, loads) -> list:
    t0 = time.perf_counter()
    states = section_static.solve_section_statics(section_static.build_section_tire(spec), "flat", list(loads))
    print(f"waveguide tire: build and {len(loads)} loads in {time.perf_counter() - t0:.1f} s")
    return states


def compare_linearised(compliance: linearised.ContactCompliance, states: list) -> None:
    print("  load N | deflection mm solids / waveguide | K_v N/mm solids / waveguide (ratio)")
    for state in states:
        linear = linearised.flat_road_at_load(compliance, state.load)
        print(
            f"  {state.load:6.0f} | {linear.deflection * 1e3:6.2f} / {state.deflection * 1e3:6.2f}"
            f" | {linear.stiffness / 1e3:6.1f} / {state.vertical_stiffness / 1e3:6.1f}"
            f" ({linear.stiffness / state.vertical_stiffness:.3f})"
        )


def load_nonlinear(tire, inflated, compliance, load: float, step: float) -> None:
    print("  lift mm | force N (linearised) | K_v N/mm | footprint mm | s")
    state, lift, t_total = None, 0.0, time.perf_counter()
    while state is None or state.road_force < load:
        lift += step
        t0 = time.perf_counter()
        state = statics.press_on_flat_road(tire, inflated, lift, steps=1, start=state)
        seconds = time.perf_counter() - t0
        k_v = statics.vertical_stiffness(tire, state)
        length, width = footprint(tire, state)
        linear = linearised.flat_road_at_lift(compliance, lift).load
        print(
            f"  {lift * 1e3:7.1f} | {state.road_force:7.0f} ({linear:7.0f}) | {k_v / 1e3:6.1f}"
            f" | {length * 1e3:5.1f} x {width * 1e3:5.1f} | {seconds:5.1f}",
            flush=True,
        )
    print(f"  loaded to {state.road_force:.0f} N in {time.perf_counter() - t_total:.0f} s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14_cross_section")
    parser.add_argument("--crown", type=int, default=4)
    parser.add_argument("--sidewall", type=int, default=2)
    parser.add_argument("--arcs", type=float, nargs="+", default=[0.02])
    parser.add_argument("--step", type=float, default=0.001)
    parser.add_argument("--no-nonlinear", dest="nonlinear", action="store_false")
    args = parser.parse_args()
    # one contact column per tassello column: the coarse crown's tread nodes are ~15 mm apart
    section = {"mesh.crown_elements": args.crown, "mesh.sidewall_elements": args.sidewall}
    spec = ru.load_tire(args.tire).replace(**section, **{"tasselli.strips_per_column": 1})
    states = waveguide(spec, LOADS)
    for arc in args.arcs:
        t0 = time.perf_counter()
        tire = statics.build_loaded_tire(spec, graded_arcs(0.28, arc, 0.3, 0.06))
        t1 = time.perf_counter()
        inflated = statics.inflate(tire)
        t2 = time.perf_counter()
        compliance = linearised.contact_compliance(tire, inflated)
        t3 = time.perf_counter()
        print(
            f"solids, {arc * 1e3:.0f} mm arcs: {tire.n_dof} DOF; build {t1 - t0:.1f} s, inflation {t2 - t1:.1f} s, "
            f"compliance of {compliance.nodes.size} tread nodes {t3 - t2:.1f} s"
        )
        compare_linearised(compliance, states)
        if args.nonlinear:
            load_nonlinear(tire, inflated, compliance, spec.operating.vertical_load, args.step)


if __name__ == "__main__":
    main()
