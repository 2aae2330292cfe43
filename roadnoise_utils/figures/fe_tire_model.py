"""Figures of notebook 01-fe-tire-model: the FET mesh (Fig. 3), loaded shapes, footprint (Fig. 2), modes, ring check, H_tot, compounds, load-deflection."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib import patheffects
from matplotlib.collections import LineCollection
from matplotlib.patches import Circle, Rectangle
from matplotlib.ticker import MaxNLocator

from ..tire.model import Footprint, FRFResult
from ..tire.ring.mechanics import UX, UZ, FETModel
from ..tire.ring.modes import LoadedModes
from ..tire.ring.static import StaticState
from .common import MM, paper_lines


def _strip_xz(fet: FETModel, u: np.ndarray | None, strip: int, scale: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Closed polyline of one belt strip, optionally displaced by ``scale * u``."""
    mesh = fet.mesh
    x, z = mesh.belt_xz()
    x, z = x[strip].copy(), z[strip].copy()
    if u is not None:
        k = np.arange(mesh.n_elements)
        x += scale * u[mesh.dof(strip, k, UX)]
        z += scale * u[mesh.dof(strip, k, UZ)]
    return np.append(x, x[0]), np.append(z, z[0])


def plot_fet_mesh(fet: FETModel, spoke_every: int = 6, paper_dof: float | None = None) -> plt.Figure:
    """Fig. 3 analogue: the FET mesh, side view (rim, foundation springs, belt, tread) and 3D belt.

    ``paper_dof``: the size of the paper's FE model, shown beside ours.
    """
    mesh = fet.mesh
    g = fet.spec.geometry
    fig = plt.figure(figsize=(11, 4.8))
    ax = fig.add_subplot(1, 2, 1)
    x, z = mesh.belt_xz()
    tx, tz = mesh.tread_xz()
    centre = mesh.n_strips // 2
    k = np.arange(0, mesh.n_elements, spoke_every)
    rim = g.rim_radius
    spokes = [[(rim * np.sin(t), -rim * np.cos(t)), (x[centre, i], z[centre, i])] for i, t in zip(k, mesh.theta[k])]
    ax.add_collection(LineCollection(np.array(spokes) * MM, colors="0.6", lw=0.6, label="sidewall/air foundation"))
    ax.add_patch(Circle((0, 0), rim * MM, fill=True, fc="0.85", ec="0.3", label="rigid rim"))
    xs, zs = _strip_xz(fet, None, centre)
    ax.plot(xs * MM, zs * MM, "k-", lw=1.2, label=f"belt ring ({mesh.n_elements} frame elements)")
    ax.plot(tx[centre] * MM, tz[centre] * MM, ".", color="tab:brown", ms=1.5, label="tread surface")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title("side view (centre strip)")
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.14), fontsize=7, ncol=2)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    for j in range(mesh.n_strips):
        ax3.plot(x[j] * MM, np.full(mesh.n_elements, mesh.y[j]) * MM, z[j] * MM, lw=0.6, color="k")
    for i in range(0, mesh.n_elements, 4):
        ax3.plot(x[:, i] * MM, mesh.y * MM, z[:, i] * MM, lw=0.4, color="0.5")
    ax3.set_box_aspect((1, 0.45, 1))
    ax3.yaxis.set_major_locator(MaxNLocator(3))
    ax3.set_xlabel("x (mm)")
    ax3.set_ylabel("y (mm)")
    ax3.set_zlabel("z (mm)")
    paper = f" (paper: ~{paper_dof:.0f})" if paper_dof else ""
    ax3.set_title(f"belt: {mesh.n_strips} strips x {mesh.n_elements} elements, {fet.n_dof} DOF{paper}")
    fig.suptitle(f"Fig. 3 analogue: the FET model of the {fet.spec.name}")
    return fig


def plot_loaded_shape(fet: FETModel, states: dict[str, StaticState], zoom: float = 0.16) -> plt.Figure:
    """The loaded shape of the centre strip on each road, undeformed and deformed (true scale)."""
    mesh = fet.mesh
    centre = mesh.n_strips // 2
    fig, axes = plt.subplots(1, len(states), figsize=(5.5 * len(states), 4.2), squeeze=False)
    for ax, (name, st) in zip(axes[0], states.items()):
        x0, z0 = _strip_xz(fet, None, centre)
        x1, z1 = _strip_xz(fet, st.displacement, centre)
        ax.plot(x0 * MM, z0 * MM, "--", color="0.6", label="inflated, unloaded")
        ax.plot(x1 * MM, z1 * MM, "k-", label="loaded (true scale)")
        xr = np.linspace(-zoom, zoom, 200)
        top = mesh.tread_xz()[1].min() + st.deflection
        ax.plot(xr * MM, (top - st.road.drop(xr)) * MM, color="tab:blue", lw=2, label=f"{name} surface")
        ax.set_xlim(-zoom * MM, zoom * MM)
        ax.set_ylim((top - 0.06) * MM, (top + 0.09) * MM)
        ax.set_aspect("equal")
        ax.set_title(f"{name}: deflection {st.deflection * MM:.1f} mm at {st.load:.0f} N")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("z (mm)")
        ax.legend(loc="upper right", fontsize=7)
    fig.suptitle("Loaded shape of the belt (centre strip)")
    return fig


def plot_footprint(
    static: Footprint, ax: plt.Axes | None = None, numbers: str = "all", vmax: float | None = None
) -> plt.Axes:
    """Fig. 2 analogue: contact pressure map with tassello outlines, centres (white dots) and numbers.

    ``numbers``: ``"all"``, ``"some"`` (every 5th, as the paper's partial numbering) or ``"none"``;
    ``vmax``: top of the colour scale (MPa; default the map's largest pressure), one value for
    maps drawn side by side.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    t = static.tasselli
    p = static.node_pressure
    vmax = p.max() / 1e6 if vmax is None else vmax
    for xs, ys, dxm, dxp, w, pv in zip(t.node_x, t.node_y, t.node_dx_minus, t.node_dx_plus, t.widths, p):
        ax.add_patch(
            Rectangle(
                ((xs - 0.5 * dxm) * MM, (ys - 0.5 * w) * MM),
                0.5 * (dxm + dxp) * MM,
                w * MM,
                color=plt.cm.inferno(pv / 1e6 / vmax),
                lw=0,
            )
        )
    for i, (x0, x1, y0, y1) in enumerate(t.bounds):
        ax.add_patch(Rectangle((x0 * MM, y0 * MM), (x1 - x0) * MM, (y1 - y0) * MM, fill=False, ec="w", lw=0.8))
        show = numbers == "all" or (numbers == "some" and (i % 5 == 0 or i == t.n - 1))
        if show:
            ax.annotate(
                str(i + 1),
                (t.centre_x[i] * MM, t.centre_y[i] * MM),
                xytext=(0, 4),
                textcoords="offset points",
                ha="center",
                fontsize=6,
                color="w",
                path_effects=[patheffects.withStroke(linewidth=1.5, foreground="k")],
            )
    ax.plot(t.centre_x * MM, t.centre_y * MM, "o", ms=2.5, mfc="w", mec="w")
    sm = plt.cm.ScalarMappable(cmap="inferno", norm=plt.Normalize(0, vmax))
    plt.colorbar(sm, ax=ax, label="contact pressure (MPa)", shrink=0.8)
    pad = 10
    ax.set_xlim((t.bounds[:, 0].min()) * MM - pad, (t.bounds[:, 1].max()) * MM + pad)
    ax.set_ylim((t.bounds[:, 2].min()) * MM - pad, (t.bounds[:, 3].max()) * MM + pad)
    ax.set_aspect("equal")
    ax.set_facecolor("0.15")
    ax.grid(False)
    ax.set_xlabel("x (mm), direction of travel →")
    ax.set_ylabel("y (mm)")
    return ax


def plot_modes(fet: FETModel, modes: LoadedModes, indices: list[int], amplitude: float = 0.04) -> plt.Figure:
    """Mode shapes of the loaded tire, centre and edge strips in the wheel plane."""
    mesh = fet.mesh
    n = len(indices)
    cols = min(n, 4)
    rows = int(np.ceil(n / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(3.0 * cols, 3.1 * rows), squeeze=False)
    for ax, r in zip(axes.ravel(), indices):
        shape = modes.shapes[:, r]
        translations = np.concatenate(
            [shape[mesh.dof(j, np.arange(mesh.n_elements), c)] for j in range(mesh.n_strips) for c in (UX, UZ)]
        )
        scale = amplitude / np.max(np.abs(translations))
        x0, z0 = _strip_xz(fet, None, mesh.n_strips // 2)
        ax.plot(x0 * MM, z0 * MM, color="0.75", lw=0.8)
        for strip, style in ((mesh.n_strips // 2, "k-"), (0, "r--")):
            xs, zs = _strip_xz(fet, shape, strip, scale)
            ax.plot(xs * MM, zs * MM, style, lw=1.0)
        ax.set_title(f"{modes.freqs[r]:.1f} Hz\n{modes.label(r)}", fontsize=8)
        ax.set_aspect("equal")
        ax.axis("off")
    for ax in axes.ravel()[n:]:
        ax.axis("off")
    fig.suptitle(
        f"Modes of the loaded tire, hub fixed (moduli at {modes.reference_frequency:.0f} Hz); "
        "black: centre strip, red dashed: edge strip"
    )
    return fig


def plot_mode_chart(modes: LoadedModes, f_max: float = 300.0, ax: plt.Axes | None = None) -> plt.Axes:
    """Natural frequencies by wave number, coloured by symmetry class; vertical modes sized by hub share."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    keep = modes.freqs <= f_max
    colours = {
        "vertical": "tab:red",
        "fore-aft": "tab:blue",
        "lateral S": "tab:green",
        "lateral A": "tab:olive",
        "mixed": "0.5",
    }
    share = np.abs(modes.hub_share) / np.abs(modes.hub_share).max()
    for cls, colour in colours.items():
        idx = [r for r in np.nonzero(keep)[0] if modes.symmetry_class(r) == cls]
        if idx:
            sizes = 20 + 200 * share[idx] if cls == "vertical" else 20
            ax.scatter(
                modes.wave_number[idx] + 0.12 * modes.lateral_order[idx],
                modes.freqs[idx],
                s=sizes,
                color=colour,
                label=cls,
                alpha=0.8,
            )
    ax.set_xlabel("circumferential wave number n (offset by lateral order m)")
    ax.set_ylabel("frequency (Hz)")
    ax.legend(title="symmetry class")
    ax.set_title("Modes of the loaded tire by wave number and symmetry class")
    return ax


def plot_ring_check(table: pd.DataFrame, ax: plt.Axes | None = None) -> plt.Axes:
    """Closed-form vs FE single-ring frequencies."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 4))
    ax.plot(table.index, table["closed_form_Hz"], "o-", mfc="none", label="closed form (inextensible ring)")
    ax.plot(table.index, table["fe_Hz"], "x", ms=8, label="FE ring")
    ax.set_xlabel("circumferential wave number n")
    ax.set_ylabel("natural frequency (Hz)")
    ax.legend()
    ax.set_title("Ring frequencies: closed form against the FE model")
    return ax


def plot_htot(
    frf: FRFResult,
    peaks: np.ndarray | None = None,
    f_max: float = 300.0,
    ax: plt.Axes | None = None,
    label: str = "H_tot, FETvisco",
    paper: dict[str, float] | None = None,
) -> plt.Axes:
    """Modulus of the whole-footprint-to-hub FRF in N/mm (paper Fig. 5 axes).

    ``peaks`` (Hz): marked on the curve and listed in the legend; ``paper``: the paper's
    frequencies (label -> Hz), drawn as reference lines.
    """
    if ax is None:
        _, ax = plt.subplots()
    keep = frf.freqs <= f_max
    ax.plot(frf.freqs[keep], np.abs(frf.H_tot[keep]) / 1e3, label=label)
    if peaks is not None:
        shown = peaks[peaks <= f_max]
        modulus = np.interp(shown, frf.freqs, np.abs(frf.H_tot)) / 1e3
        listed = ", ".join(f"{f:.1f}" for f in shown)
        ax.plot(shown, modulus, "v", color="tab:red", ms=6, label=f"ours: peaks at {listed} Hz")
    ax.set_xlim(0, f_max)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|H| (N/mm)")
    ax.legend()
    if paper:
        paper_lines(ax, paper, axis="x", unit="Hz")
    return ax


def plot_compounds(laws: dict, f_max: float = 400.0) -> plt.Figure:
    """Storage-modulus ratio and loss factor of each rubber compound vs frequency."""
    f = np.linspace(0.5, f_max, 400)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.6))
    for name, law in laws.items():
        a1.plot(f, law.storage(2 * np.pi * f), label=name)
        a2.plot(f, law.loss_factor(2 * np.pi * f), label=name)
    a1.set_ylabel("$E'(f) / E_0$")
    a2.set_ylabel("loss factor tan δ")
    for a in (a1, a2):
        a.set_xlabel("Frequency (Hz)")
    a1.legend()  # the same colours on both panels
    fig.suptitle("Fractional-Zener rubber compounds")
    return fig


def plot_load_deflection(
    loads: np.ndarray, deflections: np.ndarray, static: StaticState, ax: plt.Axes | None = None
) -> plt.Axes:
    """Load vs deflection with the tangent at the nominal load."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 4))
    ax.plot(deflections * MM, loads, "o-", ms=3, label="active-set solutions")
    d = np.linspace(static.deflection - 0.006, static.deflection + 0.006, 2)
    ax.plot(
        d * MM,
        static.load + static.vertical_stiffness * (d - static.deflection),
        "--",
        label=f"tangent {static.vertical_stiffness / 1e3:.0f} N/mm",
    )
    ax.plot(static.deflection * MM, static.load, "ks", label="nominal load")
    ax.set_xlabel("deflection (mm)")
    ax.set_ylabel("vertical load (N)")
    ax.legend()
    ax.set_title("Load against deflection on the flat road, tangent at the nominal load")
    return ax
