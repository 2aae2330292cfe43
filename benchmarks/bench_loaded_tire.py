"""Benchmark of the loaded FE tire beside the waveguide tire of the same file and section, in one run.

Run on demand (never as a timed test; the nonlinear loading takes minutes)::

    python benchmarks/bench_loaded_tire.py                      # 20 mm arcs, loaded to the file's load
    python benchmarks/bench_loaded_tire.py --arcs 0.02 0.01     # two footprint arc lengths
    python benchmarks/bench_loaded_tire.py --no-nonlinear       # the linearised comparison alone
    python benchmarks/bench_loaded_tire.py --step 0.002         # road steps of 2 mm
    python benchmarks/bench_loaded_tire.py --convergence        # the tire file's mesh and two refinements
    python benchmarks/bench_loaded_tire.py --file-modes         # the inflated modes on the tire file's mesh

Both tires discretise the 165/65 R14 file's section at ``--crown`` and ``--sidewall`` elements;
the swept solids take arcs of ``--arcs`` (m) over the footprint sector (+-0.28 rad), growing to
60 mm. For each loaded mesh:

1. build, inflation and the tread's compliance about the inflated state (times);
2. the flat road on the solids linearised as the waveguide tire (about the round tire,
   pre-stressed by the linear inflation) and about the inflated state (the loading's geometric
   nonlinearity switched off), beside the waveguide tire, all by the same contact solve, at
   1-4.5 kN: deflection and tangent K_v;
3. the nonlinear loading in road steps of ``--step`` (m) up to the file's load: per step the
   road force, the tangent K_v, the footprint (length x width of the held nodes), the
   linearised tire's force at the same lift, the time, the least acoustic eigenvalue over the
   points (negative where a layer's law has lost strong ellipticity:
   :func:`roadnoise_utils.tire.loaded.solid.ellipticity`), and whether the state is a minimum of
   the potential or a saddle (:func:`roadnoise_utils.tire.loaded.road_contact.is_stable`).

4. the dynamics about the loaded state at the file's load (``--no-dynamics`` skips it): the
   linearisation, the reduced basis and the footprint FRFs 0-400 Hz every 1 Hz (times, modes),
   beside the waveguide tire's FRFs at the same load: H_tot at rest and its first peaks, G_H's
   first peaks, the share of the static stiffness within 15 mm of the footprint's ends (the
   waveguide's: its end rows of tasselli), the tasselli, the peak contact pressure and the linear
   chain's quasi-static peak of the paper's 15 x 15 mm cleat on the flat road (the static
   influences H_i(0) times the cleat's tassello inputs, at its worst position).

``--drum`` instead runs both tires through the tire-model interface on the paper's drum (the
loaded FE tire from its tire file, ``--loaded``; the waveguide of the same section): the loading's
time, deflection, tangent K_v, tasselli and peak pressure, H_tot at rest and its first peaks, the
static influence of the footprint's end rows, and the linear chain's quasi-static peak of the
paper's 15 x 15 mm cleat (:func:`roadnoise_utils.experiments.cleat.quasi_static_peak`).

``--convergence`` loads the loaded FE tire file (``--loaded``) on the flat road at its load on its
own mesh and two refinements (:data:`CONVERGENCE_MESHES`: footprint arcs 20, 14 and 10 mm, crown 4,
6 and 8 and sidewall 2, 3 and 4 elements) through the interface: K_v, the footprint and the first
peak f1 of H_tot (a parabola through the 1 Hz samples), with the times.

``--modes N`` first compares the inflated, unloaded modes n = 0..6 on N uniform arcs with the
waveguide's: each solid mode's harmonic is the one that carries most of its displacement.
``--file-modes`` compares them on the loaded tire file's own graded mesh (``--loaded``).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np
import scipy.sparse.linalg as spla

import roadnoise_utils as ru
from roadnoise_utils.experiments.cleat import quasi_static_force, row_influence
from roadnoise_utils.experiments.paper_defaults import cleat_input
from roadnoise_utils.guards import RoadnoiseWarning
from roadnoise_utils.tire.cross_section import static as section_static
from roadnoise_utils.tire.cross_section.checks import harmonic_frequencies
from roadnoise_utils.tire.cross_section.operators import harmonic_operators
from roadnoise_utils.tire.loaded import dynamics, footprint, linearised, modal, road_contact, solid, stages, statics
from roadnoise_utils.tire.loaded.mesh import graded_arcs
from roadnoise_utils.tire.model import tire_model
from roadnoise_utils.tire.symmetric_factor import SymmetricFactor

LOADS = (1000.0, 2000.0, 3000.0, 4512.0)


#: The tire file's mesh and two refinements, each element length divided by about sqrt(2): footprint arcs (m),
#: crown and sidewall elements of the section.
CONVERGENCE_MESHES = [(0.02, 4, 2), (0.014, 6, 3), (0.01, 8, 4)]


def footprint_size(tire: statics.LoadedTire, state: statics.StaticState) -> tuple[float, float]:
    """Length and width (m) of the held nodes' deformed positions."""
    x = tire.mesh.coordinates[state.contact] + state.u.reshape(-1, 3)[state.contact]
    return float(np.ptp(x[:, 0])), float(np.ptp(x[:, 1]))


def waveguide(spec, loads) -> list:
    t0 = time.perf_counter()
    states = section_static.solve_section_statics(section_static.build_section_tire(spec), "flat", list(loads))
    print(f"waveguide tire: build and {len(loads)} loads in {time.perf_counter() - t0:.1f} s")
    return states


def compare_linearised(round_tire, inflated, states: list) -> None:
    print("  load N | deflection mm: round / inflated / waveguide | K_v N/mm: round / inflated / waveguide")
    for state in states:
        a, b = (linearised.flat_road_at_load(c, state.load) for c in (round_tire, inflated))
        print(
            f"  {state.load:6.0f} | {a.deflection * 1e3:6.2f} / {b.deflection * 1e3:6.2f} / {state.deflection * 1e3:6.2f}"
            f" | {a.stiffness / 1e3:6.1f} / {b.stiffness / 1e3:6.1f} / {state.vertical_stiffness / 1e3:6.1f}"
        )


def compare_modes(spec, tire: statics.LoadedTire, label: str, count: int = 40) -> None:
    """The inflated, unloaded modes n = 0..6 of the solids on ``tire``'s mesh beside the waveguide of its section."""
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    mass = solid.mass_matrix(tire.groups, tire.n_dof)[free][:, free].tocsc()
    ops = harmonic_operators(tire.mesh.section, spec.laws(), spec.operating.inflation_pressure)
    reference = {n: harmonic_frequencies(ops, n)[:2] for n in range(7)}
    inflated = statics.inflate(tire)
    tangents = {
        "round": linearised.round_linearisation(tire).tangent,
        "inflated": statics.residual_and_tangent(tire, inflated.u, inflated.pressure)[1],
    }
    found = {}
    for name, k in tangents.items():
        k_free = k[free][:, free]
        inverse = spla.LinearOperator(k_free.shape, matvec=SymmetricFactor(k_free).solve, dtype=float)
        values, vectors = spla.eigsh(k_free.tocsc(), k=count, M=mass, sigma=0.0, OPinv=inverse)
        full = np.zeros((tire.n_dof, count))
        full[free] = vectors
        order = np.argsort(values)
        harmonics = modal.harmonic_of_modes(tire.mesh.theta, full[:, order])
        for n in range(7):
            f = np.sqrt(values[order][harmonics == n]) / (2 * np.pi)
            found[name, n] = f if n == 0 else f[::2]  # n > 0: the cos and sin pair
    print(f"modes on {label} ({tire.n_dof} DOF), inflated and unloaded, Hz (deviation from the waveguide):")
    print("  n  # | waveguide | round                | inflated")
    for n in range(7):
        for j, f_ref in enumerate(reference[n]):
            cells = []
            for name in tangents:
                f = found[name, n]
                cells.append(f"{f[j]:7.2f} ({100 * (f[j] / f_ref - 1):+5.2f} %)" if j < f.size else "    -")
            print(f"  {n}  {j} | {f_ref:9.2f} | {cells[0]:20s} | {cells[1]}")


def load_nonlinear(tire, inflated, compliance, load: float, step: float) -> statics.StaticState:
    print(
        "  lift mm | force N (linearised) | K_v N/mm | footprint mm | s | least acoustic eigenvalue MPa | minimum of the potential"
    )
    state, lift, t_total = None, 0.0, time.perf_counter()
    while state is None or state.road_force < load:
        lift += step
        t0 = time.perf_counter()
        with warnings.catch_warnings():  # a saddle is reported in the table
            warnings.simplefilter("ignore", RoadnoiseWarning)
            state = road_contact.press_on_road(tire, inflated, lift, steps=1, start=state)
        seconds = time.perf_counter() - t0
        k_v = road_contact.vertical_stiffness(tire, state)
        length, width = footprint_size(tire, state)
        linear = linearised.flat_road_at_lift(compliance, lift).load
        acoustic = min(float(v.min()) for v in solid.ellipticity(tire.groups, state.u))
        print(
            f"  {lift * 1e3:7.1f} | {state.road_force:7.0f} ({linear:7.0f}) | {k_v / 1e3:6.1f}"
            f" | {length * 1e3:5.1f} x {width * 1e3:5.1f} | {seconds:5.1f} | {acoustic / 1e6:7.1f} | {'yes' if state.stable else 'no: a saddle'}",
            flush=True,
        )
    print(f"  loaded to {state.road_force:.0f} N in {time.perf_counter() - t_total:.0f} s")
    lift += (load - state.road_force) / road_contact.vertical_stiffness(tire, state)  # one step back to the load
    state = road_contact.press_on_road(tire, inflated, lift, steps=1, start=state)
    print(f"  at the load: {state.road_force:.0f} N at {lift * 1e3:.2f} mm, a minimum: {state.stable}")
    return state


def peaks(values: np.ndarray, freqs: np.ndarray, count: int = 4) -> str:
    """The first ``count`` local maxima of ``|values|`` above 10 Hz (below, the laws' stiffening alone): frequency
    (Hz) and magnitude (N/mm)."""
    magnitude = np.abs(values)
    local = (magnitude[1:-1] > magnitude[:-2]) & (magnitude[1:-1] > magnitude[2:]) & (freqs[1:-1] > 10.0)
    inner = np.nonzero(local)[0][:count] + 1
    return ", ".join(f"{freqs[i]:.0f} Hz {magnitude[i] / 1e3:.0f}" for i in inner)


def compare_dynamics(spec, tire, state) -> None:
    freqs = np.arange(0.0, 401.0)
    t0 = time.perf_counter()
    lin = dynamics.linearise(tire, state)
    t1 = time.perf_counter()
    reduced = dynamics.reduce(lin, float(freqs.max()))
    t2 = time.perf_counter()
    frf = dynamics.footprint_frf(lin, freqs, reduced)
    t3 = time.perf_counter()
    print(
        f"dynamics about the loaded state: linearise {t1 - t0:.0f} s, reduce {t2 - t1:.0f} s "
        f"({reduced.n_modes} modes at rest below {dynamics.CUTOFF_FACTOR * freqs.max():.0f} Hz, "
        f"{reduced.mass.shape[0]} coordinates), FRFs at {freqs.size} frequencies {t3 - t2:.0f} s"
    )
    model = tire_model(spec)
    case = model.case()
    reference = model.fixed_hub_frfs(case, freqs)
    rows = row_influence(model.load(case), reference.H[:, 0].real)["H(0) of the row (N/mm)"].to_numpy()
    nodes = tire.mesh.coordinates[state.contact]
    theta = np.arctan2(nodes[:, 0], -nodes[:, 2])
    radius = np.hypot(nodes[:, 0], nodes[:, 2]).mean()
    ends = np.abs(theta) * radius > np.abs(theta).max() * radius - 0.015
    share = frf.hub[0].real[ends].sum() / frf.H_tot[0].real
    loaded_fp = footprint.loaded_footprint(tire, state)
    fe_h0 = footprint.frf_result(frf, loaded_fp.tasselli).H[:, 0].real
    section_fp = model.load(case)
    cleat = {
        name: float(quasi_static_force(h0, cleat_input(fp, 0.1, distance=(-0.1, 0.1))).max())
        for name, fp, h0 in (("FE", loaded_fp, fe_h0), ("waveguide", section_fp, reference.H[:, 0].real))
    }
    print(
        f"  footprint: {loaded_fp.tasselli.n} tasselli (waveguide {section_fp.tasselli.n}), peak pressure "
        f"{loaded_fp.node_pressure.max() / 1e6:.2f} MPa (waveguide {section_fp.node_pressure.max() / 1e6:.2f}); "
        f"the linear chain's quasi-static peak of the paper's cleat on the flat road: {cleat['FE']:.0f} N "
        f"(waveguide {cleat['waveguide']:.0f} N)"
    )
    print("  tire      | H_tot(0) N/mm | first peaks of |H_tot| (N/mm)       | of |G_H|                  | ends' share")
    print(
        f"  loaded FE | {frf.H_tot[0].real / 1e3:13.1f} | {peaks(frf.H_tot, freqs):35s} | {peaks(-frf.G_H, freqs, 3):25s} | {share:.2f}"
    )
    print(
        f"  waveguide | {reference.H_tot[0].real / 1e3:13.1f} | {peaks(reference.H_tot, freqs):35s} | "
        f"{peaks(reference.G_H, freqs, 3):25s} | {(rows[0] + rows[-1]) / rows.sum():.2f}"
    )


def compare_on_drum(loaded_name: str) -> None:
    """Both tires on the paper's drum through the tire-model interface (their cached stages)."""
    from roadnoise_utils.experiments.cleat import cleat_conditions, quasi_static_peak

    loaded = tire_model(loaded_name)
    construction = loaded.spec.construction.replace(**{"tasselli.strips_per_column": 1})
    conditions = cleat_conditions()
    print(
        "  tire      | load s | FRFs s | deflection mm | K_v N/mm | tasselli | peak MPa | H_tot(0) N/mm | first peaks of |H_tot| | end rows N/mm | cleat peak N"
    )
    for name, model in (("loaded FE", loaded), ("waveguide", tire_model(construction))):
        case = model.case("drum", drum_radius=conditions.drum_radius)
        t0 = time.perf_counter()
        fp = model.load(case)
        t1 = time.perf_counter()
        frfs = model.fixed_hub_frfs(case)
        t2 = time.perf_counter()
        rows = row_influence(fp, frfs.H[:, 0].real)["H(0) of the row (N/mm)"].to_numpy()
        peak = quasi_static_peak(model, conditions.height, conditions.base, conditions.shape, conditions.drum_radius)
        print(
            f"  {name:9s} | {t1 - t0:6.0f} | {t2 - t1:6.0f} | {fp.deflection * 1e3:13.1f} | {fp.vertical_stiffness / 1e3:8.1f}"
            f" | {fp.tasselli.n:8d} | {fp.node_pressure.max() / 1e6:8.2f} | {frfs.H_tot[0].real / 1e3:13.1f}"
            f" | {peaks(frfs.H_tot, frfs.freqs, 3):22s} | {rows[0]:5.1f}, {rows[-1]:5.1f} | {peak:.0f}",
            flush=True,
        )


def first_peak(values: np.ndarray, freqs: np.ndarray) -> float:
    """The first local maximum of ``|values|`` above 10 Hz (Hz), refined by a parabola through its three samples."""
    magnitude = np.abs(values)
    local = (magnitude[1:-1] > magnitude[:-2]) & (magnitude[1:-1] > magnitude[2:]) & (freqs[1:-1] > 10.0)
    i = int(np.nonzero(local)[0][0]) + 1
    below, at, above = magnitude[i - 1 : i + 2]
    return float(freqs[i] + 0.5 * (freqs[1] - freqs[0]) * (below - above) / (below - 2 * at + above))


def mesh_convergence(loaded_name: str, meshes: list[tuple[float, int, int]]) -> None:
    """The loaded tire on the flat road at its file's load on each mesh (footprint arc m, crown and sidewall
    elements), through the interface: K_v, the footprint, the first peak of H_tot (f1), times."""
    base = tire_model(loaded_name)
    print("  arc mm | crown | sidewall | DOF   | load s | FRFs s | deflection mm | K_v N/mm | footprint mm    | f1 Hz")
    for arc, crown, sidewall in meshes:
        model = base.replace(
            **{
                "solid_mesh.footprint_arc": arc,
                "solid_mesh.crown_elements": crown,
                "solid_mesh.sidewall_elements": sidewall,
            }
        )
        case = model.case()
        t0 = time.perf_counter()
        fp = model.load(case)
        t1 = time.perf_counter()
        frfs = model.fixed_hub_frfs(case)
        t2 = time.perf_counter()
        print(
            f"  {arc * 1e3:6.0f} | {crown:5d} | {sidewall:8d} | {model.equivalent_dof():5d} | {t1 - t0:6.0f} | {t2 - t1:6.0f}"
            f" | {fp.deflection * 1e3:13.2f} | {fp.vertical_stiffness / 1e3:8.1f} | {fp.footprint_length * 1e3:5.1f} x "
            f"{fp.footprint_width * 1e3:5.1f} | {first_peak(frfs.H_tot, frfs.freqs):5.1f}",
            flush=True,
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14_cross_section")
    parser.add_argument("--crown", type=int, default=4)
    parser.add_argument("--sidewall", type=int, default=2)
    parser.add_argument("--arcs", type=float, nargs="+", default=[0.02])
    parser.add_argument("--step", type=float, default=0.001)
    parser.add_argument("--no-nonlinear", dest="nonlinear", action="store_false")
    parser.add_argument("--no-dynamics", dest="dynamics", action="store_false")
    parser.add_argument("--modes", type=int, default=0, help="uniform arcs for the modes' comparison (0: none)")
    parser.add_argument("--drum", action="store_true", help="both tires on the drum through the interface")
    parser.add_argument("--loaded", default="165_65R14_loaded", help="the loaded FE tire file of --drum")
    parser.add_argument(
        "--convergence", action="store_true", help="the loaded tire file's mesh and two refinements, flat road"
    )
    parser.add_argument(
        "--file-modes", action="store_true", help="the inflated modes n = 0..6 on the loaded tire file's own mesh"
    )
    args = parser.parse_args()
    if args.drum:
        compare_on_drum(args.loaded)
        return
    if args.convergence:
        mesh_convergence(args.loaded, CONVERGENCE_MESHES)
        return
    if args.file_modes:
        loaded = tire_model(args.loaded).spec
        compare_modes(loaded.construction, stages.built_tire(loaded), f"the mesh of {args.loaded}")
        return
    # one contact column per tassello column: the coarse crown's tread nodes are ~15 mm apart
    section = {"mesh.crown_elements": args.crown, "mesh.sidewall_elements": args.sidewall}
    spec = ru.load_tire(args.tire).replace(**section, **{"tasselli.strips_per_column": 1})
    if args.modes:
        compare_modes(
            spec,
            statics.build_loaded_tire(spec, np.linspace(-np.pi, np.pi, args.modes + 1)),
            f"{args.modes} uniform arcs",
        )
    states = waveguide(spec, LOADS)
    for arc in args.arcs:
        t0 = time.perf_counter()
        tire = statics.build_loaded_tire(spec, graded_arcs(0.28, arc, 0.3, 0.06))
        t1 = time.perf_counter()
        inflated = statics.inflate(tire)
        t2 = time.perf_counter()
        compliance = linearised.contact_compliance(tire, inflated)
        t3 = time.perf_counter()
        rounded = linearised.round_linearisation(tire)
        round_compliance = linearised.contact_compliance(tire, rounded.state, tangent=rounded.tangent)
        print(
            f"solids, {arc * 1e3:.0f} mm arcs: {tire.n_dof} DOF; build {t1 - t0:.1f} s, inflation {t2 - t1:.1f} s, "
            f"compliance of {compliance.nodes.size} tread nodes {t3 - t2:.1f} s"
        )
        compare_linearised(round_compliance, compliance, states)
        if args.nonlinear:
            state = load_nonlinear(tire, inflated, compliance, spec.operating.vertical_load, args.step)
            if args.dynamics:
                compare_dynamics(spec, tire, state)


if __name__ == "__main__":
    main()
