"""The cross-section tire swept around its axle: a 3-D mesh of 27-node layered solids.

Each 9-node layered element of the cross-section (:mod:`roadnoise_utils.tire.cross_section.mesh`:
quadratic along the meridian and through the thickness, integrated ply by ply) is swept through
an arc of the circumference into a 27-node element, quadratic in the angle as well. The nodes of
a ring (one angle) are the section's nodes; the rings are the arcs' end and mid angles, so the
mesh closes on itself. The arcs are graded (:func:`graded_arcs`): short in the footprint
sector around the bottom of the tire, long elsewhere.

Axes: ``x`` forward (the direction of travel at the bottom), ``y`` along the axle (the section's
axial coordinate), ``z`` up, the axle at the origin. The angle ``theta`` is measured from the
bottom of the tire towards ``x``, as in the waveguide model: a section point at radius ``r``
sits at ``(r sin theta, y, -r cos theta)``. The geometry is isoparametric: inside an element it
is interpolated from the nodes, which lie on the exact surfaces of revolution.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp

from ..cross_section.mesh import SectionMesh

#: Largest length ratio of two neighbouring arcs in a graded circumference.
GROWTH = 1.3


@dataclass(frozen=True, eq=False)
class SolidMesh:
    """Nodes and 27-node elements of the swept tire.

    Attributes
    ----------
    section : SectionMesh
        The cross-section swept (its nodes, elements and ply-by-ply integration points).
    theta : ndarray (n_rings,)
        Angle of every ring of nodes (rad, from the bottom, in ``[-pi, pi)``): the arcs' end
        and mid angles in turn.
    coordinates : ndarray (n_nodes, 3)
        Node positions ``(x, y, z)`` (m); node ``ring * n_section_nodes + section_node``.
    elements : ndarray of int (n_el, 27)
        Node indices; local node ``9 c + k`` is node ``k`` of the section element on the
        element's ring ``c`` (0, 1, 2: start, middle and end of its arc).
    section_element : ndarray of int (n_el,)
        The section element each element is swept from.
    arc : ndarray of int (n_el,)
        The arc (around the circumference) each element spans.
    """

    section: SectionMesh
    theta: np.ndarray
    coordinates: np.ndarray
    elements: np.ndarray
    section_element: np.ndarray
    arc: np.ndarray

    @property
    def n_nodes(self) -> int:
        return self.coordinates.shape[0]

    @property
    def n_dof(self) -> int:
        return 3 * self.n_nodes

    @property
    def n_arcs(self) -> int:
        return self.theta.size // 2

    def node(self, ring: np.ndarray | int, section_node: np.ndarray | int) -> np.ndarray:
        """Index of ``section_node`` on ``ring``."""
        return np.asarray(ring) * self.section.n_nodes + np.asarray(section_node)

    @cached_property
    def scatter(self) -> Scatter:
        """Where the entries of every element's matrix land in the mesh's sparse matrices (built once)."""
        return Scatter.of(self.elements, self.n_dof)

    @property
    def bead_nodes(self) -> np.ndarray:
        """The nodes of both bead stations on every ring (clamped to the rim)."""
        rings = np.arange(self.theta.size)
        return np.ravel(self.node(rings[:, None], self.section.bead_nodes[None, :]))


@dataclass(frozen=True, eq=False)
class Scatter:
    """The sparse pattern (CSR) of a mesh's matrices and where each element matrix entry lands in it.

    Assembling by this map is one weighted ``numpy.bincount`` of the element entries into the
    pattern's values, instead of a coordinate list sorted and summed at every assembly (the statics
    assemble a tangent at every Newton iteration).

    Attributes
    ----------
    indptr, indices : ndarray of int
        The CSR pattern: every DOF pair two elements share or one element couples.
    positions : ndarray of int (n_el, 81 * 81)
        Index into the pattern's values of each element's entry ``(3 a + i, 3 b + j)``, row-major.
    n_dof : int
    """

    indptr: np.ndarray
    indices: np.ndarray
    positions: np.ndarray
    n_dof: int

    @classmethod
    def of(cls, elements: np.ndarray, n_dof: int) -> Scatter:
        """The scatter of 27-node ``elements`` (n_el, 27) over ``n_dof`` DOF (three per node)."""
        dofs = (3 * elements[:, :, None] + np.arange(3)).reshape(elements.shape[0], -1)
        keys = (dofs[:, :, None].astype(np.int64) * n_dof + dofs[:, None, :]).reshape(dofs.shape[0], -1)
        # sorted: row-major, the CSR order (a sort and a mask: numpy's hash-based ``unique`` of integers
        # takes ~18x longer on these millions of keys)
        ordered = np.sort(keys, axis=None)
        pattern = ordered[np.concatenate(([True], ordered[1:] != ordered[:-1]))]
        rows = pattern // n_dof
        return cls(
            indptr=np.searchsorted(rows, np.arange(n_dof + 1)).astype(np.int32),
            indices=(pattern % n_dof).astype(np.int32),
            positions=np.searchsorted(pattern, keys).astype(np.int32),
            n_dof=n_dof,
        )

    def matrix(self, elements: list[np.ndarray], blocks: list[np.ndarray]) -> sp.csr_matrix:
        """The sparse matrix of the element matrices ``blocks`` (each (m, 81, 81), real) of the ``elements``
        (each (m,) indices), summed where they share DOF."""
        positions = np.concatenate([self.positions[e].ravel() for e in elements])
        values = np.concatenate([np.asarray(b, float).ravel() for b in blocks])
        data = np.bincount(positions, weights=values, minlength=self.indices.size)
        return sp.csr_matrix((data, self.indices, self.indptr), shape=(self.n_dof, self.n_dof))


def graded_arcs(
    radius: float, fine_length: float, sector_half_angle: float, coarse_length: float, growth: float = GROWTH
) -> np.ndarray:
    """Arc boundaries (rad) of a circumference, fine in a sector around the bottom, coarse elsewhere.

    Arcs of at most ``fine_length`` (m, at ``radius``) cover ``-sector_half_angle..sector_half_angle``
    (an arc boundary at the bottom, ``theta = 0``);
    beyond it they grow by at most ``growth`` (default :data:`GROWTH`) per arc up to ``coarse_length``, and equal
    arcs no longer than that fill the rest, symmetric about the bottom.

    Returns
    -------
    ndarray (n_arcs + 1,)
        Increasing angles from ``-pi`` to ``pi``.
    """
    if not 0.0 < fine_length <= coarse_length:
        raise ValueError(f"fine_length = {fine_length!r} m must be > 0 and <= coarse_length = {coarse_length!r} m")
    if not growth > 1.0:
        raise ValueError(f"growth = {growth!r} must be > 1")
    if not 0.0 <= sector_half_angle < np.pi:
        raise ValueError(f"sector_half_angle = {sector_half_angle!r} rad must be in [0, pi)")
    n_half = max(1, int(np.ceil(sector_half_angle * radius / fine_length - 1e-9)))
    fine = sector_half_angle / n_half if sector_half_angle > 0 else fine_length / radius
    side = list(np.full(n_half, fine))  # from the bottom (theta = 0) towards pi
    coarse = coarse_length / radius
    step = fine
    while step * growth < coarse and sum(side) + step * growth < np.pi:
        step *= growth
        side.append(step)
    rest = np.pi - sum(side)
    n_rest = int(np.ceil(rest / coarse - 1e-9)) if rest > 1e-12 else 0
    upper = np.cumsum(np.concatenate([side, np.full(n_rest, rest / max(n_rest, 1))]))
    if upper[-1] > np.pi + 1e-12:
        raise ValueError(
            f"the fine sector (+-{sector_half_angle:g} rad of {fine_length:g} m arcs) does not fit in one turn"
        )
    upper[-1] = np.pi
    return np.concatenate([-upper[::-1], [0.0], upper])


def sweep(section: SectionMesh, arcs: np.ndarray) -> SolidMesh:
    """Sweep ``section`` through the arcs of ``arcs`` (boundaries, rad, ``-pi`` to ``pi``).

    Parameters
    ----------
    section : SectionMesh
        The layered cross-section (waveguide mesh of the tire file).
    arcs : ndarray (n_arcs + 1,)
        Strictly increasing arc boundaries spanning exactly one turn (e.g. :func:`graded_arcs`).
    """
    arcs = np.asarray(arcs, float)
    if arcs.ndim != 1 or arcs.size < 4 or np.any(np.diff(arcs) <= 0):
        raise ValueError("arcs must be at least 3 strictly increasing arc boundaries (rad)")
    if abs(arcs[-1] - arcs[0] - 2 * np.pi) > 1e-9:
        raise ValueError(f"arcs must span one turn (2 pi), got {arcs[-1] - arcs[0]:.12g} rad")
    n_arcs = arcs.size - 1
    theta = np.empty(2 * n_arcs)
    theta[0::2] = arcs[:-1]
    theta[1::2] = 0.5 * (arcs[:-1] + arcs[1:])
    n_section = section.n_nodes
    sin, cos = np.sin(theta)[:, None], np.cos(theta)[:, None]
    coordinates = np.stack(
        [
            (section.r[None, :] * sin).ravel(),
            np.broadcast_to(section.y[None, :], (theta.size, n_section)).ravel(),
            (-section.r[None, :] * cos).ravel(),
        ],
        axis=1,
    )
    n_sec_el = section.elements.shape[0]
    arc = np.repeat(np.arange(n_arcs), n_sec_el)
    section_element = np.tile(np.arange(n_sec_el), n_arcs)
    rings = (2 * arc[:, None] + np.arange(3)) % theta.size  # (n_el, 3)
    elements = (rings[:, :, None] * n_section + section.elements[section_element][:, None, :]).reshape(-1, 27)
    return SolidMesh(
        section=section,
        theta=theta,
        coordinates=coordinates,
        elements=elements,
        section_element=section_element,
        arc=arc,
    )
