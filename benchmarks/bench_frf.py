"""Benchmark of the FRF stage: direct viscoelastic sweep and modal local FRFs.

Run on demand (never as a timed test)::

    python benchmarks/bench_frf.py

Times, on the same loaded tire and frequencies, our direct sweep (one adjoint solve per
frequency in the mirror-symmetric subspace) side by side with the same adjoint solve on the
full system and with the textbook approach (full system, one forward solve per tassello), and
the modal reduction (build once, then evaluate the local FRFs).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import scipy.sparse.linalg as spla

import roadnoise_utils as ru
from roadnoise_utils.tire.ring.loaded import loaded_tire


def timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def forward_per_tassello(fet, static, freqs):
    """Reference: factorise the full D(omega), one forward solve per tassello."""
    lt = loaded_tire(fet, static)
    inputs = lt.road_input @ static.tasselli.membership().T  # (free DOF, tasselli)
    out = np.empty((static.tasselli.n, freqs.size), complex)
    for k, f in enumerate(freqs):
        w = 2 * np.pi * f
        lu = spla.splu(lt.dynamic_stiffness(w), permc_spec="NATURAL")
        u = lu.solve(fet.modulus_ratio("tread", w) * inputs)
        out[:, k] = -(lt.hub_row(w) @ u)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tire", default="165_65R14")
    parser.add_argument("--f-max", type=float, default=400.0)
    args = parser.parse_args()
    tire = ru.load_tire(args.tire)
    fet = ru.build_fet(tire)
    static = ru.solve_static(fet)
    freqs = np.arange(0.0, args.f_max + 0.5, 1.0)
    t_sym, visco = timed(lambda: ru.frf_visco(fet, static, freqs, progress=False))
    t_full, full = timed(lambda: ru.frf_visco(fet, static, freqs, progress=False, use_symmetry=False))
    few = freqs[:: max(1, freqs.size // 20)]
    t_fwd, fwd = timed(lambda: forward_per_tassello(fet, static, few))
    t_fwd_all = t_fwd * freqs.size / few.size
    t_build, reduced = timed(lambda: ru.modal_reduction(fet, static, visco=visco))
    t_eval, modal = timed(lambda: reduced.model.frf(freqs))
    idx = np.searchsorted(freqs, few)
    agree_full = np.max(np.abs(full.H - visco.H)) / np.max(np.abs(visco.H))
    agree_fwd = np.max(np.abs(fwd - visco.H[:, idx])) / np.max(np.abs(visco.H))
    print(f"tire {tire.name}, {fet.n_dof} DOF, {static.tasselli.n} tasselli, {freqs.size} frequencies")
    print("| FRFs of every tassello | time (s) | goal |")
    print("|---|---|---|")
    print(f"| direct, adjoint solve in the symmetric subspace (ours) | {t_sym:.2f} | < 10 |")
    print(f"| direct, adjoint solve on the full system | {t_full:.2f} | - |")
    print(
        f"| direct, full system, one forward solve per tassello (extrapolated from {few.size} freqs) "
        f"| {t_fwd_all:.1f} | - |"
    )
    print(f"| modal reduction: identification, frozen modes, residual anchors (once) | {t_build:.2f} | - |")
    print(f"| modal local FRFs, all tasselli | {t_eval:.4f} | < 1 |")
    print(
        f"(agreement with ours: full adjoint {agree_full:.1e}, forward per tassello {agree_fwd:.1e}; "
        f"modal model: {modal.method})"
    )


if __name__ == "__main__":
    main()
