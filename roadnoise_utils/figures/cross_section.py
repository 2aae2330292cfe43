"""Figures of notebook 09, the cross-section FE tire: layers, 3-D view, loaded shape, dispersion."""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.collections import PolyCollection
from matplotlib.ticker import MaxNLocator

from .common import MM

if TYPE_CHECKING:
    from ..tire.cross_section.static import SectionStaticState, SectionTire

#: Colours of the construction layers (unknown names cycle through the tab10 map).
LAYER_COLOURS = {
    "liner": "#8c8c8c",
    "carcass": "#e6a23c",
    "belt_1": "#4a6fa5",
    "belt_2": "#2c4a7a",
    "cap": "#7fb3d5",
    "undertread": "#5d5d5d",
    "tread": "#222222",
    "sidewall": "#a0522d",
}


def _ply_polygons(tire: SectionTire) -> tuple[list[np.ndarray], list[str]]:
    """One polygon per ply of every element, in (y, r) mm, and its layer name."""
    from ..tire.cross_section.waveguide import lagrange3

    mesh = tire.mesh
    pts = mesh.points
    polygons, names = [], []
    xi = np.linspace(-1, 1, 7)
    for e, nodes in enumerate(mesh.elements):
        sel = pts.element == e
        layer_ids = pts.layer[sel]
        etas = pts.eta[sel]
        for layer in np.unique(layer_ids):
            eta = etas[layer_ids == layer]
            span = eta.max() - eta.min()
            # three Gauss points per ply span 77.5 % of it: recover the ply's edges
            centre, half = 0.5 * (eta.max() + eta.min()), 0.5 * span / np.sqrt(0.6)
            edges = (centre - half, centre + half)
            ring = [(x, edges[0]) for x in xi] + [(x, edges[1]) for x in xi[::-1]]
            n_xi, _ = lagrange3(np.array([p[0] for p in ring]))
            n_eta, _ = lagrange3(np.array([p[1] for p in ring]))
            shape = (n_xi[:, None, :] * n_eta[None, :, :]).reshape(9, -1)
            r = mesh.r[nodes] @ shape
            y = mesh.y[nodes] @ shape
            polygons.append(np.column_stack([y * MM, r * MM]))
            names.append(pts.layers[layer])
    return polygons, names


def plot_cross_section(tire: SectionTire, ax: plt.Axes | None = None, mesh_lines: bool = True) -> plt.Axes:
    """The cross-section with its layers (colour) and its 9-node elements (lines)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 5.5))
    polygons, names = _ply_polygons(tire)
    fallback = plt.get_cmap("tab10")
    colours = [LAYER_COLOURS.get(n, fallback(hash(n) % 10)) for n in names]
    ax.add_collection(PolyCollection(polygons, facecolors=colours, edgecolors="none"))
    mesh = tire.mesh
    if mesh_lines:
        for nodes in mesh.elements:
            corners = nodes[[0, 6, 8, 2, 0]]
            ax.plot(mesh.y[corners] * MM, mesh.r[corners] * MM, color="w", lw=0.3)
    for name in dict.fromkeys(names):
        ax.plot([], [], "s", color=LAYER_COLOURS.get(name, fallback(hash(name) % 10)), label=name)
    g = tire.spec.geometry
    ax.axhline(g.rim_radius * MM, color="0.5", ls="--", lw=0.8)
    ax.text(0, g.rim_radius * MM + 2, "rim (bead seat)", ha="center", fontsize=8, color="0.4")
    bead = mesh.bead_nodes
    ax.plot(mesh.y[bead] * MM, mesh.r[bead] * MM, "k^", ms=4, label="clamped to the rim")
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("y (mm), across")
    ax.set_ylabel("r (mm), from the axle")
    ax.legend(fontsize=7, loc="center", ncol=2)
    return ax


def plot_three_d(tire: SectionTire, state: SectionStaticState | None = None, displacement=None, scale: float = 1.0):
    """A 3-D view: the tread surface and the sidewalls as a surface of revolution, loaded if given.

    ``displacement``: (n_theta, n_nodes, 3) from :func:`roadnoise_utils.tire.cross_section.static.loaded_displacement`
    at ``np.linspace(-pi, pi, n_theta)``, drawn ``scale`` times.
    """
    mesh = tire.mesh
    outer = mesh.node(np.arange(mesh.n_stations), mesh.n_rows - 1)
    n_theta = 73 if displacement is None else displacement.shape[0]
    theta = np.linspace(-np.pi, np.pi, n_theta)
    r = np.broadcast_to(mesh.r[outer], (n_theta, outer.size)).copy()
    y = np.broadcast_to(mesh.y[outer], (n_theta, outer.size)).copy()
    t = np.broadcast_to(theta[:, None], r.shape).copy()
    if displacement is not None:
        u = displacement[:, outer] * scale
        r += u[..., 0]
        y += u[..., 2]
        t += u[..., 1] / np.maximum(r, 1e-9)
    fig = plt.figure(figsize=(7, 6))
    ax = fig.add_subplot(projection="3d")
    x, z = r * np.sin(t), -r * np.cos(t)
    shade = np.abs(np.cos(t))
    ax.plot_surface(x * MM, y * MM, z * MM, facecolors=plt.cm.Greys(0.3 + 0.5 * shade), linewidth=0, shade=False)
    if state is not None:
        ax.plot([-150, 150], [0, 0], [-(tire.spec.geometry.outer_radius - state.deflection) * MM] * 2, "r-", lw=1)
    ax.set_box_aspect((1, 0.4, 1))
    ax.yaxis.set_major_locator(MaxNLocator(3))  # the short axis: three ticks that do not overlap
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_zlabel("z (mm)")
    ax.view_init(elev=12, azim=-60)
    return fig


def plot_loaded_section(tire: SectionTire, displacement: np.ndarray, ax: plt.Axes | None = None, scale: float = 1.0):
    """The cross-section at the centre of the footprint, unloaded (grey) and loaded (black)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 5))
    mesh = tire.mesh
    for row, style in ((0, "-"), (mesh.n_rows - 1, "-")):
        nodes = mesh.node(np.arange(mesh.n_stations), row)
        ax.plot(mesh.y[nodes] * MM, mesh.r[nodes] * MM, style, color="0.7", lw=1)
        u = displacement[nodes] * scale
        ax.plot((mesh.y[nodes] + u[:, 2]) * MM, (mesh.r[nodes] + u[:, 0]) * MM, style, color="k", lw=1.2)
    ax.plot([], [], color="0.7", label="inflated, unloaded")
    ax.plot([], [], color="k", label=f"loaded (x{scale:g})" if scale != 1 else "loaded")
    ax.set_aspect("equal")
    ax.set_xlabel("y (mm)")
    ax.set_ylabel("r (mm), at the bottom of the tire")
    ax.legend(fontsize=8)
    return ax


def plot_dispersion(table: pd.DataFrame, closed_form: pd.Series | None = None, ax: plt.Axes | None = None) -> plt.Axes:
    """Free-tire natural frequency against harmonic n, marked by the crown motion; the ring's closed form."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4.5))
    markers = {"radial": ("o", "tab:blue"), "tangential": ("s", "tab:green"), "lateral": ("^", "tab:orange")}
    data = table.reset_index()
    for kind, (marker, colour) in markers.items():
        sel = data["crown motion"] == kind
        ax.plot(
            data["n"][sel],
            data["frequency (Hz)"][sel],
            marker,
            color=colour,
            ls="none",
            label=f"{kind} (cross-section)",
        )
    if closed_form is not None:
        ax.plot(closed_form.index, closed_form.to_numpy(), "k--", lw=1, label="ring model, closed form (notebook 01)")
    ax.set_xlabel("circumferential harmonic n")
    ax.set_ylabel("frequency (Hz)")
    ax.legend(fontsize=8)
    return ax
