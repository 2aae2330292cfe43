"""The contact points of the cross-section footprint: receptance gathers and the footprint solve.

The footprint solve (:mod:`roadnoise_utils.tire.cross_section.footprint`) sums the reduced harmonics' receptances at the
contact DOF over the harmonics for every row offset (the angular sums, :func:`angular_table`),
then gathers the vertical receptance of each pair of contact points from them
(:class:`Projection`). A fore-aft even field needs only the points with ``theta >= 0``
(:func:`roadnoise_utils.tire.cross_section.footprint._mirror_pairs`); on a left-right symmetric tire the solve splits
again into symmetric and antisymmetric loads (:class:`LateralSplit`), each on one point of
each lateral pair, reading only the left half's rows of the sums.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import sparse

from .contact import angular_sums
from .dynamics import direct_receptance, lateral_mirror
from .static import SectionStaticState, SectionTire


def contact_rows(c: int, columns: np.ndarray) -> np.ndarray:
    """The contact DOF of the grid columns ``columns``: their radial, then their tangential DOF (2n,)."""
    return np.concatenate([columns, c + columns])


def blocks_by_sum(receptance: np.ndarray, c: int, columns: np.ndarray) -> np.ndarray:
    """A harmonic's receptance rows (b, 2n, 2c) of the grid columns ``columns`` (n,), in the order of
    :func:`contact_rows`, as its blocks in summation order (b, 4, n, c).

    ``rr`` and ``tt`` (summed with ``cos``), then ``-rt`` and ``tr`` (summed with ``sin``), as
    :func:`roadnoise_utils.tire.cross_section.contact.angular_sums` sums them; only the rows of the grid columns
    ``columns`` (the loaded points' columns the gathers read).
    """
    n = columns.size
    out = np.empty((receptance.shape[0], 4, n, c), receptance.dtype)
    radial, tangential = receptance[:, :n], receptance[:, n:]
    out[:, 0], out[:, 1] = radial[:, :, :c], tangential[:, :, c:]
    out[:, 2], out[:, 3] = -radial[:, :, c:], tangential[:, :, :c]
    return out


def angular_tables(blocks: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    """Harmonic sums of a block of frequencies' receptance blocks (b, n_n, 4, n, c) (:func:`blocks_by_sum`)
    as gather tables.

    Returns (n_off n c 4, b) complex, frequencies last: for each (offset, row column, column) the sums
    of ``rr, tt, rt, tr`` (:meth:`Projection.even` reads them so, in one sparse product for the block).
    The weights are real, so each sum is one real product over the real and imaginary parts together
    (half the work of a complex one), for every frequency of the block at once.
    """
    b, n_n, _, n, c = blocks.shape
    values = blocks.view(float).reshape(b, n_n, 2, -1)  # (b, n_n, [rr tt | rt tr], 2 n c complex as floats)
    even = np.matmul(cos, values[:, :, 0]).reshape(b, -1, 2, n, c, 2)
    odd = np.matmul(sin, values[:, :, 1]).reshape(b, -1, 2, n, c, 2)
    sums = np.concatenate([even, odd], axis=2)  # (b, n_off, 4, n, c, re/im)
    return np.ascontiguousarray(sums.transpose(1, 3, 4, 2, 0, 5)).view(complex).reshape(-1, b)


def column_image(tire: SectionTire) -> np.ndarray | None:
    """Each contact-grid column's left-right mirror image among the columns, or None (asymmetric section)."""
    mirror = lateral_mirror(tire.ops)
    if mirror is None:
        return None
    target, _ = mirror
    position = {node: j for j, node in enumerate(tire.grid.nodes)}
    image = np.array([position.get(target[3 * node] // 3, -1) for node in tire.grid.nodes])
    return None if np.any(image < 0) else image


@dataclass(frozen=True, eq=False)
class LateralSplit:
    """The footprint solve :math:`C y = t` split by the tire's left-right mirror.

    On a symmetric tire (every reduced harmonic with its mirror, the contact set symmetric) the
    even receptance ``comp`` (R, R) commutes with the mirror of the points: a load splits into
    its symmetric and antisymmetric parts, each solved on one point of each lateral pair, from
    the rows ``rows`` of ``comp`` only (so only those rows' angular sums are needed): two solves
    of about R/2 instead of one of R. Without a mirror every point is its own image: the plain solve.

    Attributes
    ----------
    rows : ndarray of int (R_L,)
        Representatives solved for: each lateral pair once, the centre column's points alone.
    partner : ndarray of int (R_L,)
        Each row's lateral image among the representatives (itself on the centre column).
    columns : ndarray of int
        Grid columns of the rows: the receptance rows the angular sums are taken of.
    projection : Projection
        ``comp[rows]`` (R_L, R) from the gather table of those columns.
    """

    rows: np.ndarray
    partner: np.ndarray
    columns: np.ndarray
    projection: Projection

    def solve(self, comp_rows: np.ndarray, load: np.ndarray) -> np.ndarray:
        """``y`` (b, R) with ``comp y = load`` (b, R) from ``comp_rows = comp[:, rows]`` (b, R_L, R);
        a load (b, R, k) gives k solutions (b, R, k) from the same factorisations."""
        single = load.ndim == 2
        load = load[..., None] if single else load
        rows, partner = self.rows, self.partner
        pairs = partner != rows
        direct, image = comp_rows[:, :, rows], comp_rows[:, :, partner]
        even_load, odd_load = 0.5 * (load[:, rows] + load[:, partner]), 0.5 * (load[:, rows] - load[:, partner])
        symmetric = np.linalg.solve(direct + image * pairs[None, None, :], even_load)
        y = np.empty(load.shape, complex)
        y[:, rows], y[:, partner] = symmetric, symmetric
        if pairs.any():
            antisymmetric = (direct - image)[:, pairs][:, :, pairs]
            odd = np.linalg.solve(antisymmetric, odd_load[:, pairs])
            y[:, rows[pairs]] += odd
            y[:, partner[pairs]] -= odd
        return y[..., 0] if single else y


def even_projection(static: SectionStaticState, keep, partner, rows: np.ndarray, first=None) -> Projection:
    """``comp`` of the representatives ``keep`` (fore-aft mirror ``partner``), rows ``rows`` of them."""
    grid = static.grid
    col, row = static.points
    th = grid.theta[row]
    centre = int(row.max() - row.min())  # offsets -span..span (section_footprint._offsets)
    paired = partner >= 0
    kept, mirrors = keep, partner[paired]
    direct = row[kept[rows]][:, None] - row[kept][None, :] + centre
    mirrored = row[kept[rows]][:, None] - row[mirrors][None, :] + centre
    return Projection(
        (col[kept[rows]], th[kept[rows]]), (col[kept], th[kept]), (col[mirrors], th[mirrors]),
        direct, mirrored, grid.n_cols, first,
    )  # fmt: skip


def lateral_split(tire: SectionTire, static: SectionStaticState, keep, partner, harmonics: list) -> LateralSplit:
    """The :class:`LateralSplit` of the representatives ``keep`` (the plain solve without a mirror)."""
    col, row = static.points
    image = column_image(tire) if all(h.mirror is not None for h in harmonics) else None
    identity = np.arange(keep.size)
    rows, images = identity, identity
    if image is not None:
        lookup = {(c, r): k for k, (c, r) in enumerate(zip(col[keep], row[keep]))}
        found = np.array([lookup.get((image[c], r), -1) for c, r in zip(col[keep], row[keep])])
        if np.all(found >= 0):
            rows = np.nonzero(image[col[keep]] >= col[keep])[0]  # one column of each mirror pair
            images = found[rows]
    columns = np.unique(col[keep][rows])
    first = np.full(tire.grid.n_cols, -1)
    first[columns] = np.arange(columns.size)
    return LateralSplit(rows, images, columns, even_projection(static, keep, partner, rows, first))


class Projection:
    """Vertical receptance of the contact points from the (r, theta) angular sums.

    ``u_z = -cos(a) u_r + sin(a) u_t`` and a vertical force ``F`` loads ``f_r = -cos(b) F``,
    ``f_t = sin(b) F``. The trigonometric weights and the positions of each point pair in the
    sums' gather table (offset, row column, column; :func:`angular_tables`) do not depend on
    frequency: built once. ``first`` (n_cols,) is the position of each grid column among the
    table's row columns (default: the table has every column's row).
    """

    def __init__(self, rows, columns, mirrors, direct, mirrored, c, first=None):
        """``rows``, ``columns``, ``mirrors``: (grid column, angle) of the receptance's rows, its
        columns and the columns' fore-aft mirrors; ``direct``, ``mirrored``: offset positions."""
        (row_col, row_theta), (col, theta), (mirror_col, mirror_theta) = rows, columns, mirrors
        self.c = c
        first = np.arange(c) if first is None else np.asarray(first)
        n_first = int(first.max()) + 1
        self.direct = ((direct * n_first + first[row_col][:, None]) * c + col[None, :]).astype(np.intp)
        self.mirrored = ((mirrored * n_first + first[row_col][:, None]) * c + mirror_col[None, :]).astype(np.intp)
        self.weights = [self._weights(row_theta, theta), self._weights(row_theta, mirror_theta)]

    @staticmethod
    def _weights(theta_a, theta_b):
        ca, sa, cb, sb = np.cos(theta_a), np.sin(theta_a), np.cos(theta_b), np.sin(theta_b)
        # blocks rr, tt, rt, tr (the gather table's order)
        return np.stack([np.outer(ca, cb), np.outer(sa, sb), -np.outer(ca, sb), -np.outer(sa, cb)], axis=-1)

    @staticmethod
    def block(table: np.ndarray, pick: np.ndarray, weights: np.ndarray) -> np.ndarray:
        """The vertical receptance of the point pairs at positions ``pick`` of one frequency's ``table``
        (n, 4) complex (:func:`angular_tables`), ``weights`` (.., 4)."""
        return np.einsum("abk,abk->ab", np.take(table, pick, axis=0), weights)

    def even(self, tables: np.ndarray, paired: np.ndarray) -> np.ndarray:
        """Receptance of an even (fore-aft symmetric) field on the points with theta >= 0, (b, rows, R), from
        a block of frequencies' gather tables (n 4, b) (:func:`angular_tables`).

        The gather and the weighted sums are one linear map from a table's entries to ``comp``, built
        once per ``paired``: one sparse product for every frequency of the block.
        """
        operator = self._even_operator(paired, tables.shape[0])
        return (operator @ tables).T.reshape((tables.shape[1],) + self.direct.shape)

    def _even_operator(self, paired: np.ndarray, n_entries: int) -> sparse.csr_matrix:
        key = (np.asarray(paired, bool).tobytes(), n_entries)
        cached = getattr(self, "_operators", {})
        if key not in cached:
            rows, cols = self.direct.shape
            out = np.arange(rows * cols).reshape(rows, cols)
            targets = [out, out[:, np.asarray(paired, bool)]]
            positions = [self.direct, self.mirrored]
            entry_rows = np.concatenate([np.repeat(t.ravel(), 4) for t in targets])
            entry_cols = np.concatenate([(4 * p[..., None] + np.arange(4)).ravel() for p in positions])
            values = np.concatenate([w.ravel() for w in self.weights]).astype(complex)
            shape = (rows * cols, n_entries)
            cached[key] = sparse.csr_matrix((values, (entry_rows, entry_cols)), shape=shape)
            self._operators = cached
        return cached[key]


def contact_receptance(tire: SectionTire, static: SectionStaticState, frequency: float) -> np.ndarray:
    """Vertical receptance between the contact points at one frequency (m/N), (P, P) complex.

    Every harmonic solved directly (no reduction, no interpolation): the reference of
    :func:`footprint_frf` and the input of a contact model of the user's own. Points in the
    order of ``static.points``; a vertical force at point ``b`` moves point ``a`` by ``C[a, b]``.
    """
    grid, ops = tire.grid, tire.ops
    omega = 2 * np.pi * float(frequency)
    flex = np.stack([direct_receptance(ops, grid.dofs, n, omega) for n in range(tire.harmonics + 1)])
    col, row = static.points
    offsets = grid.dtheta * np.arange(-(grid.n_rows - 1), grid.n_rows)
    sums = angular_sums(flex, offsets, grid.dtheta)
    th = grid.theta[row]
    offset_index = row[:, None] - row[None, :] + grid.n_rows - 1
    projection = Projection((col, th), (col, th), (col, th), offset_index, offset_index, grid.n_cols)
    c = grid.n_cols
    blocks = np.stack([sums[:, :c, :c], sums[:, c:, c:], sums[:, :c, c:], sums[:, c:, :c]], axis=1)
    table = np.moveaxis(blocks, 1, 3).reshape(-1, 4)  # (offset, row column, column) x (rr, tt, rt, tr)
    return projection.block(table, projection.direct, projection.weights[0])
