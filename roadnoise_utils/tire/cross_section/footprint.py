"""Footprint dynamics of the cross-section tire: contact receptance and hub-force transfer.

With the tire loaded (:func:`roadnoise_utils.tire.cross_section.static.solve_section_static`), the contact points
follow the road vertically (bilateral, frictionless: the linearisation about the loaded state,
as the paper's FE model with the contact set frozen). At each frequency:

1. the receptance between the contact points, :math:`C(\\omega)`, from the harmonic sum with
   the frequency-dependent moduli (:mod:`roadnoise_utils.tire.cross_section.contact`): every harmonic is
   Ritz-reduced (:mod:`roadnoise_utils.tire.cross_section.dynamics`), those with a mode below ``cutoff`` with their
   modes; the quasi-static rest is sampled in ``n`` (24 harmonics, cubic interpolation between
   them: smooth there, no resonance); every reduced harmonic is evaluated at every frequency;
2. the hub-force transfer of a vertical force at each point, ``t(omega)``, from the exact
   ``n = 1`` rim reaction (:func:`roadnoise_utils.tire.cross_section.dynamics.rim_transfer`);
3. the hub force per unit road displacement at each point,
   :math:`h(\\omega) = C(\\omega)^{-1} t(\\omega)`: a road displacement field ``d`` gives the
   hub force :math:`h^T d`; every point moving together gives :math:`H_{tot} = \\sum h`, the
   points of tassello ``i`` together give :math:`H_i`. On a left-right symmetric tire the solve
   splits into the loads' symmetric and antisymmetric parts, each on one point of each lateral
   pair (:class:`LateralSplit`): half the angular sums, a quarter of the solve's work.

With the points held, a rim motion meets the dynamic stiffness :math:`D_{rim} + t^T C^{-1} t`
(the moving hub's tire, paper Eq. 5-7): ``D_rim`` with the tread free, plus the forces that hold
the points (by reciprocity a unit rim motion moves the free points by ``t``); ``G_H`` is its
negative, the force on the hub, as for the ring model.
"""

from __future__ import annotations

from collections import deque
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace

import numpy as np
from threadpoolctl import threadpool_limits

from ... import guards
from ...parallel import threads
from ..model import FRFResult
from ..tasselli import Tasselli
from . import spec as cross_section
from .cavity_frf import SectionCavityCoupling, cavity_terms, effective_rim, woodbury_solve
from .contact import patch_factor
from .dynamics import rim_transfer
from .footprint_points import (  # noqa: F401 (contact_receptance: the reference, kept importable from here)
    LateralSplit,
    Projection,
    angular_tables,
    blocks_by_sum,
    contact_receptance,
    contact_rows,
    even_projection,
    lateral_split,
)
from .frequency_nodes import smooth_harmonics
from .reductions import FootprintReductions, dynamic_harmonics, footprint_reductions  # noqa: F401 (dynamic_harmonics: kept importable from here)
from .static import SectionStaticState, SectionTire

#: Harmonics with a mode below ``CUTOFF_FACTOR * f_max`` are reduced with those modes (:func:`footprint_frf`).
CUTOFF_FACTOR = 2.5
#: Frequencies per block of the evaluation (memory: block x offsets x (2 columns)^2 complex).
BLOCK = 16


@dataclass(frozen=True, eq=False)
class FootprintFRF:
    """Hub-force transfer of the footprint points of a loaded cross-section tire.

    Attributes
    ----------
    freqs : ndarray (n_f,)
        Hz.
    hub : ndarray (n_f, P) complex
        Hub force per unit vertical road displacement at each contact point (N/m), points in
        the order of ``static.points``.
    transfer : ndarray (n_f, P) complex
        Hub force per unit vertical force at each contact point (-).
    free_rim : ndarray (n_f,) complex
        Dynamic stiffness of the rim's vertical motion with the tread free (N/m).
    static : SectionStaticState
    n_dynamic : int
        Harmonics ``0..n_dynamic`` carried their modes.
    """

    freqs: np.ndarray
    hub: np.ndarray
    transfer: np.ndarray
    free_rim: np.ndarray
    static: SectionStaticState
    n_dynamic: int

    @property
    def H_tot(self) -> np.ndarray:
        """Hub force per unit displacement of the whole footprint (N/m), (n_f,)."""
        return self.hub.sum(axis=1)

    def H_tasselli(self, tasselli: Tasselli | None = None) -> np.ndarray:
        """Hub force per unit displacement of each tassello (N/m), (n_f, n_tasselli)."""
        t = self.static.tasselli if tasselli is None else tasselli
        if t.node_x.size != self.hub.shape[1]:
            raise ValueError("tasselli must partition this footprint's contact points (static.tasselli)")
        return self.hub @ t.membership().T

    def at(self, freqs: np.ndarray) -> FootprintFRF:
        """The same transfer at some of its frequencies (Hz; each must be one of ``self.freqs``)."""
        freqs = np.asarray(freqs, float)
        pick = np.searchsorted(self.freqs, freqs)
        if np.any(pick >= self.freqs.size) or not np.array_equal(
            self.freqs[np.minimum(pick, self.freqs.size - 1)], freqs
        ):
            raise ValueError("freqs must be frequencies of this FootprintFRF")
        return replace(
            self, freqs=freqs, hub=self.hub[pick], transfer=self.transfer[pick], free_rim=self.free_rim[pick]
        )

    def to_frf_result(self) -> FRFResult:
        """The same FRFs as every model's :class:`roadnoise_utils.tire.model.FRFResult` (the input of the fits, Eq. 1-4).

        ``H`` per tassello of ``static.tasselli`` (rows), ``H_points`` per contact point.
        """
        return FRFResult(
            freqs=self.freqs,
            H=self.H_tasselli().T,
            H_tot=self.H_tot,
            G_H=self.G_H,
            H_points=self.hub.T,
            method="cross-section tire: harmonic sum, Ritz-reduced harmonics",
        )

    @property
    def G_H(self) -> np.ndarray:
        """Force the tire exerts on the hub per unit hub displacement, footprint points held (N/m), (n_f,).

        The convention of :attr:`roadnoise_utils.tire.model.FRFResult.G_H` (``-K_v`` at rest): ``-(D_rim + t^T h)``.
        """
        return -(self.free_rim + np.einsum("fp,fp->f", self.transfer, self.hub))


def _check_inputs(tire: SectionTire, static: SectionStaticState, freqs) -> np.ndarray:
    """Refuse frequencies that are not finite, ascending and >= 0, a static state of another tire,
    and evaluation blocks above the memory limit; warn above 2 kHz (the model's band is 400 Hz)."""
    freqs = np.asarray(freqs, float)
    if freqs.ndim != 1 or freqs.size == 0 or not np.all(np.isfinite(freqs)) or freqs.min() < 0:
        raise ValueError("freqs must be a non-empty 1-D array of finite frequencies >= 0 Hz")
    if np.any(np.diff(freqs) <= 0):
        raise ValueError("freqs must be strictly increasing")
    if freqs.max() <= 0:
        raise ValueError("freqs must reach above 0 Hz (the band sets the Ritz bases)")
    if freqs.max() > 2000.0:
        guards.warn(f"freqs reach {freqs.max():g} Hz: the cross-section tire is built for 0-400 Hz")
    if static.tire is not None and cross_section.to_dict(static.tire) != cross_section.to_dict(tire.spec):
        raise ValueError("static was solved for another tire than this one; solve the static state of this tire")
    _, rows = np.nonzero(static.contact)
    n_bytes = 16.0 * BLOCK * (2 * (rows.max() - rows.min()) + 1) * (2 * tire.grid.n_cols) ** 2 * 3
    guards.check_memory(n_bytes, "the footprint FRF's angular sums", "[mesh] contact_spacing, crown_elements")
    return freqs


def _offsets(static: SectionStaticState) -> np.ndarray:
    _, rows = static.points
    span = rows.max() - rows.min()
    return static.grid.dtheta * np.arange(-span, span + 1)


def _trig(n: np.ndarray, offsets: np.ndarray, dtheta: float, basis: np.ndarray | None = None):
    """``cos`` and ``sin`` weights (n_off, n) of the harmonic sums, patch factor included.

    With ``basis`` (n, n_samples) the weights act on sampled harmonics, the receptance of
    harmonic ``n`` being ``basis[n] @ samples`` (interpolation in ``n``).
    """
    weight = patch_factor(n, dtheta)
    cos = np.cos(np.outer(offsets, n)) * weight
    sin = np.sin(np.outer(offsets, n)) * weight
    if basis is not None:
        cos, sin = cos @ basis, sin @ basis
    return cos, sin


def _mirror_pairs(static: SectionStaticState) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fore-aft mirror of the contact points: (points with theta >= 0, index of each point's
    representative among them, the mirror partner of each representative or -1 on theta = 0).

    Raises ValueError when the contact set is not mirror-symmetric.
    """
    col, row = static.points
    rows = static.grid.n_rows
    centre = (rows - 1) // 2
    lookup = {(c, r): k for k, (c, r) in enumerate(zip(col, row))}
    mirror = np.array([lookup.get((c, rows - 1 - r), -1) for c, r in zip(col, row)])
    if np.any(mirror < 0):
        raise ValueError("the contact set is not fore-aft symmetric")
    keep = np.nonzero(row >= centre)[0]
    representative = np.empty(col.size, int)
    representative[keep] = np.arange(keep.size)
    behind = row < centre
    representative[behind] = representative[mirror[behind]]
    partner = np.where(row[keep] > centre, mirror[keep], -1)
    return keep, representative, partner


@dataclass(frozen=True, eq=False)
class EvenFootprint:
    """The contact points' vertical receptance for fore-aft even fields, ready to evaluate.

    The reduced harmonics (``0..n_dynamic`` with their modes, then the sampled quasi-static
    ones), the trigonometric weights of the harmonic sums and the mirror pairing, built once
    for a band (:meth:`build`). :meth:`receptances` gives, per frequency, ``comp`` (R, R) over
    the representatives (points with ``theta >= 0``): the displacement of representative ``a``
    per unit vertical force at representative ``b`` *and its mirror*. ``comp = S W`` with
    ``S`` symmetric and ``W = diag(pair_weight)`` (2 for a mirrored pair, 1 on ``theta = 0``):
    ``S`` is the receptance of the even coordinates, a pair's displacement per unit total force.

    Attributes
    ----------
    tire, static : SectionTire, SectionStaticState
    harmonics : list of ReducedHarmonic
        Dynamic harmonics ``0..n_dynamic``, then the sampled quasi-static ones.
    n_dynamic : int
    keep, representative, partner : ndarray of int
        See :func:`_mirror_pairs`.
    cos, sin : ndarray
        Weights of the harmonic sums (:func:`_trig`).
    projection : Projection
        ``comp`` from the gather table of every column (:meth:`receptances`).
    lateral : LateralSplit
        The solve of :meth:`footprint` split by the left-right mirror (the plain solve without one).
    """

    tire: SectionTire
    static: SectionStaticState
    harmonics: list
    n_dynamic: int
    keep: np.ndarray
    representative: np.ndarray
    partner: np.ndarray
    cos: np.ndarray
    sin: np.ndarray
    projection: Projection
    lateral: LateralSplit

    @classmethod
    def build(
        cls,
        tire: SectionTire,
        static: SectionStaticState,
        f_max: float,
        cutoff: float,
        reductions: FootprintReductions | None = None,
    ) -> EvenFootprint:
        """Reduce the harmonics for ``0..f_max`` Hz, modes below ``cutoff`` Hz (see the module notes).

        ``reductions``: the tire's :func:`footprint_reductions` for this band and cutoff, if computed before.
        """
        keep, representative, partner = _mirror_pairs(static)  # before any work: the set must be symmetric
        grid = tire.grid
        if reductions is None:
            reductions = footprint_reductions(tire, f_max, cutoff)
        elif (reductions.f_max, reductions.cutoff) != (float(f_max), float(cutoff)):
            raise ValueError(
                f"reductions are for {reductions.f_max:g} Hz with modes below {reductions.cutoff:g} Hz, "
                f"not {f_max:g} Hz and {cutoff:g} Hz"
            )
        dynamic, n_high, basis, high = reductions.dynamic, reductions.n_high, reductions.basis, reductions.high
        offsets = _offsets(static)
        cos_dyn, sin_dyn = _trig(np.arange(len(dynamic)), offsets, grid.dtheta)
        cos_high, sin_high = _trig(n_high, offsets, grid.dtheta, basis)
        harmonics = dynamic + high
        projection = even_projection(static, keep, partner, np.arange(keep.size))
        return cls(
            tire=tire,
            static=static,
            harmonics=harmonics,
            n_dynamic=len(dynamic) - 1,
            keep=keep,
            representative=representative,
            partner=partner,
            cos=np.hstack([cos_dyn, cos_high]),
            sin=np.hstack([sin_dyn, sin_high]),
            projection=projection,
            lateral=lateral_split(tire, static, keep, partner, harmonics),
        )

    @property
    def pair_weight(self) -> np.ndarray:
        """2 for a representative with a mirror partner, 1 on ``theta = 0`` (R,)."""
        return np.where(self.partner >= 0, 2.0, 1.0)

    def _tables(
        self, block: np.ndarray, laws: dict, inertia: bool, columns: np.ndarray, smooth=None, part=None
    ) -> np.ndarray:
        """The gather tables (:func:`angular_tables`, (n 4, b)) of the receptance rows of the grid columns
        ``columns`` at the angular frequencies ``block`` (rad/s, at most :data:`BLOCK`); the ``smooth``
        harmonics' share (:class:`~roadnoise_utils.tire.cross_section.frequency_nodes.SmoothHarmonics`)
        interpolated at the requested frequencies ``part``."""
        c = self.tire.grid.n_cols
        rows = contact_rows(c, columns)
        evaluated = np.ones(len(self.harmonics), bool) if smooth is None else ~smooth.smooth
        picked = np.flatnonzero(evaluated)
        if picked.size == 0:  # every harmonic interpolated (no inertia: no resonance)
            return smooth.tables_at(part)
        blocks = np.empty((block.size, picked.size, 4, columns.size, c), complex)
        for j, k in enumerate(picked):
            blocks[:, j] = blocks_by_sum(self.harmonics[k].receptance(laws, block, inertia, rows), c, columns)
        tables = angular_tables(blocks, self.cos[:, picked], self.sin[:, picked])
        if smooth is not None:
            tables += smooth.tables_at(part)
        return tables

    def _blocks(
        self, omegas: np.ndarray, laws: dict | None, inertia: bool, columns: np.ndarray, work=None, interpolate=True
    ):
        """Yields ``(slice, result)`` per block of :data:`BLOCK` frequencies, ``result = work(slice, tables)``
        (default the tables themselves: each frequency's gather table of the receptance rows of the grid
        columns ``columns``, :meth:`_tables`), in the order of the blocks.

        With ``interpolate`` the harmonics without a mode near the band are evaluated on frequency nodes
        and interpolated when the grid is dense (:mod:`roadnoise_utils.tire.cross_section.frequency_nodes`);
        without, every harmonic is evaluated at every frequency (the reference).
        On :func:`roadnoise_utils.parallel.threads` threads, a block each, whole (its harmonics' receptances,
        its tables and ``work``): LAPACK, BLAS and numpy's loops release the GIL, so the cores share every
        step. At most two blocks are held at once.
        """
        laws = self.tire.ops.laws if laws is None else laws
        parts = [slice(start, min(start + BLOCK, len(omegas))) for start in range(0, len(omegas), BLOCK)]
        freqs = np.asarray(omegas) / (2 * np.pi)
        smooth = smooth_harmonics(self, freqs, laws, inertia, columns) if interpolate else None

        def run(part: slice):
            tables = self._tables(np.asarray(omegas[part], float), laws, inertia, columns, smooth, part)
            return tables if work is None else work(part, tables)

        count = threads()
        with ThreadPoolExecutor(max_workers=count) as workers, threadpool_limits(1):
            pending = deque(workers.submit(run, part) for part in parts[:count])
            for index, part in enumerate(parts):
                result = pending.popleft().result()
                if index + count < len(parts):
                    pending.append(workers.submit(run, parts[index + count]))
                yield part, result

    def receptances(self, omegas: np.ndarray, laws: dict | None = None, inertia: bool = True, interpolate: bool = True):
        """``comp`` at angular frequencies ``omegas`` (rad/s), in blocks: yields ``(slice, (b, R, R))``.

        ``laws`` default the tire's own (frequency-dependent) compound laws; ``interpolate``: see :meth:`_blocks`.
        """
        paired = self.partner >= 0
        every_column = np.arange(self.tire.grid.n_cols)
        for part, tables in self._blocks(omegas, laws, inertia, every_column, interpolate=interpolate):
            # an even displacement field: h(j, -a) = h(j, a); the mirrored column adds to its partner
            yield part, self.projection.even(tables, paired)

    def _rim_loads(self, omegas: np.ndarray, laws: dict | None, inertia: bool, cavity: SectionCavityCoupling | None):
        """At ``omegas`` (rad/s): the hub-force transfer of a vertical force at each contact point (n, P), the
        free rim's dynamic stiffness (n,) (:func:`roadnoise_utils.tire.cross_section.dynamics.rim_transfer`; with the
        ``cavity``, both effective: :func:`roadnoise_utils.tire.cross_section.cavity_frf.effective_rim`), and the cavity's
        terms and coupled modes (None without one)."""
        tire, static = self.tire, self.static
        rim = rim_transfer(tire.ops, tire.grid.dofs, omegas, inertia, laws)
        col, row = static.points
        th, c = tire.grid.theta[row], tire.grid.n_cols
        spread = np.sinc(tire.grid.dtheta / (2 * np.pi))
        transfer = (-(np.cos(th) ** 2) * rim.contact[:, col] + np.sin(th) ** 2 * rim.contact[:, c + col]) * spread
        if cavity is None:
            return transfer, rim.free_rim, None, None
        terms = cavity_terms(tire, static, cavity, omegas, self.harmonics)
        coupled = terms.coupled()
        transfer, free_rim = effective_rim(transfer, rim.free_rim, terms, coupled)
        return transfer, free_rim, terms, coupled

    def footprint(
        self,
        freqs: np.ndarray,
        laws: dict | None = None,
        inertia: bool = True,
        progress: bool = False,
        cavity: SectionCavityCoupling | None = None,
        interpolate: bool = True,
    ) -> FootprintFRF:
        """The :class:`FootprintFRF` at ``freqs`` (Hz) with these reductions (``laws``: see :meth:`receptances`);
        with the loaded air ``cavity`` (:mod:`roadnoise_utils.tire.cross_section.cavity_frf`; the tire's own laws, with inertia).
        ``interpolate``: see :meth:`_blocks`."""
        static = self.static
        freqs = np.asarray(freqs, float)
        if cavity is not None and (laws is not None or not inertia):
            raise ValueError("cavity: the air cavity is coupled with the tire's own laws and inertia only")
        col, row = static.points
        hub = np.empty((freqs.size, col.size), complex)
        transfer = np.empty((freqs.size, col.size), complex)
        free_rim = np.empty(freqs.size, complex)
        lateral, paired = self.lateral, self.partner >= 0

        def solve(part: slice, tables: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            loads, rim, terms, coupled = self._rim_loads(2 * np.pi * freqs[part], laws, inertia, cavity)
            comp_rows = lateral.projection.even(tables, paired)
            load = loads[:, self.keep]
            if terms is None:
                return lateral.solve(comp_rows, load)[:, self.representative], loads, rim

            def solve_rows(rhs):
                return lateral.solve(comp_rows, rhs)

            points = terms.points[:, self.keep]
            y = woodbury_solve(solve_rows, load, points, coupled, self.pair_weight)
            return y[:, self.representative], loads, rim

        blocks = self._blocks(2 * np.pi * freqs, laws, inertia, lateral.columns, solve, interpolate)
        if progress:
            from tqdm.auto import tqdm

            blocks = tqdm(blocks, total=-(-freqs.size // BLOCK), desc="footprint FRF")
        for part, (y, loads, rim) in blocks:
            hub[part], transfer[part], free_rim[part] = y, loads, rim
        return FootprintFRF(
            freqs=freqs, hub=hub, transfer=transfer, free_rim=free_rim, static=static, n_dynamic=self.n_dynamic
        )


def footprint_frf(
    tire: SectionTire,
    static: SectionStaticState,
    freqs: np.ndarray,
    cutoff_factor: float = CUTOFF_FACTOR,
    progress: bool = False,
    inertia: bool = True,
    reductions: FootprintReductions | None = None,
    cavity: SectionCavityCoupling | None = None,
    interpolate: bool = True,
) -> FootprintFRF:
    """The footprint's hub-force transfer of a loaded cross-section tire (see the module notes).

    Parameters
    ----------
    tire, static : SectionTire, SectionStaticState
        The contact set must be fore-aft symmetric (flat road or drum: the static solves are);
        the solve works on its mirror-even half.
    freqs : ndarray
        Frequencies (Hz), ascending, >= 0.
    cutoff_factor : float
        Harmonics with a mode below ``cutoff_factor * max(freqs)`` are reduced with those modes;
        at 2.5 the first harmonic without one is within 1.1e-3 of its direct solve at f_max
        (4e-3 at 2.0).
    inertia : bool
        ``False``: the quasi-static response (no inertia, moduli at each frequency), the
        residual anchors of the modal reduction.
    reductions : FootprintReductions, optional
        The tire's :func:`footprint_reductions` for ``max(freqs)`` and the cutoff, if computed
        before (e.g. cached: they do not depend on the loaded state).
    cavity : SectionCavityCoupling, optional
        The loaded air cavity (:func:`roadnoise_utils.tire.cross_section.cavity_frf.section_cavity_coupling` of this
        static state), coupled into the FRFs (beyond the paper); None: the paper's model.
    interpolate : bool
        On a dense grid (at least twice the nodes of
        :func:`~roadnoise_utils.tire.cross_section.frequency_nodes.frequency_nodes`), the harmonics with
        no mode within max(0.25 ``max(freqs)``, 100 Hz) of the band are evaluated on nodes 10 Hz apart
        above 40 Hz and interpolated (:mod:`~roadnoise_utils.tire.cross_section.frequency_nodes`: within 1e-5 of the
        direct evaluation on the 165/65 R14, 0-400 Hz every 1 Hz); ``False`` evaluates every harmonic at
        every frequency.
    """
    freqs = _check_inputs(tire, static, freqs)
    interpolate = guards.flag("interpolate", interpolate)
    _mirror_pairs(static)  # before any work: the set must be symmetric
    f_max = float(freqs.max())
    if reductions is None and cavity is not None:  # the wall's static shapes in the reduced harmonics
        reductions = footprint_reductions(tire, f_max, cutoff_factor * f_max, cavity.cavity.wall)
    even = EvenFootprint.build(tire, static, f_max, cutoff_factor * f_max, reductions)
    return even.footprint(freqs, inertia=inertia, progress=progress, cavity=cavity, interpolate=interpolate)
