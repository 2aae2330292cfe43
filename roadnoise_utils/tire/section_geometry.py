"""The meridian of a cross-section tire file and its layered mesh.

The reference line of the mesh is the outer face of the structure (the belt top at the crown,
the carcass's outer face on the sidewalls). From it, node rows go inward by the structure
stack (``crown`` or ``sidewall``) and outward by the cover stack (``tread`` or
``sidewall_cover``), two 9-node elements through the thickness:

* crown: a circular arc of radius ``crown_radius - tread thickness`` about the tread's centre of
  curvature, so the outer face is the tread surface of transverse radius ``crown_radius``;
* sidewall: the equilibrium ("natural") shape of an inflated radial carcass
  (:func:`natural_shape`), one branch from the widest point (at ``max_width_radius``, outer
  face ``section_width / 2`` minus the sidewall cover) up to the belt edge and one down to
  the bead (``bead_radius``, ``bead_width / 2``), so the inflation stresses it as a membrane;
* the thickness changes from the crown's to the sidewall's over the first sidewall element
  (the shoulder), where the sidewall stacks' materials apply.

Stations run from the left bead (``y < 0``) over the crown to the right bead; the bead stations
are clamped to the rim.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .cross_section import CrossSectionSpec
from .section_mesh import Ply, SectionMesh, structured_mesh


@dataclass(frozen=True, eq=False)
class Meridian:
    """Reference line at the node stations: points, unit outward normals, stack thicknesses.

    Arrays over stations (2E + 1), left bead to right bead. ``crown`` marks the stations of the
    crown (between the belt edges, inclusive).
    """

    r: np.ndarray
    y: np.ndarray
    normal_r: np.ndarray
    normal_y: np.ndarray
    inner: np.ndarray
    outer: np.ndarray
    crown: np.ndarray


def natural_shape(r_w: float, y_w: float, r_end: float, y_end: float, n: int) -> tuple[np.ndarray, ...]:
    """Equilibrium meridian of an inflated radial carcass from its widest point to ``(r_end, y_end)``.

    A radial carcass carries no hoop force, so its meridional tension is :math:`N = C/r` and
    axial equilibrium of the part between ``r_w`` and ``r`` gives the tangent's angle to the
    radial direction, :math:`\\sin\\beta = (r^2 - r_w^2)/(r_0^2 - r_w^2)` (the "natural shape"
    of Purdy 1963; Clark 1981, ch. 8), with ``r_0`` fitted so that the curve reaches
    ``y_end``. Returns ``n + 1`` points equally spaced along the arc (the first the widest
    point) and the unit tangents pointing away from it: ``r, y, t_r, t_y``.
    """
    from scipy.integrate import cumulative_trapezoid
    from scipy.optimize import brentq

    up = r_end > r_w
    # the substitution r = r_w + (r_end - r_w) (1 - cos u) keeps the grid fine near both ends
    grid = r_w + (r_end - r_w) * (1 - np.cos(np.linspace(0, np.pi / 2, 2001)))

    def drop(r0_sq: float) -> np.ndarray:
        sin_b = (grid**2 - r_w**2) / (r0_sq - r_w**2)
        tan_b = sin_b / np.sqrt(np.maximum(1 - sin_b**2, 1e-12))
        return -cumulative_trapezoid(np.abs(tan_b), np.abs(grid - r_w), initial=0.0)

    target = y_end - y_w
    edge = r_end**2 if up else 2 * r_w**2 - r_end**2  # |sin beta| = 1 at r_end: the widest possible bulge
    r0_sq = brentq(lambda v: drop(v)[-1] - target, edge * (1 + 1e-9), 1e3 * r_w**2)
    y = y_w + drop(r0_sq)
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(grid), np.diff(y)))])
    s = np.linspace(0, arc[-1], n + 1)
    r_s, y_s = np.interp(s, arc, grid), np.interp(s, arc, y)
    sin_b = np.clip((r_s**2 - r_w**2) / (r0_sq - r_w**2), -1, 1)
    cos_b = np.sqrt(1 - sin_b**2)
    sign = 1.0 if up else -1.0
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
    widest = (g.max_width_radius, 0.5 * g.section_width - t_cover)
    n_s = 2 * m.sidewall_elements
    upper_len = np.hypot(edge[0] - widest[0], edge[1] - widest[1])
    lower_len = np.hypot(widest[0] - g.bead_radius, widest[1] - 0.5 * g.bead_width)
    n_up = min(max(2, 2 * round(0.5 * n_s * upper_len / (upper_len + lower_len))), n_s - 2)
    ur, uy, utr, uty = natural_shape(*widest, edge[0], edge[1], n_up)
    lr, ly, ltr, lty = natural_shape(*widest, g.bead_radius, 0.5 * g.bead_width, n_s - n_up)
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
    # shoulder: blend the thickness over the first sidewall element (two stations)
    for k, w in ((n_crown, 0.5), (n_crown + 1, 1.0)):
        inner[k] = (1 - w) * t_crown + w * t_side
        outer[k] = (1 - w) * t_tread + w * t_cover
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
