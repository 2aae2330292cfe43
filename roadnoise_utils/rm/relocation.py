"""Pole relocation of many FRFs, each with its own poles, from one starting pole set (paper Eq. 1).

The per-tassello half of relaxed vector fitting (:mod:`.fitting` runs it from each start and keeps
each FRF's best): all rows relocated together, batched by their poles' structure (how many are
real), each row's error recorded after every relocation and its best poles kept.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .vf_kernels import confine, conjugate_closed, errors_for_poles, initial_poles, relocate, split_poles


@dataclass
class Relocations:
    """The relocations of every row from one starting pole set: each row's kept poles and errors."""

    start: str
    best_poles: np.ndarray
    best_iteration: np.ndarray
    errors: list[list[float]]
    used: np.ndarray

    def best_error(self, i: int) -> float:
        return min(self.errors[i])


def lowest_frequency(s: np.ndarray) -> float:
    """The band's lowest nonzero (scaled) frequency: where a log-spaced start begins."""
    positive = s.imag[s.imag > 0]
    return float(positive[0]) if positive.size else 0.0


def relocate_rows(s, frf, w, dc, n_poles, start, iterations, tolerance, proportional) -> Relocations:
    """Relaxed vector fitting of each row of ``frf`` (own poles per row) from the ``start`` poles, batched.

    Each relocation's poles are confined to what the band can support (:func:`.vf_kernels.confine`);
    after every relocation each row's residues are solved and its error recorded; each row keeps
    the poles of its smallest error (ties: the earlier iteration).
    """
    m = frf.shape[0]
    omega_low = lowest_frequency(s)
    poles = np.tile(confine(initial_poles(n_poles, start, omega_low), omega_low), (m, 1))
    real, upper = split_poles(poles[0])
    first = errors_for_poles(s, frf, w, np.tile(real, (m, 1)), np.tile(upper, (m, 1)), dc, proportional)
    run = Relocations(start, poles.copy(), np.zeros(m, int), [[e] for e in first], np.zeros(m, int))
    active = np.ones(m, bool)
    for it in range(1, iterations + 1):
        splits = [split_poles(p) for p in poles]
        structure = np.array([r.size for r, _ in splits])
        new = poles.copy()
        for n_r in np.unique(structure[active]):
            rows = np.nonzero(active & (structure == n_r))[0]
            real = np.array([splits[i][0] for i in rows]).reshape(rows.size, n_r)
            upper = np.array([splits[i][1] for i in rows]).reshape(rows.size, (n_poles - n_r) // 2)
            zeros = relocate(s, frf[rows], w[rows], real, upper, proportional)
            new[rows] = [conjugate_closed(confine(z, omega_low)) for z in zeros]
        record(s, frf, w, dc, new, np.nonzero(active)[0], it, run, proportional)
        moved = np.max(np.abs(np.sort_complex(new) - np.sort_complex(poles)), axis=1) / np.max(np.abs(poles), axis=1)
        poles = new
        run.used[active] = it
        active &= moved >= tolerance
        if not active.any():
            break
    return run


def record(s, frf, w, dc, new, rows, it, run: Relocations, proportional: bool) -> None:
    """Errors of the relocated poles ``new`` of ``rows`` (batched by pole structure); keep each row's best."""
    splits = {i: split_poles(new[i]) for i in rows}
    structure = np.array([splits[i][0].size for i in rows], int)
    for n_r in np.unique(structure):
        group = rows[structure == n_r]
        real = np.array([splits[i][0] for i in group]).reshape(group.size, n_r)
        upper = np.array([splits[i][1] for i in group]).reshape(group.size, (new.shape[1] - n_r) // 2)
        found = errors_for_poles(s, frf[group], w[group], real, upper, None if dc is None else dc[group], proportional)
        for i, e in zip(group, found):
            if e < min(run.errors[i]):
                run.best_poles[i], run.best_iteration[i] = new[i], it
            run.errors[i].append(float(e))
