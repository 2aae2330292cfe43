"""Time stepping of the cross-section tire at its contact grid: every harmonic, Newmark with Prony moduli.

The tire is axisymmetric, so its harmonics are independent until the contact couples them. Each
harmonic ``n = 0..N`` has two sets of the same matrices (the symmetric set, ``u_r, u_y`` as
``cos n theta`` and ``u_theta`` as ``sin n theta``, and the antisymmetric set, ``sin`` and
``-cos``): a road passing under the tire excites both. Every harmonic is reduced to its Ritz
basis as in the frequency domain (:func:`roadnoise_utils.tire.cross_section.dynamics.reduce_harmonic`: the static shapes
of the contact DOF at the band's two ends, plus the modes below the cutoff for the harmonics
that have one), so a harmonic's state is ~120 numbers instead of ~1000.

* **Viscoelasticity.** Each compound's stiffness carries its Prony series
  (:func:`.rubber.prony_series`, < 0.2 % from its fractional law over 0.1-2000 Hz): the same
  model as the frequency-domain FETvisco, one auxiliary state per Maxwell branch, updated
  exactly for a displacement linear over the step (as the ring model's
  :mod:`roadnoise_utils.tire.contact`). The compounds' series share one grid of relaxation
  times, and so their states (:class:`.rubber.SharedPronyStates`: 12 state vectors, not 47).
* **Newmark.** Average acceleration (unconditionally stable, no numerical damping): per step
  and harmonic :math:`A q_{k+1} = M(\\tfrac4{dt^2} q + \\tfrac4{dt}\\dot q + \\ddot q) +
  \\sum_c K_c h_c + C^T g` with :math:`A = \\tfrac4{dt^2}M + K_{gas} + \\sum_c \\phi_c K_c`,
  ``h_c`` the compound's history and ``g`` the contact loads; :math:`A^{-1}M` and
  :math:`A^{-1}K_c` are formed once, so a step is one batched product per harmonic group.
* **Contact grid.** A vertical force ``F`` at point ``(j, a)`` loads harmonic ``n`` with
  :math:`g = \\mathrm{sinc}(n\\Delta\\theta/2)\\,(-\\cos\\theta_a F\\cos n\\theta_a,
  \\sin\\theta_a F \\sin n\\theta_a)` (symmetric set; antisymmetric: ``sin`` and ``-cos``), the
  arc-spread load of :mod:`roadnoise_utils.tire.cross_section.contact`; the displacement at a point is the same sum
  back. So :meth:`HarmonicStepper.effective_compliance` (the step's compliance of the grid)
  is :func:`roadnoise_utils.tire.cross_section.contact.vertical_compliance` of :math:`C A^{-1} C^T`.
* **Hub force.** From the tire's vertical momentum balance (only ``n = 1`` moves the centre of
  mass): :math:`F_H = \\mathrm{sinc}(\\Delta\\theta/2) \\sum F - p^T \\ddot q_1`, ``p`` the
  vertical momentum per coordinate (the same balance as :mod:`roadnoise_utils.tire.cross_section.modal`),
  with :math:`\\ddot q_1` the force unbalance at the step's end (the coordinates are
  mass-orthonormal): the generalised-alpha acceleration itself approximates the acceleration
  :math:`(\\alpha_f - \\alpha_m)\\,dt` earlier, which doubled the frozen check's RMS error at
  ``rho = 0.5``.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from ... import guards
from ..rubber import PronyBranches, SharedPronyStates, prony_series
from .contact import ContactGrid, patch_factor, vertical_compliance
from .dynamics import Projected, ReducedHarmonic, lateral_mirror, parity_bases, reduce_harmonic
from .static import SectionStaticState, SectionTire

#: Spectral radius of the generalised-alpha scheme at infinite frequency (1: the trapezoidal rule):
#: at 0.5 an oscillation at 250 Hz loses 0.2 % of its amplitude per period at the cleat runs' step
#: (1/6000 s; 0.03 % at 1/12000 s, 0.007 % at 80 Hz), and the footprint settles back to its static
#: contact after the cleat.
SPECTRAL_RADIUS = 0.5
#: Harmonics with a mode below ``CUTOFF_FACTOR * f_max`` keep their modes (as the frequency domain).
CUTOFF_FACTOR = 2.5


@dataclass(frozen=True, eq=False)
class SteppedHarmonic:
    """One harmonic ready for time stepping: its passive part (:func:`passive_part`), mass-orthonormal.

    Attributes
    ----------
    n : int
    projected : Projected
        Matrices on the kept basis (``mass`` the identity).
    n_modes : int
        Modes in the Ritz basis (0: a quasi-static harmonic).
    dropped : int
        Directions of negative static stiffness left out.
    parity : int
        +1 / -1: the left-right symmetric / antisymmetric half of the harmonic's basis (a
        symmetric tire's halves are stepped apart); 0: the whole basis.
    """

    n: int
    projected: Projected
    n_modes: int
    dropped: int
    parity: int = 0


def reduce_all(
    tire: SectionTire, f_max: float, cutoff_factor: float = CUTOFF_FACTOR, dynamic: list | None = None
) -> list[SteppedHarmonic]:
    """Every harmonic ``0..N`` reduced for ``0..f_max`` Hz and made passive (:func:`passive_part`).

    With its modes up to the first ``n >= 2`` without one below ``cutoff_factor * f_max``; the
    rest on their static shapes at 0 Hz only (as accurate in the cleat runs as both ends, at a
    third of the cost: the frozen check is unchanged to 1e-4). A left-right symmetric harmonic
    (:func:`roadnoise_utils.tire.cross_section.dynamics.lateral_mirror`) gives its symmetric and antisymmetric halves,
    which its matrices do not couple: stepping them apart reads half the operators' entries.

    ``dynamic``: the harmonics with their modes, reduced before for this band and cutoff
    (:attr:`roadnoise_utils.tire.cross_section.reductions.FootprintReductions.dynamic`: the same reductions).
    """
    out, modal, mirror = [], True, lateral_mirror(tire.ops)
    given = {} if dynamic is None else {red.n: red for red in dynamic}
    for n in range(tire.harmonics + 1):
        cutoff = cutoff_factor * f_max if modal else None
        if modal and n in given:
            red = given[n]
        else:
            red = reduce_harmonic(tire.ops, tire.grid.dofs, n, f_max, cutoff, both_ends=modal, mirror=mirror)
        modal = modal and not (n >= 2 and red.n_modes == 0)
        for parity, half in parity_halves(red):
            projected, dropped = passive_part(half, list(tire.ops.scaled))
            out.append(SteppedHarmonic(n, projected, red.n_modes, dropped, parity))
    return out


def parity_halves(red: ReducedHarmonic) -> list[tuple[int, Projected]]:
    """``(parity, matrices)`` of a harmonic's left-right symmetric (+1) and antisymmetric (-1) halves, or ``(0, whole)``."""
    if red.mirror is None:
        return [(0, red.projected)]
    return [(parity, red.projected.rotated(basis)) for parity, basis in parity_bases(red.mirror)]


def passive_part(projected: Projected, names: list[str]) -> tuple[Projected, int]:
    """The projected harmonic made passive for time stepping, and the directions dropped.

    Two parts of the cross-section model are not passive, and a time-stepped model shows it:

    * the linear inflation leaves the belt plies' edges in hoop compression (down to -69 MPa on
      the 165/65 R14); its geometric stiffness makes harmonics above ~190 (wavelengths < 9 mm)
      statically unstable in a shoulder-local wrinkle of the smeared ply. The frequency domain
      sees a negative compliance term; in time it is a real pole (e-folding in ~60 us). Kept:
      the mass-orthogonal complement of the directions of negative static stiffness.
    * the pneumatic stiffness (pre-stress and pressure load) is indefinite, and the tire file
      gives it the carcass law: its negative part then stiffens negatively with frequency and
      its Maxwell branches feed energy in. Kept: the law on each compound's positive part,
      its negative part lossless at its static value.
    """
    stiffness = projected.gas + sum(projected.compounds[c] for c in names)
    lam, vectors = sla.eigh(0.5 * (stiffness + stiffness.T), 0.5 * (projected.mass + projected.mass.T))
    t = vectors[:, lam > 0]
    gas = t.T @ projected.gas @ t
    compounds = {}
    for c in names:
        part = t.T @ projected.compounds[c] @ t
        mu, phi = np.linalg.eigh(0.5 * (part + part.T))
        negative = (phi[:, mu < 0] * mu[mu < 0]) @ phi[:, mu < 0].T
        compounds[c] = part - negative
        gas = gas + negative
    reduced = Projected(
        compounds=compounds,
        gas=gas,
        mass=t.T @ projected.mass @ t,
        contact=t.T @ projected.contact,
        momentum=t.T @ projected.momentum,
        damping=None if projected.damping is None else t.T @ projected.damping @ t,
    )
    return reduced, int((lam <= 0).sum())


@dataclass(frozen=True)
class GeneralizedAlpha:
    """Generalised-alpha constants (Chung & Hulbert 1993) for a spectral radius ``rho`` at infinite frequency.

    ``rho = 1`` is the trapezoidal rule (average acceleration). Contact held directly on the
    tread's nodes makes the stepped system a constrained one: the trapezoidal rule then leaves
    a non-decaying oscillation at the Nyquist frequency in the accelerations and contact
    forces, and with one-sided contact a chatter that pumps energy in (at ``rho = 0.8`` the
    footprint still shrank from 650 to 330 points in the 50 ms after the cleat); ``rho < 1``
    damps it, second-order accurate, with little damping in the band (see :data:`SPECTRAL_RADIUS`).
    """

    rho: float

    @property
    def alpha_m(self) -> float:
        return (2.0 * self.rho - 1.0) / (self.rho + 1.0)

    @property
    def alpha_f(self) -> float:
        return self.rho / (self.rho + 1.0)

    @property
    def gamma(self) -> float:
        return 0.5 - self.alpha_m + self.alpha_f

    @property
    def beta(self) -> float:
        return 0.25 * (1.0 - self.alpha_m + self.alpha_f) ** 2


def size_groups(entries: list[SteppedHarmonic]) -> list[list[SteppedHarmonic]]:
    """``entries`` (whole harmonics, in order) grouped by the size of each harmonic's largest basis, smallest first.

    A group pads every basis to its largest, and the step reads every padded entry: on the
    165/65 R14 one quasi-static harmonic of 60 coordinates among 349 of 28-30 doubled the
    quasi-static harmonics' operators and Maxwell states.
    """
    by_size: dict[int, list[SteppedHarmonic]] = {}
    for _, members in itertools.groupby(entries, key=lambda h: h.n):
        members = list(members)
        by_size.setdefault(max(h.projected.gas.shape[0] for h in members), []).extend(members)
    return [by_size[size] for size in sorted(by_size)]


class StepGroup:
    """Reduced models of one basis size, padded to it, mass-orthonormal: their generalised-alpha operators and
    states, with ``columns`` independent load cases along the last axis of every state.

    Each entry is a :class:`SteppedHarmonic` (a harmonic of the cross-section tire, or a whole
    reduced model stepped as one entry); the entries of harmonic ``n = 1`` are the ones whose
    motion moves the centre of mass (:attr:`moving`). An entry's viscous part (``damping``, the
    air cavity's in the loaded tire) enters the generalised-alpha balance at the same weighted
    instant as the stiffness, :math:`C[(1-\alpha_f)v_{n+1} + \alpha_f v_n]` (Chung & Hulbert
    1993), its share at the step's start inside the force unbalance.
    """

    def __init__(
        self, harmonics: list[SteppedHarmonic], dt: float, branches: dict[str, PronyBranches], scheme, columns: int = 2
    ):
        self.n = np.array([h.n for h in harmonics])
        size = max(h.projected.gas.shape[0] for h in harmonics)
        d = harmonics[0].projected.contact.shape[1]
        names = list(branches)
        h_count = len(harmonics)
        inertia = (1.0 - scheme.alpha_m) / (scheme.beta * dt**2)
        weight = 1.0 - scheme.alpha_f
        self.operator = np.zeros((h_count, size, size * (1 + len(names))))  # [A^-1, (1 - af) A^-1 K_c ...]
        self.load = np.zeros((h_count, size, d))  # (1 - af) A^-1 C^T
        self.contact = np.zeros((h_count, d, size))  # C
        self.static = np.zeros((h_count, size, size))  # inverse static stiffness
        self.momentum = np.zeros((h_count, size))  # vertical momentum per coordinate: n = 1 only
        viscous = any(h.projected.damping is not None for h in harmonics)
        self.damping = np.zeros((h_count, size, size)) if viscous else None  # C: the viscous parts, if any
        velocity_weight = weight * scheme.gamma / (scheme.beta * dt)
        self.dropped: dict[int, int] = {}  # harmonic: directions of negative static stiffness left out
        for i, h in enumerate(harmonics):
            p, k = h.projected, h.projected.gas.shape[0]  # mass-orthonormal: M = I
            if h.dropped:
                self.dropped[h.n] = self.dropped.get(h.n, 0) + h.dropped
            a = inertia * np.eye(k) + weight * (p.gas + sum(branches[c].factor * p.compounds[c] for c in names))
            if p.damping is not None:
                a = a + velocity_weight * p.damping
                self.damping[i, :k, :k] = p.damping
            a_inv = np.linalg.inv(0.5 * (a + a.T))
            blocks = [a_inv] + [weight * (a_inv @ p.compounds[c]) for c in names]
            for b, block in enumerate(blocks):
                self.operator[i, :k, b * size : b * size + k] = block
            self.load[i, :k] = weight * (a_inv @ p.contact)  # contact: (k, d), the basis at the contact DOF
            self.contact[i, :, :k] = p.contact.T
            stiff = p.gas + sum(p.compounds[c] for c in names)
            self.static[i, :k, :k] = np.linalg.inv(0.5 * (stiff + stiff.T))
            if h.n == 1:
                self.momentum[i, :k] = p.momentum
        self.moving = np.nonzero(self.n == 1)[0]  # the entries whose motion moves the centre of mass
        self.harmonics = np.unique(self.n)  # a harmonic's entries (its whole basis or its halves) are adjacent
        self.firsts = np.searchsorted(self.n, self.harmonics)
        self.size, self.names = size, names
        self.q = np.zeros((h_count, size, columns))
        self.velocity = np.zeros_like(self.q)
        self.acceleration = np.zeros_like(self.q)
        self.unbalance = np.zeros_like(self.q)  # external minus internal force (M = I: the inertia force)
        self.prony = SharedPronyStates({c: branches[c] for c in names}, self.q.size)  # one state per relaxation time
        self.history = {c: np.zeros(self.q.size) for c in names}  # the next step's, kept by each update
        self.stacked = np.zeros((h_count, self.operator.shape[2], columns))  # the products' right-hand side

    def flexibility(self) -> np.ndarray:
        """:math:`(1 - \\alpha_f) C A^{-1} C^T` per harmonic (h, d, d): the step's compliance at the contact DOF."""
        return np.matmul(self.contact, self.load)

    def start(self, loads: np.ndarray) -> None:
        """At rest under the static contact ``loads`` (h, d, columns), every Maxwell branch relaxed."""
        self.q = np.matmul(self.static, np.matmul(np.transpose(self.contact, (0, 2, 1)), loads))
        for array in (self.velocity, self.acceleration, self.unbalance):
            array[:] = 0.0
        self.history = self.prony.start(self.q.ravel())

    def predict(self, dt: float, scheme: GeneralizedAlpha) -> np.ndarray:
        """The coordinates at the step's end with no new contact load (h, size, columns)."""
        inertia = (1.0 - scheme.alpha_m) / (scheme.beta * dt**2)
        ahead = self.q + dt * self.velocity + (0.5 - scheme.beta) * dt**2 * self.acceleration
        size = self.size
        self.stacked[:, :size] = inertia * ahead - scheme.alpha_m * self.acceleration + scheme.alpha_f * self.unbalance
        if self.damping is not None:  # (1 - af) C v_{n+1}: its part known before the step
            known = (
                scheme.gamma / (scheme.beta * dt) * ahead
                - self.velocity
                - (1.0 - scheme.gamma) * dt * self.acceleration
            )
            self.stacked[:, :size] += (1.0 - scheme.alpha_f) * np.matmul(self.damping, known)
        for b, c in enumerate(self.names, start=1):
            self.stacked[:, b * size : (b + 1) * size] = self.history[c].reshape(self.q.shape)
        return np.matmul(self.operator, self.stacked)

    def advance(self, free: np.ndarray, loads: np.ndarray, dt: float, scheme: GeneralizedAlpha) -> None:
        """Complete the step predicted as ``free`` (:meth:`predict`) under the contact ``loads`` (h, d, columns)."""
        a = scheme
        q_new = free + np.matmul(self.load, loads)
        ahead = self.q + dt * self.velocity + (0.5 - a.beta) * dt**2 * self.acceleration
        acceleration = (q_new - ahead) / (a.beta * dt**2)
        self.velocity = self.velocity + dt * ((1.0 - a.gamma) * self.acceleration + a.gamma * acceleration)
        self.unbalance = (
            (1.0 - a.alpha_m) * acceleration + a.alpha_m * self.acceleration - a.alpha_f * self.unbalance
        ) / (1.0 - a.alpha_f)
        self.prony.update_in_place(self.q.ravel(), q_new.ravel(), self.history)
        self.q, self.acceleration = q_new, acceleration


class HarmonicStepper:
    """The cross-section tire's contact-grid dynamics in time steps of ``dt`` (see the module notes).

    Parameters
    ----------
    tire : SectionTire
    dt : float
        Time step (s).
    reduced : list of SteppedHarmonic, optional
        Harmonics ``0..N`` from :func:`reduce_all` (built here if omitted).
    f_max : float
        Band of the Ritz bases (Hz) when they are built here.
    grid : ContactGrid, optional
        The tire's grid with more rows (:func:`roadnoise_utils.tire.cross_section.contact.extended_grid`); default the tire's.
    spectral_radius : float
        Of the generalised-alpha scheme at infinite frequency (:class:`GeneralizedAlpha`).
    runs : int
        Independent runs stepped together (each with its own contact forces). The step's cost is
        mostly reading the harmonics' operators, once per step for all runs: two runs cost
        little more than one. With ``runs > 1`` forces, displacements and hub forces carry a
        leading axis of runs.
    """

    def __init__(
        self,
        tire: SectionTire,
        dt: float,
        reduced: list[SteppedHarmonic] | None = None,
        f_max: float = 400.0,
        grid: ContactGrid | None = None,
        spectral_radius: float = SPECTRAL_RADIUS,
        runs: int = 1,
    ):
        self.dt = guards.real("dt", dt, 0.0, 0.01, lo_open=True, unit="s")
        self.runs = guards.integer("runs", runs, 1, 16)
        grid = tire.grid if grid is None else grid
        n_all = tire.harmonics + 1
        guards.check_memory(8.0 * n_all * 160**2 * 8, f"the Newmark operators of {n_all} harmonics", "[mesh] harmonics")
        reduced = reduce_all(tire, f_max) if reduced is None else reduced
        numbers = np.array([h.n for h in reduced])
        halves: dict[int, list[int]] = {}
        for h in reduced:
            halves.setdefault(h.n, []).append(h.parity)
        complete = all(sorted(p) in ([0], [-1, 1]) for p in halves.values())
        if np.any(np.diff(numbers) < 0) or sorted(halves) != list(range(n_all)) or not complete:
            raise ValueError(
                f"reduced must hold the harmonics 0..{n_all - 1} in order, each whole or as its two halves (reduce_all)"
            )
        ops = tire.ops
        self.branches = {c: PronyBranches(prony_series(ops.laws[c]), self.dt) for c in ops.scaled}
        first_static = next((i for i, h in enumerate(reduced) if h.n >= 2 and h.n_modes == 0), len(reduced))
        parts = [reduced[:first_static], *size_groups(reduced[first_static:])]  # the modal harmonics first
        self.n_harmonics = n_all
        self.scheme = GeneralizedAlpha(guards.real("spectral_radius", spectral_radius, 0.0, 1.0))
        self.groups = [StepGroup(part, self.dt, self.branches, self.scheme, 2 * self.runs) for part in parts if part]
        self.grid = grid
        c = grid.n_cols
        n = np.arange(n_all)
        root = np.sqrt(patch_factor(n, grid.dtheta))  # one sinc for the spread force, one for the averaged motion
        self.cos = np.cos(np.outer(grid.theta, n)) * root  # (rows, harmonics)
        self.sin = np.sin(np.outer(grid.theta, n)) * root
        self.down = -np.cos(grid.theta)  # radial share of an upward force / vertical share of u_r
        self.along = np.sin(grid.theta)
        self.spread = float(np.sinc(grid.dtheta / (2 * np.pi)))
        self.columns = c

    @property
    def dropped(self) -> dict[int, int]:
        """Directions of negative static stiffness left out, per harmonic (see :func:`passive_part`)."""
        return dict(sorted((n, count) for g in self.groups for n, count in g.dropped.items()))

    @property
    def n_dynamic(self) -> int:
        """Last harmonic reduced with its modes."""
        return int(self.groups[0].n[-1])

    def effective_compliance(self) -> np.ndarray:
        """Vertical compliance of the contact grid within one step (m/N), (P, P) in the grid's point order."""
        flex = self._per_harmonic([g.flexibility() for g in self.groups])
        return vertical_compliance(self.grid, 0.5 * (flex + np.transpose(flex, (0, 2, 1))))

    def _per_run(self, values: np.ndarray) -> np.ndarray:
        """Grid values (n_cols, n_rows), or (runs, n_cols, n_rows) with several runs, as (runs, n_cols, n_rows)."""
        shape = (self.runs, self.columns, self.cos.shape[0])
        values = np.asarray(values, float)
        allowed = [shape, shape[1:]] if self.runs == 1 else [shape]
        if values.shape not in allowed:
            raise ValueError(f"grid values must have the shape {allowed[-1]}, got {values.shape}")
        return values.reshape(shape)

    def _as_given(self, values: np.ndarray) -> np.ndarray:
        return values[0] if self.runs == 1 else values

    def loads(self, forces: np.ndarray) -> np.ndarray:
        """Generalised loads (harmonics, 2 c, 2 runs) of upward point forces (n_cols, n_rows) (N), per run."""
        c, runs = self.columns, self.runs
        forces = self._per_run(forces)
        radial, tangential = forces * self.down, forces * self.along  # (runs, c, rows)
        out = np.empty((self.cos.shape[1], 2 * c, runs, 2))
        order = (2, 1, 0)  # (runs, c, harmonics) -> (harmonics, c, runs)
        out[:, :c, :, 0] = np.transpose(radial @ self.cos, order)
        out[:, :c, :, 1] = np.transpose(radial @ self.sin, order)
        out[:, c:, :, 0] = np.transpose(tangential @ self.sin, order)
        out[:, c:, :, 1] = -np.transpose(tangential @ self.cos, order)
        return out.reshape(self.cos.shape[1], 2 * c, 2 * runs)

    def vertical(self, values: np.ndarray) -> np.ndarray:
        """Upward displacement of every grid point (n_cols, n_rows) (m) from contact-DOF values (harmonics, 2 c, 2 runs)."""
        c, runs = self.columns, self.runs
        values = values.reshape(values.shape[0], 2 * c, runs, 2)
        out = np.empty((runs, c, self.cos.shape[0]))
        for r in range(runs):
            radial = self.cos @ values[:, :c, r, 0] + self.sin @ values[:, :c, r, 1]  # (rows, c)
            tangential = self.sin @ values[:, c:, r, 0] - self.cos @ values[:, c:, r, 1]
            out[r] = (self.down[:, None] * radial + self.along[:, None] * tangential).T
        return self._as_given(out)

    def _split(self, loads: np.ndarray):
        """Each group with the loads of its entries (a harmonic's halves see the same contact loads)."""
        for g in self.groups:
            yield g, loads[g.n]

    def _per_harmonic(self, values: list[np.ndarray]) -> np.ndarray:
        """The groups' per-entry values (entries, ...) summed per harmonic (harmonics, ...); a harmonic is in one group."""
        out = np.empty((self.n_harmonics,) + values[0].shape[1:], values[0].dtype)
        for g, v in zip(self.groups, values):
            out[g.harmonics] = np.add.reduceat(v, g.firsts, axis=0)
        return out

    def start(self, forces: np.ndarray) -> np.ndarray:
        """Rest under the static contact forces (n_cols, n_rows) (per run); returns the grid's displacement (m)."""
        for g, part in self._split(self.loads(forces)):
            g.start(part)
        return self.vertical(self._contact_values())

    def _contact_values(self, q: list[np.ndarray] | None = None) -> np.ndarray:
        q = [g.q for g in self.groups] if q is None else q
        return self._per_harmonic([np.matmul(g.contact, x) for g, x in zip(self.groups, q)])

    def predict(self) -> np.ndarray:
        """The next step with no new contact force: grid displacement (m); kept for :meth:`advance`."""
        self._free = [g.predict(self.dt, self.scheme) for g in self.groups]
        return self.vertical(self._contact_values(self._free))

    def advance(self, forces: np.ndarray) -> float | np.ndarray:
        """Complete the predicted step under the contact forces (n_cols, n_rows) (N); returns the hub force (N).

        With several runs: forces (runs, n_cols, n_rows), hub forces (runs,).
        """
        hub = self.spread * self._per_run(forces).sum(axis=(1, 2))
        for (g, part), free in zip(self._split(self.loads(forces)), self._free):
            g.advance(free, part, self.dt, self.scheme)
            for e in g.moving:  # the inertia at t_{n+1} is the unbalance (the scheme's acceleration lags it)
                hub -= g.momentum[e] @ g.unbalance[e, :, 0::2]
        return float(hub[0]) if self.runs == 1 else hub

    def displacement(self) -> np.ndarray:
        """Upward displacement of every grid point at the current step (m), (n_cols, n_rows)."""
        return self.vertical(self._contact_values())


def check_static_start(static: SectionStaticState, start: np.ndarray, penetration: np.ndarray) -> None:
    """Refuse a start whose contact points (``start``, m) do not sit on the road (``penetration``, m).

    The static shapes of every harmonic are in its Ritz basis, so the reduced statics are exact.
    """
    miss = float(np.abs(start - penetration).max())
    if miss > 1e-6 * static.deflection:
        raise RuntimeError(f"the reduced static state misses the road by {miss:.3g} m at the contact points")
