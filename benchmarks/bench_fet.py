"""Benchmark of the FET stage: assembly, static contact solve, first 60 loaded modes.

Run on demand (never as a timed test)::

    python benchmarks/bench_fet.py

Prints a Markdown table (best of ``--repeat`` runs, wall time) for the README. Alongside our
condensed active-set solve it times the textbook alternative on the same model: an active set
that refactorises the full sparse system in every iteration.
"""

from __future__ import annotations

import argparse
import os
import platform
import time

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import roadnoise_utils as ru
from roadnoise_utils.tire.ring.mechanics import UZ


def best_of(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def full_active_set(fet, load: float) -> float:
    """Reference: frictionless active set, full sparse refactorisation per iteration (returns deflection)."""
    mesh = fet.mesh
    free = np.setdiff1d(np.arange(fet.n_dof), mesh.hub_dofs)
    k0 = fet.K(0.0, storage_only=True)[free][:, free].tocsc()
    tx, tz = mesh.tread_xz()
    gap0 = (tz - tz.min()).ravel()
    dofs = np.searchsorted(free, mesh.dof(*np.indices(tz.shape), UZ).ravel())
    kn = fet.tread_normal.ravel()
    active = gap0 <= load / 2e5
    for _ in range(100):
        k = (k0 + sp.csc_matrix((kn[active], (dofs[active], dofs[active])), shape=k0.shape)).tocsc()
        lu = spla.splu(k)
        rhs_unit = np.zeros(free.size)
        rhs_gap = np.zeros(free.size)
        rhs_unit[dofs[active]] = kn[active]
        rhs_gap[dofs[active]] = -kn[active] * gap0[active]
        u1, u0 = lu.solve(rhs_unit), lu.solve(rhs_gap)
        f1 = kn[active] * (1 - u1[dofs[active]])
        f0 = kn[active] * (-gap0[active] - u0[dofs[active]])
        delta = (load - f0.sum()) / f1.sum()
        uz = delta * u1[dofs] + u0[dofs]
        forces = np.where(active, kn * (delta - gap0 - uz), 0.0)
        gap = gap0 - delta + uz
        new = np.where(active, forces > 0, gap < 0)
        if np.array_equal(new, active):
            return delta
        active = new
    raise RuntimeError("no convergence")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    spec = ru.load_tire(args.tire)
    t_build, fet = best_of(lambda: ru.build_fet(spec), args.repeat)
    t_flat, flat = best_of(lambda: ru.solve_static(fet, road="flat"), args.repeat)
    t_drum, _ = best_of(lambda: ru.solve_static(fet, road="drum"), args.repeat)
    t_full, delta_full = best_of(lambda: full_active_set(fet, spec.operating.vertical_load), args.repeat)
    t_modes, modes = best_of(lambda: ru.loaded_modes(fet, flat, n_modes=60), args.repeat)
    assert abs(delta_full / flat.deflection - 1) < 1e-9, "reference and condensed active sets disagree"
    print(
        f"tire {spec.name}: {fet.n_dof} DOF; {platform.processor() or platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}"
    )
    print("| step | time (s) | goal |")
    print("|---|---|---|")
    print(f"| assembly (M, K parts) | {t_build:.3f} | < 2 |")
    print(f"| static solve, flat road (condensed active set) | {t_flat:.3f} | < 5 |")
    print(f"| static solve, drum | {t_drum:.3f} | < 5 |")
    print(f"| static solve, flat road, full refactorisation per iteration (reference) | {t_full:.3f} | - |")
    print(f"| first 60 loaded modes (shift-invert Lanczos) | {t_modes:.3f} | - |")
    print(
        f"(highest mode {modes.freqs[-1]:.0f} Hz; deflection agrees with the reference to "
        f"{abs(delta_full / flat.deflection - 1):.1e})"
    )


if __name__ == "__main__":
    main()
