"""The meridian of a cross-section tire file and its layered mesh.

The reference line of the mesh is the outer face of the structure (the belt top at the crown,
the carcass's outer face on the sidewalls). From it, node rows go inward by the structure
stack (``crown`` or ``sidewall``) and outward by the cover stack (``tread`` or
``sidewall_cover``), two 9-node elements through the thickness:

* crown: a circular arc of radius ``crown_radius - tread thickness`` about the tread's centre of
  curvature, so the outer face is the tread surface of transverse radius ``crown_radius``;
* sidewall: the equilibrium ("natural") shape of an inflated radial carcass, one meridional
  tension constant ``N r`` from the bead (``bead_radius``, ``bead_width / 2``) to the belt edge,
  its widest point at ``section_width / 2`` minus the sidewall cover
  (:func:`natural_constants`; the radius of the widest point follows), so the inflation
  stresses it as a membrane;
* the tread surface drops by ``shoulder_drop`` (parabola) over the outer ``shoulder_width`` of
  the crown, a rounded shoulder (the tread stack thins there);
* the thickness changes from the crown's to the sidewall's over the first sidewall element
  (the shoulder), where the sidewall stacks' materials apply.

Stations run from the left bead (``y < 0``) over the crown to the right bead; the bead stations
are clamped to the rim.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .mesh import Ply, SectionMesh, structured_mesh
from .spec import CrossSectionSpec


@dataclass(frozen=True, eq=False)
class Meridian:
    """Reference line at the node stations: points, unit outward normals, stack thicknesses.

    Arrays over stations (2E + 1), left bead to right bead. ``crown`` marks the stations of the
    crown (between the belt edges, inclusive); ``widest_radius`` is the radius of the widest
    point of the natural shape and ``natural_r0`` its ``r_0`` (m): the membrane tension is
    ``N r = p (r_0^2 - r_w^2) / 2``.
    """

    r: np.ndarray
    y: np.ndarray
    normal_r: np.ndarray
    normal_y: np.ndarray
    inner: np.ndarray
    outer: np.ndarray
    crown: np.ndarray
    widest_radius: float = 0.0
    natural_r0: float = 0.0


def _drop(r_w: float, r0_sq: float, r_end: float, samples: int = 4001) -> tuple[np.ndarray, np.ndarray]:
    """Radii from ``r_w`` to ``r_end`` and the axial drop of the natural shape there (m)."""
    from scipy.integrate import cumulative_trapezoid

    # r = r_w + (r_end - r_w) (1 - cos u) keeps the grid fine near both ends
    grid = r_w + (r_end - r_w) * (1 - np.cos(np.linspace(0, np.pi / 2, samples)))
    sin_b = (grid**2 - r_w**2) / (r0_sq - r_w**2)
    tan_b = sin_b / np.sqrt(np.maximum(1 - sin_b**2, 1e-14))
    return grid, -cumulative_trapezoid(np.abs(tan_b), np.abs(grid - r_w), initial=0.0)


@functools.lru_cache(maxsize=256)
def natural_constants(y_w: float, bead: tuple[float, float], edge: tuple[float, float]) -> tuple[float, float]:
    """Widest radius ``r_w`` and ``r_0^2`` of the one natural shape through the bead and the belt edge.

    A radial carcass carries no hoop force, so its meridional tension is :math:`N = C/r` and
    axial equilibrium of the part between ``r_w`` and ``r`` gives the tangent's angle to the
    radial direction, :math:`\\sin\\beta = (r^2 - r_w^2)/(r_0^2 - r_w^2)` (the "natural shape"
    of Purdy 1963; Clark 1981, ch. 8), one constant from the bead to the belt edge. Given the
    widest point's axial position ``y_w``, the two ends fix ``r_w`` and ``r_0``.

    Memoised on its five numbers (0.2 s of root finding each): a tire's section is meshed again for
    every design, load case and solid mesh built from the same construction.
    """
    from scipy.optimize import brentq

    (r_b, y_b), (r_e, y_e) = bead, edge

    def r0_for(r_w: float) -> float:
        low = (2 * r_w**2 - r_b**2) * (1 + 1e-9)  # |sin beta| = 1 at the bead: the widest possible bulge
        return brentq(lambda v: _drop(r_w, v, r_b)[1][-1] - (y_b - y_w), low, 1e3 * r_w**2)

    def edge_miss(r_w: float) -> float:
        try:
            r0_sq = r0_for(r_w)
        except ValueError:  # the lower branch cannot bulge out to the widest point: too close to the bead
            return -1.0
        if r0_sq <= r_e**2:  # the upper branch turns axial before the belt edge
            return -1.0
        return _drop(r_w, r0_sq, r_e)[1][-1] - (y_e - y_w)

    candidates = np.linspace(r_b, r_e, 42)[1:-1]
    misses = np.array([edge_miss(r) for r in candidates])
    change = np.nonzero(np.diff(np.sign(misses)) > 0)[0]
    if change.size == 0:
        raise ValueError(
            "no natural carcass shape joins the bead and the belt edge at this section width: check [geometry] "
            "section_width, bead_radius, bead_width, tread_width and the stack thicknesses"
        )
    r_w = brentq(edge_miss, candidates[change[0]], candidates[change[0] + 1])
    return r_w, r0_for(r_w)


def natural_shape(r_w: float, y_w: float, r0_sq: float, r_end: float, n: int) -> tuple[np.ndarray, ...]:
    """``n + 1`` points of the natural shape from the widest point to ``r_end``, equally spaced along the arc.

    Returns ``r, y`` and the unit tangents pointing away from the widest point ``t_r, t_y``.
    """
    grid, drop = _drop(r_w, r0_sq, r_end)
    y = y_w + drop
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(grid), np.diff(y)))])
    s = np.linspace(0, arc[-1], n + 1)
    r_s, y_s = np.interp(s, arc, grid), np.interp(s, arc, y)
    sin_b = np.clip((r_s**2 - r_w**2) / (r0_sq - r_w**2), -1, 1)
    cos_b = np.sqrt(1 - sin_b**2)
    sign = 1.0 if r_end > r_w else -1.0
    return r_s, y_s, sign * cos_b, -np.abs(sin_b)


def meridian(spec: CrossSectionSpec) -> Meridian:
    """The reference line of a tire at its node stations (see the module notes)."""
    g, m = spec.geometry, spec.mesh
    t_tread, t_cover = spec.thickness("tread"), spec.thickness("sidewall_cover")
    t_crown, t_side = spec.thickness("crown"), spec.thickness("sidewall")
    centre = g.outer_radius - g.crown_radius
    rho = g.crown_radius - t_tread
    phi_edge = np.arcsin(0.5 * g.tread_width / g.crown_radius)
    # right half: crown (centre -> edge), sidewall (edge -> widest -> bead), stations 2 per element
    n_c = m.crown_elements  # whole crown; each half has n_c stations (2 n_c / 2)
    phi = np.linspace(0.0, phi_edge, n_c + 1)
    crown_r, crown_y = centre + rho * np.cos(phi), rho * np.sin(phi)
    crown_nr, crown_ny = np.cos(phi), np.sin(phi)
    edge = (crown_r[-1], crown_y[-1])
    y_w = 0.5 * g.section_width - t_cover
    bead = (g.bead_radius, 0.5 * g.bead_width)
    r_w, r0_sq = natural_constants(y_w, bead, edge)
    n_s = 2 * m.sidewall_elements
    upper_len = np.hypot(edge[0] - r_w, edge[1] - y_w)
    lower_len = np.hypot(r_w - bead[0], y_w - bead[1])
    n_up = min(max(2, 2 * round(0.5 * n_s * upper_len / (upper_len + lower_len))), n_s - 2)
    ur, uy, utr, uty = natural_shape(r_w, y_w, r0_sq, edge[0], n_up)
    lr, ly, ltr, lty = natural_shape(r_w, y_w, r0_sq, bead[0], n_s - n_up)
    # stations from the belt edge (excluded: it is the crown's last) over the widest point to the bead
    side_r = np.concatenate([ur[::-1][1:], lr[1:]])
    side_y = np.concatenate([uy[::-1][1:], ly[1:]])
    tr = np.concatenate([-utr[::-1][1:], ltr[1:]])
    ty = np.concatenate([-uty[::-1][1:], lty[1:]])
    norm = np.hypot(tr, ty)
    # outward normal: the tangent (moving towards the bead) turned towards +y / +r
    side_nr, side_ny = ty / norm, -tr / norm
    half_r = np.concatenate([crown_r, side_r])
    half_y = np.concatenate([crown_y, side_y])
    half_nr = np.concatenate([crown_nr, side_nr])
    half_ny = np.concatenate([crown_ny, side_ny])
    n_crown = crown_r.size
    inner = np.concatenate([np.full(n_crown, t_crown), np.full(side_r.size, t_side)])
    outer = np.concatenate([np.full(n_crown, t_tread), np.full(side_r.size, t_cover)])
    # rounded shoulder: the tread surface drops (parabola) over the outer shoulder_width of the crown
    into = np.clip((np.abs(crown_y) - (crown_y[-1] - g.shoulder_width)) / g.shoulder_width, 0.0, 1.0)
    outer[:n_crown] -= g.shoulder_drop * into**2
    t_edge_tread = outer[n_crown - 1]
    # shoulder: blend the thickness over the first sidewall element (two stations)
    for k, w in ((n_crown, 0.5), (n_crown + 1, 1.0)):
        inner[k] = (1 - w) * t_crown + w * t_side
        outer[k] = (1 - w) * t_edge_tread + w * t_cover
    crown = np.arange(half_r.size) < n_crown

    def mirror(a, sign):
        return np.concatenate([sign * a[:0:-1], a])

    return Meridian(
        r=mirror(half_r, 1)[:],
        y=mirror(half_y, -1),
        normal_r=mirror(half_nr, 1),
        normal_y=mirror(half_ny, -1),
        inner=mirror(inner, 1),
        outer=mirror(outer, 1),
        crown=mirror(crown, 1).astype(bool),
        widest_radius=float(r_w),
        natural_r0=float(np.sqrt(r0_sq)),
    )


def _plies(spec: CrossSectionSpec, region: str, thickness: float) -> list[Ply]:
    """Plies of a stack as fractions of an element ``thickness`` (the stack scaled to fit)."""
    stack = spec.stack(region)
    total = sum(layer.thickness for _, layer in stack)
    return [
        Ply(
            name=name,
            fraction=layer.thickness / total,
            stiffness=layer.stiffness(),
            density=getattr(layer, "effective_density", layer.density),
            compound=layer.compound,
        )
        for name, layer in stack
    ]


def section_mesh(spec: CrossSectionSpec) -> tuple[SectionMesh, Meridian]:
    """The layered mesh of a tire's cross-section and its reference line."""
    line = meridian(spec)
    fractions = np.array([-1.0, -0.5, 0.0, 0.5, 1.0])
    depth = np.where(
        fractions[None, :] < 0, fractions[None, :] * line.inner[:, None], fractions[None, :] * line.outer[:, None]
    )
    node_r = line.r[:, None] + depth * line.normal_r[:, None]
    node_y = line.y[:, None] + depth * line.normal_y[:, None]
    n_el = (line.r.size - 1) // 2
    stacks = []
    for e in range(n_el):
        in_crown = bool(line.crown[2 * e] and line.crown[2 * e + 2])
        regions = ("crown", "tread") if in_crown else ("sidewall", "sidewall_cover")
        stacks.append([_plies(spec, regions[0], 1.0), _plies(spec, regions[1], 1.0)])
    return structured_mesh(node_r, node_y, stacks), line
