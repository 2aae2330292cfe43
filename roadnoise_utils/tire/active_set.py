"""The primal active set of frictionless vertical contact with a rising rigid road, shared by both tire models.

The ring model (:mod:`roadnoise_utils.tire.ring.static`) condenses its stiffness onto the tread points and adds the tread
springs in series; the cross-section model (:mod:`roadnoise_utils.tire.cross_section.static`) gives the compliance of its
contact grid from the harmonic sum. Both then solve the same problem: contact forces
``lambda >= 0`` and the road's rise ``delta`` with

.. math:: C\\lambda - \\delta\\,\\mathbf 1 + g_0 = 0 \\text{ on the active set},\\qquad
          \\mathbf 1^T\\lambda = W,

the active set updated until no point in contact pulls and no point out of contact penetrates.
:func:`held_contact` solves the same contact with the rise held instead of the load (the cleat
passages), and :class:`StepContact` the contact of one time step of a dynamic passage on the step's
compliance, its factor kept from step to step.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla


def _active_solution(compliance, gap0, extra, active: np.ndarray, load: float) -> tuple[np.ndarray, float, float]:
    """Contact forces of the active set at ``load``, the rise delta and dF/d(delta)."""
    idx = np.nonzero(active)[0]
    c = compliance(idx)[idx]
    c = 0.5 * (c + c.T) + np.diag(extra[idx])
    factor = sla.cho_factor(c)
    a = sla.cho_solve(factor, np.ones(idx.size))
    b = sla.cho_solve(factor, -gap0[idx])
    delta = (load - b.sum()) / a.sum()
    return delta * a + b, delta, a.sum()


def active_set(
    compliance, gap0: np.ndarray, extra: np.ndarray, load: float, max_iterations: int = 200
) -> tuple[np.ndarray, float, float, int]:
    """Primal active-set solve of frictionless vertical contact with a rising rigid road.

    Parameters
    ----------
    compliance : callable
        ``compliance(columns)`` returns the columns of the vertical compliance of all candidate
        points (m/N), (n_candidates, len(columns)).
    gap0 : ndarray (n_candidates,)
        Height of each candidate above the road before loading (m).
    extra : ndarray (n_candidates,)
        Compliance in series at each point (m/N), e.g. a tread spring's ``1/k``; zeros for none.
    load : float
        Total vertical force (N).

    Returns
    -------
    forces, deflection, tangent stiffness dF/d(delta) with the contact set frozen, iterations.
    """
    if not (np.isfinite(load) and load > 0):
        raise ValueError(f"load = {load} N: valid range is (0, inf) N")
    # start from the geometric overlap at a quarter of a typical deflection: the belt moves
    # up bodily and the footprint is much shorter than the overlap at full deflection
    active = gap0 <= gap0.min() + 0.25 * load / 2.0e5
    for iteration in range(1, max_iterations + 1):
        lam_active, delta, k_tan = _active_solution(compliance, gap0, extra, active, load)
        forces = np.zeros(active.size)
        forces[active] = lam_active
        uz = compliance(np.nonzero(active)[0]) @ lam_active
        gap = gap0 - delta + uz  # point above road (m)
        new_active = np.where(active, forces > 0.0, gap < 0.0)
        if np.array_equal(new_active, active):
            return forces, delta, k_tan, iteration
        active = new_active
        if not active.any():
            raise RuntimeError("active set became empty; the contact problem is ill-posed")
    raise RuntimeError(f"contact active set did not converge in {max_iterations} iterations")


def held_contact(
    compliance, penetration: np.ndarray, active: np.ndarray, extra: np.ndarray, max_iterations: int = 100
) -> tuple[np.ndarray, np.ndarray, int]:
    r"""One-sided contact with the road held (the deflection given, not the load): the cleat passages.

    Forces ``lambda >= 0`` with :math:`(C + \mathrm{diag}(e))_{AA}\lambda_A = p_A` on the active
    set ``A``, ``p`` the penetration of the unloaded surface (m), until no point in contact pulls
    and none out of contact penetrates; ``compliance(columns)`` and ``extra`` as in
    :func:`active_set`, ``active`` the starting set. Returns the forces (N), the active set and
    the iterations.
    """
    for iteration in range(1, max_iterations + 1):
        idx = np.nonzero(active)[0]
        forces = np.zeros(active.size)
        remaining = penetration
        if idx.size:
            c = compliance(idx)
            block = c[idx] + np.diag(extra[idx])
            forces[idx] = sla.solve(0.5 * (block + block.T), penetration[idx], assume_a="pos")
            remaining = penetration - c @ forces[idx]
        new = np.where(active, forces > 0, remaining > 0)
        if np.array_equal(new, active):
            return forces, active, iteration
        active = new
    raise RuntimeError(f"quasi-static contact did not converge in {max_iterations} active-set iterations")


#: Points by which a step's active set may differ from the factored one before :class:`StepContact` refactors it.
MAX_BORDER = 48


class StepContact:
    """The one-sided contact of one time step on the step's compliance (``frozen``: the starting set held, bilateral).

    The Cholesky factor of a base set ``B`` is kept; an active set ``S`` that differs from it by a
    few points is solved through the bordered system with the added points ``A`` and the removed
    points ``R`` (their force held at zero by a multiplier that takes their equation's place):

    .. math:: \\begin{bmatrix} G_{BB} & U \\\\ U^T & D \\end{bmatrix}
              \\begin{bmatrix} f_B \\\\ w \\end{bmatrix} =
              \\begin{bmatrix} p_B \\\\ p_A, 0 \\end{bmatrix},\\qquad
              U = [G_{BA}\\;E_R],\\; D = \\mathrm{diag}(G_{AA}, 0),

    by its Schur complement on the border: a few triangular solves instead of a new factor.
    The base is refactored when the border exceeds :data:`MAX_BORDER` points.
    """

    def __init__(self, compliance: np.ndarray, active: np.ndarray, frozen: bool, max_iterations: int = 100):
        self.compliance, self.active, self.frozen = compliance, active.copy(), frozen
        self.max_iterations = max_iterations
        self._base = np.zeros(active.size, bool)
        self._cholesky = None

    def _rebase(self, active: np.ndarray) -> None:
        idx = np.nonzero(active)[0]
        self._cholesky = sla.cho_factor(self.compliance[np.ix_(idx, idx)], check_finite=False)
        self._base, self._base_idx = active.copy(), idx

    def _forces(self, active: np.ndarray, penetration: np.ndarray) -> np.ndarray:
        """Forces of the active set (zero elsewhere) for the penetrations ``penetration`` (m)."""
        added = np.nonzero(active & ~self._base)[0]
        removed = np.nonzero(self._base & ~active)[0]
        if self._cholesky is None or added.size + removed.size > MAX_BORDER:
            self._rebase(active)
            added, removed = added[:0], removed[:0]
        base = self._base_idx
        forces = np.zeros(active.size)
        if base.size == 0:
            if added.size:
                forces[added] = sla.solve(self.compliance[np.ix_(added, added)], penetration[added], assume_a="pos")
            return forces
        y = sla.cho_solve(self._cholesky, penetration[base], check_finite=False)
        if added.size + removed.size == 0:
            forces[base] = y
            return forces
        border = np.zeros((base.size, added.size + removed.size))
        border[:, : added.size] = self.compliance[np.ix_(base, added)]
        border[np.searchsorted(base, removed), added.size + np.arange(removed.size)] = 1.0
        x = sla.cho_solve(self._cholesky, border, check_finite=False)
        schur = -border.T @ x
        schur[: added.size, : added.size] += self.compliance[np.ix_(added, added)]
        rhs = np.concatenate([penetration[added], np.zeros(removed.size)]) - border.T @ y
        w = sla.solve(schur, rhs)
        forces[base] = y - x @ w
        forces[added] = w[: added.size]
        forces[removed] = 0.0  # held at zero by the border (round-off cleared)
        return forces

    def solve(self, penetration: np.ndarray) -> tuple[np.ndarray, int]:
        """Forces (N) for the penetrations of the predicted surface (m); updates :attr:`active`."""
        active = self.active
        for iteration in range(1, self.max_iterations + 1):
            forces = self._forces(active, penetration)
            if self.frozen:
                return forces, iteration
            remaining = penetration - self.compliance @ forces
            new = np.where(active, forces > 0, remaining > 0)
            if np.array_equal(new, active):
                self.active = active
                return forces, iteration
            active = new
        raise RuntimeError(f"dynamic contact did not converge in {self.max_iterations} active-set iterations")
