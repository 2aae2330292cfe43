"""Benchmark of the cleat test with one-sided contact, beside the linear chain, in one run.

Run on demand (never as a timed test)::

    python benchmarks/bench_contact.py               # 3 repeats
    python benchmarks/bench_contact.py --repeats 5
    python benchmarks/bench_contact.py --repeats 2 --cross-section 165_65R14_cross_section

Times, as ranges over the repeats (shared machines are noisy): the one-sided quasi-static run
(contact solves) and the 30 km/h run (Newmark, 0.7 m of travel) on the refined tire of
notebook 08, the same two runs of the linear RM chain (notebook 04) and the linear FE
frequency-domain passage (its second method), each also as a ratio to that FE passage's time
(the best of each run's repeats over the FE passage's best: the reference timed in the same
run, so a loaded machine shifts both). Tire stages are built once before timing;
the one-sided runs include their own set-up (factorisation, dynamic compliance). With
``--cross-section`` the cross-section tire's runs too (notebook 08, section 6): the reduction of
its harmonics (once) and its quasi-static and 30 km/h runs.
"""

from __future__ import annotations

import argparse
import time
import tracemalloc

import roadnoise_utils as ru
from roadnoise_utils.road.cleat import cleat_profile
from roadnoise_utils.tire.ring import one_sided


def timed(repeats: int, fn, *args, **kwargs) -> tuple[list[float], object]:
    times, out = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn(*args, **kwargs)
        times.append(time.perf_counter() - t0)
    return times, out


def span(times: list[float]) -> str:
    return f"{min(times):.2f} - {max(times):.2f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--cross-section", default="", help="also time this cross-section tire's runs (slow)")
    args = parser.parse_args()
    conditions = ru.experiments.one_sided_conditions()
    cleat = conditions.cleat
    refined = ru.experiments.one_sided_cleat.refined_tire(args.tire, conditions.n_elements)
    fet = ru.build_fet(refined)
    static = ru.stages.solve_static(refined, "drum", drum_radius=cleat.drum_radius)
    profile = cleat_profile(cleat.height, cleat.base, cleat.shape)
    spec = ru.load_tire(args.tire)
    drum = ru.stages.solve_static(spec, "drum", drum_radius=cleat.drum_radius)
    sections = ru.rm.modal_sections(ru.stages.assemble_fixed_hub(spec, road="drum", drum_radius=cleat.drum_radius))
    fet_linear = ru.build_fet(spec)
    rows = []
    t, qs = timed(args.repeats, one_sided.quasi_static_run, fet, static, profile, conditions.distance)
    rows.append(
        ("one-sided, quasi-static (contact solves)", refined.mesh.n_elements, t, qs.peak_force, len(qs.distance))
    )
    tracemalloc.start()
    t, dyn = timed(args.repeats, one_sided.dynamic_run, fet, static, profile, cleat.dynamic_speed, conditions.distance)
    peak_memory = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    rows.append(
        (f"one-sided, {cleat.dynamic_kmh:.0f} km/h (Newmark)", refined.mesh.n_elements, t, dyn.peak_force, len(dyn.t))
    )
    run = ru.experiments.cleat.run_cleat
    args_cleat = (drum, None, cleat.height, cleat.base, cleat.shape)
    for label, speed in (
        ("quasi-static", cleat.quasi_static_speed),
        (f"{cleat.dynamic_kmh:.0f} km/h", cleat.dynamic_speed),
    ):
        t, out = timed(
            args.repeats, run, sections, drum, speed, *args_cleat[2:], distance=conditions.distance, dynamic=False
        )
        rows.append((f"linear RM chain, {label}", spec.mesh.n_elements, t, out.peak_force, out.result.force.size))
    t, (_, force) = timed(
        args.repeats, ru.tire.ring.fe_reference.fe_cleat_response, fet_linear, drum, cleat.dynamic_speed, cleat.height, cleat.base,
        cleat.shape, conditions.distance,
    )  # fmt: skip
    rows.append(
        (f"linear FE, frequency domain, {cleat.dynamic_kmh:.0f} km/h", spec.mesh.n_elements, t, force.max(), force.size)
    )
    if args.cross_section:
        rows += cross_section_rows(args.cross_section, args.repeats, conditions)
    print(
        f"tire {spec.name}, cleat {cleat.height * 1e3:.0f} x {cleat.base * 1e3:.0f} mm, travel {conditions.distance} m, {args.repeats} repeats"
    )
    reference = next(times for label, _, times, _, _ in rows if label.startswith("linear FE"))
    print("| run | elements | time (s), min - max | x the linear FE run (best / best) | peak (N) | samples |")
    print("|---|---|---|---|---|---|")
    for label, elements, times, peak, samples in rows:
        print(f"| {label} | {elements} | {span(times)} | {min(times) / min(reference):.2f} | {peak:.0f} | {samples} |")
    print(f"peak Python memory of the one-sided {cleat.dynamic_kmh:.0f} km/h run: {peak_memory / 1e6:.0f} MB")


def cross_section_rows(tire: str, repeats: int, conditions) -> list[tuple]:
    """The cross-section tire's one-sided runs: its harmonics' reduction, the quasi-static and the 30 km/h run."""
    from roadnoise_utils.tire.cross_section import one_sided as section_one_sided
    from roadnoise_utils.tire.cross_section import stepping as section_stepping

    cleat = conditions.cleat
    built = ru.section_stages.section_tire(tire)
    static = ru.stages.solve_static(tire, "drum", drum_radius=cleat.drum_radius)
    profile = cleat_profile(cleat.height, cleat.base, cleat.shape)
    label = "cross-section"
    t, reduced = timed(1, section_stepping.reduce_all, built, 400.0)
    rows = [(f"{label}: reduce and make passive its 401 harmonics", "-", t, float("nan"), len(reduced))]
    t, qs = timed(
        repeats, section_one_sided.section_quasi_static_run, built, static, profile, conditions.sweep_distance, 1e-3
    )
    rows.append((f"{label}: one-sided, quasi-static (1 mm steps)", "-", t, qs.peak_force, len(qs.distance)))
    t, dyn = timed(
        repeats, section_one_sided.section_dynamic_run, built, static, profile, cleat.dynamic_speed, conditions.distance,
        dt=ru.tire.cross_section.model.CONTACT_DT, reduced=reduced,
    )  # fmt: skip
    rows.append((f"{label}: one-sided, {cleat.dynamic_kmh:.0f} km/h (raw peak)", "-", t, dyn.peak_force, len(dyn.t)))
    t, pair = timed(
        repeats, section_one_sided.section_dynamic_runs, built, static, profile, cleat.dynamic_speed,
        conditions.distance, dt=ru.tire.cross_section.model.CONTACT_DT, frozen=(False, True), reduced=reduced,
    )  # fmt: skip
    label_pair = f"{label}: one-sided and frozen {cleat.dynamic_kmh:.0f} km/h runs stepped together (raw peaks)"
    rows.append((label_pair, "-", t, pair[0].peak_force, len(pair[0].t)))
    return rows


if __name__ == "__main__":
    main()
