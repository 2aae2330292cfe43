"""Structured mesh of a tire cross-section: 9-node layered solids along the meridian.

The cross-section is a band along a meridian curve, ``2 E + 1`` node stations along it and
``2 L + 1`` node rows through the thickness (``E`` elements along, ``L`` element layers
through). Each element carries a stack of plies, each a fraction of its thickness with its own
material: a layered solid element, integrated ply by ply (three Gauss points per ply through the
thickness, three along the meridian), so a 1 mm steel belt ply and a 10 mm tread share one
element layer without locking the mesh to the thinnest ply.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import laminate
from .waveguide import QuadraturePoints, lagrange3

_GAUSS_PLY = np.polynomial.legendre.leggauss(3)
_GAUSS3 = np.polynomial.legendre.leggauss(3)


@dataclass(frozen=True)
class Ply:
    """One material layer of an element stack.

    Attributes
    ----------
    name : str
        Construction layer it belongs to (``"tread"``, ``"belt_1"``...).
    fraction : float
        Share of the element thickness (-).
    stiffness : ndarray (6, 6)
        Static stiffness in the layer axes ``(n, theta, s)`` (Pa).
    density : float
        kg/m^3.
    compound : str
        Modulus law (``[compounds.*]``) scaling its stiffness with frequency.
    """

    name: str
    fraction: float
    stiffness: np.ndarray
    density: float
    compound: str


@dataclass(frozen=True, eq=False)
class SectionMesh:
    """Nodes, elements and integration points of the cross-section.

    Attributes
    ----------
    r, y : ndarray (n_nodes,)
        Node coordinates (m): radius and axial position.
    elements : ndarray of int (n_el, 9)
        Node indices, local node ``3 a + b`` (``a`` along the meridian, ``b`` through the thickness).
    points : QuadraturePoints
    n_stations, n_rows : int
        Node stations along the meridian (``2 E + 1``) and rows through the thickness (``2 L + 1``).
    """

    r: np.ndarray
    y: np.ndarray
    elements: np.ndarray
    points: QuadraturePoints
    n_stations: int
    n_rows: int

    @property
    def n_nodes(self) -> int:
        return self.r.size

    @property
    def n_dof(self) -> int:
        return 3 * self.r.size

    def node(self, station: np.ndarray | int, row: np.ndarray | int) -> np.ndarray:
        """Node index at ``station`` along the meridian and ``row`` through the thickness."""
        return np.asarray(station) * self.n_rows + np.asarray(row)

    def face_lines(self, row: int) -> np.ndarray:
        """Three-node lines (E, 3) along the face at node ``row`` (0 inner, ``n_rows - 1`` outer)."""
        stations = np.arange(0, self.n_stations - 2, 2)
        return self.node(stations[:, None] + np.arange(3), row)

    @property
    def bead_nodes(self) -> np.ndarray:
        """Nodes of the two end stations (clamped to the rim)."""
        rows = np.arange(self.n_rows)
        return np.concatenate([self.node(0, rows), self.node(self.n_stations - 1, rows)])


def structured_mesh(node_r: np.ndarray, node_y: np.ndarray, stacks: list[list[list[Ply]]]) -> SectionMesh:
    """Build the mesh from a node grid and the ply stack of every element.

    Parameters
    ----------
    node_r, node_y : ndarray (2E + 1, 2L + 1)
        Node coordinates, stations along the meridian by rows through the thickness (m).
    stacks : list (E) of list (L) of list of Ply
        Plies of element ``(e, l)`` from its inner face outwards; fractions sum to 1.
    """
    n_st, n_rows = node_r.shape
    n_el, n_layers = (n_st - 1) // 2, (n_rows - 1) // 2
    if len(stacks) != n_el or any(len(s) != n_layers for s in stacks):
        raise ValueError("stacks must hold one ply list per element (E x L)")
    node = np.arange(n_st * n_rows).reshape(n_st, n_rows)
    elements, records = [], []
    names: dict[str, int] = {}
    compounds: dict[str, int] = {}
    xg, wg = _GAUSS3
    tg, tw = _GAUSS_PLY
    for e in range(n_el):
        for layer in range(n_layers):
            index = len(elements)
            elements.append(node[2 * e : 2 * e + 3, 2 * layer : 2 * layer + 3].ravel())
            plies = stacks[e][layer]
            total = sum(p.fraction for p in plies)
            if abs(total - 1.0) > 1e-9:
                raise ValueError(f"ply fractions of element ({e}, {layer}) sum to {total:g}, not 1")
            eta0 = -1.0
            for ply in plies:
                eta1 = eta0 + 2.0 * ply.fraction
                names.setdefault(ply.name, len(names))
                compounds.setdefault(ply.compound, len(compounds))
                for t, wt in zip(tg, tw):
                    eta = eta0 + (eta1 - eta0) * (t + 1.0) / 2.0
                    for x, wx in zip(xg, wg):
                        records.append(
                            (index, x, eta, wx * wt * ply.fraction, ply, names[ply.name], compounds[ply.compound])
                        )
                eta0 = eta1
    elements = np.asarray(elements)
    element = np.array([rec[0] for rec in records])
    xi = np.array([rec[1] for rec in records])
    eta = np.array([rec[2] for rec in records])
    tangent_r, tangent_y = meridian_tangent(node_r.ravel(), node_y.ravel(), elements[element], xi, eta)
    stiffness = np.empty((element.size, 6, 6))
    for q, rec in enumerate(records):
        stiffness[q] = laminate.to_model_axes(rec[4].stiffness, tangent_r[q : q + 1], tangent_y[q : q + 1])[0]
    points = QuadraturePoints(
        element=element,
        xi=xi,
        eta=eta,
        weight=np.array([rec[3] for rec in records]),
        stiffness=stiffness,
        density=np.array([rec[4].density for rec in records]),
        compound=np.array([rec[6] for rec in records]),
        compounds=tuple(compounds),
        layer=np.array([rec[5] for rec in records]),
        layers=tuple(names),
    )
    return SectionMesh(
        r=node_r.ravel().copy(),
        y=node_y.ravel().copy(),
        elements=elements,
        points=points,
        n_stations=n_st,
        n_rows=n_rows,
    )


def meridian_tangent(
    r: np.ndarray, y: np.ndarray, elem_nodes: np.ndarray, xi: np.ndarray, eta: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangent ``(s_r, s_y)`` along the element's ``xi`` direction (the meridian) at each point.

    ``r, y`` are the section's node coordinates (m), ``elem_nodes`` (q, 9) each point's element
    nodes, ``xi, eta`` (q,) its parent coordinates.
    """
    ni, di = lagrange3(xi)
    nj, _ = lagrange3(eta)
    d_xi = (di[:, None, :] * nj[None, :, :]).reshape(9, -1).T
    dr = (d_xi * r[elem_nodes]).sum(1)
    dy = (d_xi * y[elem_nodes]).sum(1)
    norm = np.hypot(dr, dy)
    return dr / norm, dy / norm
