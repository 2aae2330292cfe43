"""Tasselli: the footprint divided into blocks in rows and columns (paper Fig. 2).

The paper divides the FE footprint into 71 blocks ("tasselli") and feeds each with one
vertical displacement: "a weighted average of all the physical displacements of the points
inside the area of the tassello, where the weighting function consists of the shape
functions of the finite elements" (section "Simulation of Wheel-Road Interaction").

Here every contact node of the tread carries a bilinear shape function (hat) on the grid of
tread points, so a road height field :math:`z(x, y)` gives the tassello displacement

.. math:: u_i = \\sum_{n \\in i} w_n\\, \\bar z_n, \\qquad
          \\bar z_n = \\frac{\\int N_n z\\,dA}{\\int N_n\\,dA}, \\qquad
          w_n = \\frac{\\int N_n\\,dA}{\\sum_{m \\in i}\\int N_m\\,dA},

so the weights of each tassello sum to one. Columns are groups of belt strips; rows are bands
of equal length along the footprint, a contact point on a row edge in the row nearer the
footprint's middle (on the middle edge itself, the leading row of the two), decided by
geometry, never by round-off (:func:`symmetric_bands`). Tasselli are numbered from 1, row by row from the leading
edge (+x, where the road enters the footprint), and from left (-y) to right in each row.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import pandas as pd

#: Longest tassello side that still resolves 5 cm wavelengths (paper abstract), m.
MAX_TASSELLO_SIZE = 0.025

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(3)


@dataclass(frozen=True, eq=False)
class Tasselli:
    """Partition of the contact nodes into tasselli, with shape-function weights.

    Per contact node (arrays of length ``n_nodes``): ``node_strip``, ``node_index`` (belt node
    indices), ``node_x``, ``node_y`` (tread-surface position, m), ``node_dx_minus``,
    ``node_dx_plus`` (distance to the previous/next tread point along x, m),
    ``node_tassello`` (0-based tassello of the node) and ``node_weight`` (-).

    Per tassello (arrays of length ``n``): ``row``, ``column``, ``centre_x``, ``centre_y``
    (weighted centre, m), ``area`` (gross, m^2) and ``bounds`` (n, 4):
    ``x_min, x_max, y_min, y_max`` of its outline (m).
    """

    node_strip: np.ndarray
    node_index: np.ndarray
    node_x: np.ndarray
    node_y: np.ndarray
    node_dx_minus: np.ndarray
    node_dx_plus: np.ndarray
    strip_width: float
    node_tassello: np.ndarray
    node_weight: np.ndarray
    row: np.ndarray
    column: np.ndarray
    centre_x: np.ndarray
    centre_y: np.ndarray
    area: np.ndarray
    bounds: np.ndarray
    node_width: np.ndarray | None = None

    @property
    def widths(self) -> np.ndarray:
        """Lateral tributary width of each contact node (m): ``node_width``, else ``strip_width``."""
        if self.node_width is None:
            return np.full(self.node_x.size, self.strip_width)
        return self.node_width

    @property
    def n(self) -> int:
        """Number of tasselli."""
        return self.row.size

    @property
    def numbers(self) -> np.ndarray:
        """Labels 1..n as in the paper's Fig. 2."""
        return np.arange(1, self.n + 1)

    @property
    def length(self) -> np.ndarray:
        """Longitudinal size of each tassello (m)."""
        return self.bounds[:, 1] - self.bounds[:, 0]

    @property
    def width(self) -> np.ndarray:
        """Lateral size of each tassello (m)."""
        return self.bounds[:, 3] - self.bounds[:, 2]

    def node_averages(self, height: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> np.ndarray:
        """Shape-function-weighted road height at each contact node, :math:`\\bar z_n` (m).

        ``height(x, y)`` takes arrays of tread-surface coordinates (m, tire frame) and returns
        the road height there (m). The integral over each node's bilinear hat is evaluated by
        3 x 3 Gauss points on each of its four quarters (exact for cubic fields).
        """
        total = np.zeros(self.node_x.size)
        weight = np.zeros(self.node_x.size)
        dy = self.widths
        for dx_side, sx in ((self.node_dx_minus, -1.0), (self.node_dx_plus, 1.0)):
            for sy in (-1.0, 1.0):
                # Gauss points on [0, 1] in each direction, hat = (1 - a)(1 - b)
                a = 0.5 * (_GAUSS_X + 1.0)
                wa = 0.5 * _GAUSS_W
                aa, bb = np.meshgrid(a, a, indexing="ij")
                ww = np.outer(wa, wa) * (1 - aa) * (1 - bb)
                x = self.node_x[:, None, None] + sx * dx_side[:, None, None] * aa[None]
                y = self.node_y[:, None, None] + sy * dy[:, None, None] * bb[None]
                z = np.asarray(height(x, y), dtype=float)
                if not np.all(np.isfinite(z)):
                    raise ValueError("road height field returned NaN or inf inside the footprint")
                jac = dx_side[:, None, None] * dy[:, None, None]
                total += np.sum(ww[None] * z * jac, axis=(1, 2))
                weight += np.sum(ww[None] * jac, axis=(1, 2))
        return total / weight

    def average(self, height: Callable[[np.ndarray, np.ndarray], np.ndarray]) -> np.ndarray:
        """Displacement of each tassello for a road height field, :math:`u_i` (m), (n,)."""
        return np.bincount(self.node_tassello, weights=self.node_weight * self.node_averages(height), minlength=self.n)

    def table(self) -> pd.DataFrame:
        """One row per tassello (number from 1): row, column, centre, size (mm), area (cm^2), contact points."""
        return pd.DataFrame(
            {
                "row": self.row + 1,
                "column": self.column + 1,
                "centre x (mm)": self.centre_x * 1e3,
                "centre y (mm)": self.centre_y * 1e3,
                "length (mm)": self.length * 1e3,
                "width (mm)": self.width * 1e3,
                "area (cm^2)": self.area * 1e4,
                "contact points": np.bincount(self.node_tassello, minlength=self.n),
            },
            index=pd.Index(self.numbers, name="tassello"),
        )

    def membership(self) -> np.ndarray:
        """Matrix (n, n_nodes) with ``[i, m] = 1`` where contact node m belongs to tassello i."""
        out = np.zeros((self.n, self.node_x.size))
        out[self.node_tassello, np.arange(self.node_x.size)] = 1.0
        return out


class FootprintMeasures:
    """Footprint measures of a loaded tire from its tasselli (a mixin of both models' static states).

    Needs the attributes ``tasselli`` (:class:`Tasselli`) and ``load`` (N).
    """

    tasselli: Tasselli
    load: float

    @property
    def footprint_length(self) -> float:
        """Longest contact length (m), the contact points' tributary lengths included."""
        t = self.tasselli
        return float(np.max(t.node_x + 0.5 * t.node_dx_plus) - np.min(t.node_x - 0.5 * t.node_dx_minus))

    @property
    def footprint_width(self) -> float:
        """Width of the columns in contact (m), their tributary widths included."""
        t = self.tasselli
        return float(np.max(t.node_y + 0.5 * t.widths) - np.min(t.node_y - 0.5 * t.widths))

    @property
    def contact_area(self) -> float:
        """Gross contact area (m^2)."""
        return float(np.sum(self.tasselli.area))

    @property
    def mean_pressure(self) -> float:
        """Load over gross contact area (Pa)."""
        return self.load / self.contact_area


#: A node closer than this to a band edge (m) lies on it: the tolerance is far above the round-off
#: of a footprint's positions (~1e-15 m) and far below the tread's node spacing (mm).
EDGE_TOLERANCE = 1e-9


def symmetric_bands(
    position: np.ndarray, extent: float, target: float, odd_on_middle: bool = True
) -> tuple[np.ndarray, int]:
    """Band of each node across ``[0, extent]`` in the fewest equal bands no wider than ``target``.

    A node's band is decided by geometry, never by round-off of its position:

    * a node within :data:`EDGE_TOLERANCE` of an edge goes to the band nearer the middle, so a
      symmetric footprint is cut symmetrically;
    * the middle itself is an edge only for an even number of bands, and no band is nearer there:
      with ``odd_on_middle`` a node on it makes the count odd (the middle of a band then), else it
      goes to the band before the middle.

    Parameters
    ----------
    position : ndarray
        Each node's distance from the partition's start (m), within ``[0, extent]``.
    extent, target : float
        Length to divide and the longest band (m).
    odd_on_middle : bool
        Whether a node on the middle makes the number of bands odd.

    Returns
    -------
    band : ndarray of int
        Band of each node, 0 at the start.
    n_bands : int
        Number of bands, each ``extent / n_bands`` wide.
    """
    n_bands = int(np.ceil(extent / target - 1e-9))
    if odd_on_middle and n_bands % 2 == 0 and np.any(np.abs(position - 0.5 * extent) < EDGE_TOLERANCE):
        n_bands += 1
    width = extent / n_bands
    where = position / width
    tolerance = EDGE_TOLERANCE / width
    before_middle = where < 0.5 * n_bands - tolerance
    band = np.where(before_middle, np.floor(where + tolerance), np.ceil(where - tolerance) - 1)
    return np.clip(band, 0, n_bands - 1).astype(int), n_bands


def tassellate(
    node_strip: np.ndarray,
    node_index: np.ndarray,
    node_x: np.ndarray,
    node_y: np.ndarray,
    node_dx_minus: np.ndarray,
    node_dx_plus: np.ndarray,
    strip_width: float,
    target_length: float,
    strips_per_column: int,
    node_width: np.ndarray | None = None,
    node_column: np.ndarray | None = None,
) -> Tasselli:
    """Divide contact nodes into rows and columns of tasselli.

    Parameters
    ----------
    node_strip, node_index : ndarray of int
        Belt strip and circumferential index of each contact node.
    node_x, node_y : ndarray
        Tread-surface position of each contact node (m).
    node_dx_minus, node_dx_plus : ndarray
        Distance to the neighbouring tread points along x (m).
    strip_width : float
        Width of a belt strip (m).
    target_length : float
        Longest row length (m); rows are equal bands no longer than this.
    strips_per_column : int
        Belt strips per column of tasselli.
    node_width : ndarray, optional
        Lateral tributary width of each node (m) where it differs from node to node (the
        cross-section tire's quadratic elements); default ``strip_width`` for every node.
    node_column : ndarray of int, optional
        Column of tasselli of each node where the columns are not groups of
        ``strips_per_column`` strips (the cross-section tire: bands of equal width over columns
        of unequal width); ``strip_width * strips_per_column`` is then the columns' width.
    """
    column_width = strip_width * strips_per_column
    if column_width > MAX_TASSELLO_SIZE + 1e-12 or target_length > MAX_TASSELLO_SIZE + 1e-12:
        raise ValueError(
            f"tasselli of {column_width * 1e3:.1f} mm x {target_length * 1e3:.1f} mm: both sides must be <= "
            f"{MAX_TASSELLO_SIZE * 1e3:.0f} mm to resolve 5 cm wavelengths ([tasselli] strips_per_column, target_length)"
        )
    if node_x.size == 0:
        raise ValueError("no contact nodes: the tire does not touch the road")
    lead = np.max(node_x + 0.5 * node_dx_plus)
    trail = np.min(node_x - 0.5 * node_dx_minus)
    # rows numbered from the leading edge; a node on the middle edge joins the leading row of the two
    rows, _ = symmetric_bands(lead - node_x, lead - trail, target_length, odd_on_middle=False)
    columns = node_strip // strips_per_column if node_column is None else np.asarray(node_column, int)
    # numbering: row by row from the leading edge, left to right
    key = rows * (columns.max() + 1) + columns
    unique_keys, node_tassello = np.unique(key, return_inverse=True)
    widths = np.full(node_x.size, strip_width) if node_width is None else np.asarray(node_width, float)
    area = 0.5 * (node_dx_minus + node_dx_plus) * widths
    weight = area / np.bincount(node_tassello, weights=area)[node_tassello]
    return tasselli_from_nodes(
        node_strip=node_strip,
        node_index=node_index,
        node_x=node_x,
        node_y=node_y,
        node_dx_minus=node_dx_minus,
        node_dx_plus=node_dx_plus,
        strip_width=strip_width,
        node_tassello=node_tassello,
        node_weight=weight,
        row=unique_keys // (columns.max() + 1),
        column=unique_keys % (columns.max() + 1),
        node_width=None if node_width is None else widths,
    )


def tasselli_from_nodes(
    *,
    node_strip: np.ndarray,
    node_index: np.ndarray,
    node_x: np.ndarray,
    node_y: np.ndarray,
    node_dx_minus: np.ndarray,
    node_dx_plus: np.ndarray,
    strip_width: float,
    node_tassello: np.ndarray,
    node_weight: np.ndarray,
    row: np.ndarray,
    column: np.ndarray,
    node_width: np.ndarray | None = None,
) -> Tasselli:
    """:class:`Tasselli` from its contact nodes, each with its tassello and FE weight; the tasselli's
    centres, areas and outlines follow from the nodes (as :func:`tassellate` defines them).

    ``node_tassello`` numbers the tasselli from 0 (every one holding a node); ``row`` and
    ``column`` are per tassello. The centre is the weighted centroid of the nodes' shape-function
    kernels: a hat over ``[x - dx_minus, x + dx_plus]`` has its centroid at
    ``x + (dx_plus - dx_minus) / 3``, so linear road fields average to the centre.
    """
    n = int(node_tassello.max()) + 1
    widths = np.full(node_x.size, strip_width) if node_width is None else np.asarray(node_width, float)
    area = 0.5 * (node_dx_minus + node_dx_plus) * widths

    def _reduce(values: np.ndarray, fn) -> np.ndarray:
        out = np.full(n, np.nan)
        for i in range(n):
            out[i] = fn(values[node_tassello == i])
        return out

    bounds = np.column_stack(
        [
            _reduce(node_x - 0.5 * node_dx_minus, np.min),
            _reduce(node_x + 0.5 * node_dx_plus, np.max),
            _reduce(node_y - 0.5 * widths, np.min),
            _reduce(node_y + 0.5 * widths, np.max),
        ]
    )
    return Tasselli(
        node_strip=node_strip,
        node_index=node_index,
        node_x=node_x,
        node_y=node_y,
        node_dx_minus=node_dx_minus,
        node_dx_plus=node_dx_plus,
        strip_width=strip_width,
        node_tassello=node_tassello,
        node_weight=node_weight,
        row=row,
        column=column,
        centre_x=np.bincount(
            node_tassello, weights=node_weight * (node_x + (node_dx_plus - node_dx_minus) / 3), minlength=n
        ),
        centre_y=np.bincount(node_tassello, weights=node_weight * node_y, minlength=n),
        area=np.bincount(node_tassello, weights=area, minlength=n),
        bounds=bounds,
        node_width=node_width,
    )
