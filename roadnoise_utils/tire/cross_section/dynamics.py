"""Harmonic dynamics of the cross-section tire: Ritz-reduced receptances and the rim transfer.

For every harmonic ``n`` the receptance at the contact DOF,
:math:`F_n(\\omega) = E^T [K_n(\\omega) - \\omega^2 M_n]^{-1} E`, with the frequency-dependent
moduli of every compound (the paper's FETvisco), is evaluated in a Ritz basis of the harmonic:

* the static responses to unit loads at the contact DOF with the storage moduli at the band's
  two ends (0 Hz and ``f_max``): exact at 0 Hz, and close to the static shapes of the compound
  mixes in between (five compounds vary independently, so not exactly: ritz_error measures it);
* the undamped modes of the harmonic below ``cutoff`` (storage moduli at ``f_max / 2``); none
  above the harmonic whose first mode exceeds ``cutoff`` (quasi-static harmonics, whose
  inertia the static shapes still carry).

The basis is orthonormalised (pivoted QR) and the matrices of each compound, of the gas
pre-stress and of the mass are projected once (Galerkin), so a frequency costs a small dense
solve. (A static-correction form, quasi-static part plus a modal correction, was 10x less
accurate at 400 Hz: the truncated modes' inertia is missing from it.) :func:`ritz_error` compares the reduced receptance with
the direct sparse solve.

The rim: with ``theta`` from the bottom of the tire, a rigid vertical motion ``w`` of the rim is
the ``n = 1`` symmetric-set field ``a_r = -w, a_theta = w`` at the bead DOF, so only ``n = 1``
carries a vertical hub force (:func:`rim_vector`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla

from .operators import HarmonicOperators
from .waveguide import harmonic_weight


@dataclass(frozen=True, eq=False)
class Projected:
    """Matrices of one harmonic projected on a basis (weight ``w_n`` included)."""

    compounds: dict[str, np.ndarray]
    gas: np.ndarray
    mass: np.ndarray
    contact: np.ndarray  # (k, d): basis values at the contact DOF
    momentum: np.ndarray  # (k,): vertical momentum per unit coordinate (kg), zero unless n = 1
    wall: np.ndarray | None = None  # (k,): the cavity wall's load (section_cavity.wall_volume), if in the basis
    damping: np.ndarray | None = None  # (k, k): a viscous part (N s/m; the air's, stepped in time), if any

    @cached_property
    def _stacked(self) -> np.ndarray:
        """(gas, compounds..., mass) flattened, (2 + n_compounds, k * k): the terms of :meth:`dynamic_stiffness`."""
        k = self.gas.shape[0]
        return np.stack([self.gas, *self.compounds.values(), self.mass]).reshape(-1, k * k)

    def dynamic_stiffness(self, laws: dict, omegas: np.ndarray, inertia: bool = True) -> np.ndarray:
        """Projected :math:`K_n(\\omega) - \\omega^2 M_n`, (n_omega, k, k) complex."""
        omegas = np.asarray(omegas, float)
        factors = [np.ones(omegas.size)] + [laws[name].ratio(omegas) for name in self.compounds]
        factors.append(-(omegas**2) if inertia else np.zeros(omegas.size))
        k = self.gas.shape[0]
        weights = np.stack(factors, axis=1).astype(complex)  # real matrices: real and imaginary parts apart
        return (weights.real @ self._stacked + 1j * (weights.imag @ self._stacked)).reshape(omegas.size, k, k)

    def rotated(self, basis: np.ndarray) -> Projected:
        """The same matrices on the orthonormal coordinates ``basis`` (k, k_new) of this basis."""
        compounds = {name: basis.T @ m @ basis for name, m in self.compounds.items()}
        wall = None if self.wall is None else basis.T @ self.wall
        damping = None if self.damping is None else basis.T @ self.damping @ basis
        return Projected(compounds, basis.T @ self.gas @ basis, basis.T @ self.mass @ basis,
                         basis.T @ self.contact, basis.T @ self.momentum, wall, damping)  # fmt: skip


def parity_bases(mirror: np.ndarray) -> list[tuple[int, np.ndarray]]:
    """``(+1, W_s), (-1, W_a)``: orthonormal bases of the left-right symmetric and antisymmetric halves
    of a harmonic's Ritz coordinates, from its mirror there (:attr:`ReducedHarmonic.mirror`)."""
    sign, vectors = np.linalg.eigh(0.5 * (mirror + mirror.T))
    return [(parity, vectors[:, sign * parity > 0]) for parity in (1, -1)]


#: Largest departure from a mirror symmetry accepted in the reduced coordinates (relative).
MIRROR_TOLERANCE = 1e-9


@dataclass(frozen=True, eq=False)
class _Condensed:
    """One mirror-symmetry part of a harmonic, its basis rotated so that its first ``rank`` coordinates alone
    move the contact DOF: its matrices there and ``R`` (rank, d)."""

    projected: Projected
    r: np.ndarray

    def receptance(self, laws: dict, omegas: np.ndarray, inertia: bool, rows: np.ndarray | None = None) -> np.ndarray:
        """This part's share of :math:`F_n(\\omega)`, (n_omega, d, d): :math:`R^T S^{-1} R` (see :meth:`ReducedHarmonic.receptance`).

        With ``rows`` only those rows, (n_omega, rows, d): :math:`(S^{-1} R_{rows})^T R`, ``S``
        being symmetric (fewer right-hand sides and a smaller product).
        """
        stiffness = self.projected.dynamic_stiffness(laws, omegas, inertia)
        k, rank = stiffness.shape[1], self.r.shape[0]
        condensed = stiffness[:, :rank, :rank]
        if k > rank:
            inner = np.linalg.solve(stiffness[:, rank:, rank:], stiffness[:, rank:, :rank])
            condensed = condensed - np.matmul(stiffness[:, :rank, rank:], inner)
        loads = self.r if rows is None else self.r[:, rows]
        x = np.linalg.solve(condensed, np.broadcast_to(loads.astype(complex), (omegas.size,) + loads.shape))
        return np.matmul(np.swapaxes(x, 1, 2), self.r)


def _condense(projected: Projected, rotation: np.ndarray) -> _Condensed:
    """The part of ``projected`` on the orthonormal coordinates ``rotation`` (k, k_part), condensed on its contact rank."""
    contact = rotation.T @ projected.contact  # (k_part, d)
    q, r, pivots = sla.qr(contact, mode="full", pivoting=True)
    diag = np.abs(np.diag(r))
    rank = int(np.sum(diag > 1e-10 * diag[0])) if diag.size else 0
    r = r[:rank, np.argsort(pivots)]  # contact = q[:, :rank] r: the rest of q does not touch the contact DOF
    return _Condensed(projected.rotated(rotation @ q), r)


@dataclass(frozen=True, eq=False)
class ReducedHarmonic:
    """One harmonic projected on its Ritz basis (attachment shapes and modes, see the module notes).

    ``mirror`` is the tire's left-right mirror (y -> -y) in the basis coordinates (k, k), when
    the harmonic and its basis are symmetric (:func:`lateral_mirror`): the receptance then
    splits into its symmetric and antisymmetric parts.
    """

    n: int
    projected: Projected
    n_modes: int
    mirror: np.ndarray | None = None

    @cached_property
    def _condensed(self) -> list[_Condensed]:
        """The basis split by the mirror (or whole) and rotated for the condensation on the contact DOF."""
        k = self.projected.gas.shape[0]
        if self.mirror is None:
            return [_condense(self.projected, np.eye(k))]
        return [_condense(self.projected, basis) for _, basis in parity_bases(self.mirror)]

    def eigenvalues(self, laws: dict | None = None, omega: float = 0.0) -> np.ndarray:
        """Eigenvalues (rad^2/s^2, ascending) of the undamped pencil ``(K', M)`` in the basis: ``K'`` with each
        compound's storage modulus at ``omega`` (rad/s) under ``laws``, or its static modulus without ``laws``."""
        projected = self.projected
        scale = {name: 1.0 if laws is None else float(np.real(laws[name].ratio(omega))) for name in projected.compounds}
        if all(value == 1.0 for value in scale.values()):
            return self.static_eigenvalues
        stiffness = projected.gas + sum(scale[name] * m for name, m in projected.compounds.items())
        return sla.eigh(stiffness, projected.mass, eigvals_only=True)

    @cached_property
    def static_eigenvalues(self) -> np.ndarray:
        """:meth:`eigenvalues` with the static moduli (cached)."""
        projected = self.projected
        stiffness = projected.gas + sum(projected.compounds.values())
        return sla.eigh(stiffness, projected.mass, eigvals_only=True)

    @cached_property
    def compound_floors(self) -> dict[str, float]:
        """Each compound's lowest eigenvalue against the mass (rad^2/s^2 per unit modulus ratio), or 0 when its
        matrix is positive semi-definite: a compound that carries the pneumatic stiffness may be indefinite."""
        projected = self.projected
        return {
            name: min(0.0, float(sla.eigh(m, projected.mass, eigvals_only=True, subset_by_index=[0, 0])[0]))
            for name, m in projected.compounds.items()
        }

    def receptance(
        self, laws: dict, omegas: np.ndarray, inertia: bool = True, rows: np.ndarray | None = None
    ) -> np.ndarray:
        """:math:`F_n(\\omega)` at the contact DOF (m/N), (n_omega, d, d) complex; quasi-static without ``inertia``;
        with ``rows`` (indices of the contact DOF) only those rows, (n_omega, rows, d).

        On a basis rotated so that only its first coordinates move the contact DOF (``C = Q [R; 0]``,
        a QR of the contact values), :math:`F = R^T S^{-1} R` with
        :math:`S = D_{11} - D_{12} D_{22}^{-1} D_{21}` the dynamic stiffness condensed on them: a
        third of the work of solving the whole basis for the ``d`` contact loads. A symmetric
        harmonic does it on its symmetric and antisymmetric halves apart (the dynamic stiffness
        has no coupling between them), a quarter of the work again.
        """
        omegas = np.asarray(omegas, float)
        return sum(part.receptance(laws, omegas, inertia, rows) for part in self._condensed)

    def wall_response(self, laws: dict, omegas: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The response to the cavity wall's load ``g`` (reduced with its static shapes, :func:`reduce_harmonic`
        with ``wall``): the contact DOF's displacement (n_omega, d) and :math:`g^T D_n^{-1} g` (n_omega,)."""
        if self.projected.wall is None:
            raise ValueError(
                f"harmonic {self.n} was reduced without the cavity wall's load (reduce_harmonic(wall=...))"
            )
        omegas = np.asarray(omegas, float)
        contact, volume = 0.0, 0.0
        for part in self._condensed:
            p = part.projected
            z = np.linalg.solve(
                p.dynamic_stiffness(laws, omegas),
                np.broadcast_to(p.wall.astype(complex)[:, None], (omegas.size, p.wall.size, 1)),
            )
            z = z[..., 0]
            contact = contact + z @ p.contact
            volume = volume + z @ p.wall
        return contact, volume


def lateral_mirror(ops: HarmonicOperators) -> tuple[np.ndarray, np.ndarray] | None:
    """The left-right mirror (y -> -y) of the cross-section as a signed permutation of the DOF, or None.

    ``(target, sign)``: the mirror of a field ``u`` is ``v[target] = sign * u`` (``u_r, u_theta``
    kept, ``u_y`` reversed). ``None`` when a node has no mirror image (an asymmetric section).
    The operators' symmetry is checked per harmonic (:func:`reduce_harmonic`).
    """
    r, y = ops.mesh.r, ops.mesh.y
    scale = max(float(np.abs(r).max()), float(np.abs(y).max()), 1e-12)
    key = {(round(a / scale, 9), round(b / scale, 9)): i for i, (a, b) in enumerate(zip(r, y))}
    image = np.array([key.get((round(a / scale, 9), round(-b / scale, 9)), -1) for a, b in zip(r, y)])
    if np.any(image < 0):
        return None
    target = (3 * image[:, None] + np.arange(3)).ravel()
    return target, np.tile([1.0, 1.0, -1.0], r.size)


def _mirror_in_basis(
    projected: Projected, basis: np.ndarray, free: np.ndarray, mirror, n_dof: int
) -> np.ndarray | None:
    """The mirror in the basis coordinates, or None when the basis or the harmonic is not symmetric."""
    target, sign = mirror
    full = np.zeros((n_dof, basis.shape[1]))
    full[free] = basis
    mirrored = np.empty_like(full)
    mirrored[target] = sign[:, None] * full
    reduced = basis.T @ mirrored[free]
    # the basis spans a symmetric space (an orthogonal involution) and every operator commutes with it
    if np.abs(reduced @ reduced - np.eye(reduced.shape[0])).max() > MIRROR_TOLERANCE:
        return None
    for matrix in [projected.gas, projected.mass, *projected.compounds.values()]:
        scale = np.abs(matrix).max()
        if scale and np.abs(reduced @ matrix - matrix @ reduced).max() > MIRROR_TOLERANCE * scale:
            return None
    return reduced


def _free_positions(ops: HarmonicOperators, dofs: np.ndarray) -> np.ndarray:
    free = ops.free
    position = np.searchsorted(free, dofs)
    if np.any(position >= free.size) or not np.array_equal(free[position], dofs):
        raise ValueError("contact DOF must not be clamped")
    return position


def _project(
    ops: HarmonicOperators, n: int, basis: np.ndarray, position: np.ndarray, wall: np.ndarray | None = None
) -> Projected:
    free = ops.free
    w = harmonic_weight(n)
    compounds = {name: basis.T @ ((w * ops.free_compound(name, n)) @ basis) for name in ops.scaled}
    gas = basis.T @ ((w * ops.free_gas(n)) @ basis)
    mass_ff = ops.free_mass(n)
    mass = basis.T @ (mass_ff @ basis)
    momentum = basis.T @ (mass_ff @ rigid_vertical(ops)[free]) if n == 1 else np.zeros(basis.shape[1])
    wall = None if wall is None else basis.T @ wall[free]
    return Projected(compounds=compounds, gas=gas, mass=mass, contact=basis[position].T, momentum=momentum, wall=wall)


def harmonic_modes(ops: HarmonicOperators, n: int, omega: float, cutoff: float, max_modes: int = 40) -> np.ndarray:
    """Undamped modes of harmonic ``n`` below ``cutoff`` (Hz), storage moduli at ``omega``, (free, m)."""
    free = ops.free
    k = ops.free_stiffness(n, omega, storage_only=True)
    mass = ops.free_mass(n)
    lam_cut = (2 * np.pi * cutoff) ** 2
    # ARPACK's starting vector, fixed: its default is random, which made the modes, the reduced
    # harmonics and every FRF of this tire differ in their last bits from one run to the next
    start = np.random.default_rng(0).standard_normal(k.shape[0])
    count = 8
    while True:
        count = min(count, max_modes, free.size - 2)
        lam, phi = spla.eigsh(k, count, mass, sigma=0.0, v0=start)
        if lam.max() >= lam_cut or count >= max_modes:
            return phi[:, lam < lam_cut]
        count *= 2


def reduce_harmonic(
    ops: HarmonicOperators,
    dofs: np.ndarray,
    n: int,
    f_max: float,
    cutoff: float | None,
    both_ends: bool = True,
    mirror: tuple[np.ndarray, np.ndarray] | None = None,
    wall: np.ndarray | None = None,
) -> ReducedHarmonic:
    """Reduce harmonic ``n`` for the contact DOF ``dofs`` (see the module notes).

    ``cutoff`` (Hz) bounds the modes added to the basis; ``None`` for a quasi-static harmonic.
    ``both_ends=False`` keeps only the static shapes at 0 Hz (half the basis of a quasi-static harmonic).
    ``mirror`` (:func:`lateral_mirror`) records the left-right symmetry when the basis has it.
    ``wall`` (n_dof,): a load whose static shapes join the basis and whose projection is kept (the air
    cavity's, :func:`roadnoise_utils.tire.cross_section.cavity.wall_volume`; :meth:`ReducedHarmonic.wall_response`).
    """
    free = ops.free
    position = _free_positions(ops, dofs)
    rhs = np.zeros((free.size, dofs.size + (wall is not None)))
    rhs[position, np.arange(dofs.size)] = 1.0
    if wall is not None:
        rhs[:, -1] = wall[free] / np.abs(wall[free]).max()
    w_max = 2 * np.pi * f_max
    vectors = [
        spla.splu(ops.free_stiffness(n, w, storage_only=True)).solve(rhs)
        for w in ((0.0, w_max) if both_ends else (0.0,))
    ]
    n_modes = 0
    if cutoff is not None:
        phi = harmonic_modes(ops, n, 0.5 * w_max, cutoff)
        n_modes = phi.shape[1]
        vectors.append(phi)
    basis = _orthonormal(np.concatenate(vectors, axis=1))
    projected = _project(ops, n, basis, position, wall)
    in_basis = None if mirror is None else _mirror_in_basis(projected, basis, free, mirror, ops.n_dof)
    return ReducedHarmonic(n=n, projected=projected, n_modes=n_modes, mirror=in_basis)


def _orthonormal(vectors: np.ndarray, tol: float = 1e-10) -> np.ndarray:
    """Orthonormal basis of the columns (Euclidean), dependent directions dropped (pivoted QR)."""
    q, r, _ = sla.qr(vectors / np.linalg.norm(vectors, axis=0), mode="economic", pivoting=True)
    diag = np.abs(np.diag(r))
    return q[:, diag > tol * diag[0]]


def direct_receptance(ops: HarmonicOperators, dofs: np.ndarray, n: int, omega: float) -> np.ndarray:
    """:math:`F_n(\\omega)` by a sparse solve of the full harmonic (m/N), (d, d) complex: the reference."""
    free = ops.free
    position = _free_positions(ops, dofs)
    k = ops.free_stiffness(n, omega) - omega**2 * ops.free_mass(n)
    rhs = np.zeros((free.size, dofs.size), complex)
    rhs[position, np.arange(dofs.size)] = 1.0
    return spla.splu(k.tocsc()).solve(rhs)[position]


def ritz_error(ops: HarmonicOperators, reduced: ReducedHarmonic, dofs: np.ndarray, omega: float) -> float:
    """Largest entry error of the reduced receptance relative to the largest direct entry (-)."""
    ref = direct_receptance(ops, dofs, reduced.n, omega)
    red = reduced.receptance(ops.laws, np.array([omega]))[0]
    return float(np.abs(red - ref).max() / np.abs(ref).max())


def rigid_vertical(ops: HarmonicOperators) -> np.ndarray:
    """Field of a unit upward rigid translation of the whole tire in harmonic ``n = 1`` (all DOF).

    With ``theta`` from the bottom, ``u_r = -cos(theta)`` and ``u_theta = sin(theta)``: ``a_r = -1``,
    ``a_theta = 1`` at every node. ``t^T M_1 t`` is the tire's mass; ``t^T M_1 phi`` a mode's
    vertical momentum (participation).
    """
    t = np.zeros(ops.n_dof)
    t[0::3] = -1.0
    t[1::3] = 1.0
    return t


def tire_mass(ops: HarmonicOperators) -> float:
    """Mass of the whole tire (kg), from the ``n = 1`` mass matrix and a rigid vertical translation."""
    t = rigid_vertical(ops)
    return float(t @ (ops.mass_matrix(1) @ t))


@dataclass(frozen=True)
class FrozenLaw:
    """A compound law frozen at one frequency: the same complex modulus ratio at every frequency."""

    value: complex

    def ratio(self, omega) -> np.ndarray:
        """The frozen ratio, shaped like ``omega``."""
        return np.full(np.shape(omega), self.value, dtype=complex)


def frozen_laws(laws: dict, omega: float, storage_only: bool = False) -> dict[str, FrozenLaw]:
    """Every law frozen at ``omega`` (rad/s): the complex ratio, or only its real (storage) part."""
    out = {}
    for name, law in laws.items():
        g = complex(law.ratio(omega))
        out[name] = FrozenLaw(complex(g.real) if storage_only else g)
    return out


def rim_vector(ops: HarmonicOperators) -> np.ndarray:
    """Bead-DOF field of a unit upward rim motion in harmonic ``n = 1`` (full DOF vector)."""
    t = np.zeros(ops.n_dof)
    fixed = ops.fixed
    t[fixed[fixed % 3 == 0]] = -1.0  # a_r
    t[fixed[fixed % 3 == 1]] = 1.0  # a_theta
    return t


@dataclass(frozen=True, eq=False)
class RimTransfer:
    """Hub-force transfer of harmonic ``n = 1`` at a set of frequencies.

    Attributes
    ----------
    omegas : ndarray (n_f,)
    contact : ndarray (n_f, d) complex
        Vertical force on the fixed rim per unit generalised ``n = 1`` load at each contact
        DOF (-), upward positive: the hub-force transfer of a contact load.
    free_rim : ndarray (n_f,) complex
        Dynamic stiffness of the rim's vertical motion with the tread free (N/m).
    """

    omegas: np.ndarray
    contact: np.ndarray
    free_rim: np.ndarray


def rim_transfer(
    ops: HarmonicOperators, dofs: np.ndarray, omegas: np.ndarray, inertia: bool = True, laws: dict | None = None
) -> RimTransfer:
    """Exact ``n = 1`` rim transfer by sparse solves, one per frequency.

    Quasi-static without ``inertia``; ``laws`` replace the tire's compound laws (e.g. frozen ones).

    The hub force of a load ``Q`` (generalised ``n = 1`` forces) is the rim's reaction: with the
    rim fixed, ``u_f = D_ff^{-1} Q`` and the force on the rim is ``-t^T D_bf u_f`` where ``t`` is
    :func:`rim_vector` (its reaction is ``D_bf u_f``).
    """
    free, fixed = ops.free, ops.fixed
    position = _free_positions(ops, dofs)
    if laws is not None:
        ops = replace(ops, laws=laws)
    t = rim_vector(ops)
    t_b = t[fixed]
    out = np.empty((len(omegas), dofs.size), complex)
    free_rim = np.empty(len(omegas), complex)
    for i, omega in enumerate(omegas):
        d = ops.stiffness(1, omega)
        if inertia:
            d = d - omega**2 * ops.mass_matrix(1)
        d = d.tocsr()
        d_ff = d[free][:, free].tocsc()
        d_fb = d[free][:, fixed]
        z = spla.splu(d_ff).solve(np.asarray(d_fb @ t_b, complex).ravel())  # D_ff^{-1} D_fb t (D symmetric)
        out[i] = -z[position]
        free_rim[i] = t_b @ (d[fixed][:, fixed] @ t_b) - (d_fb @ t_b) @ z
    return RimTransfer(omegas=np.asarray(omegas, float), contact=out, free_rim=free_rim)
