"""Figures of the collection, each mirroring a figure of the paper (paper units at this edge only)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib import patheffects
from matplotlib.collections import LineCollection
from matplotlib.patches import Circle, Rectangle

from .fet import UX, UZ, FETModel
from .frf import FRFResult
from .modes import LoadedModes
from .static import StaticState

if TYPE_CHECKING:
    from .cleat import CleatRun

MM = 1e3  # m -> mm


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


def plot_fet_mesh(fet: FETModel, spoke_every: int = 6) -> plt.Figure:
    """Fig. 3 analogue: the FET mesh, side view (rim, foundation springs, belt, tread) and 3D belt."""
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
    ax.legend(loc="upper right", fontsize=7)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    for j in range(mesh.n_strips):
        ax3.plot(x[j] * MM, np.full(mesh.n_elements, mesh.y[j]) * MM, z[j] * MM, lw=0.6, color="k")
    for i in range(0, mesh.n_elements, 4):
        ax3.plot(x[:, i] * MM, mesh.y * MM, z[:, i] * MM, lw=0.4, color="0.5")
    ax3.set_box_aspect((1, 0.45, 1))
    ax3.set_xlabel("x (mm)")
    ax3.set_ylabel("y (mm)")
    ax3.set_zlabel("z (mm)")
    ax3.set_title(f"belt: {mesh.n_strips} strips x {mesh.n_elements} elements, {fet.n_dof} DOF")
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


def plot_footprint(static: StaticState, ax: plt.Axes | None = None, numbers: str = "all") -> plt.Axes:
    """Fig. 2 analogue: contact pressure map with tassello outlines, centres (white dots) and numbers.

    ``numbers``: ``"all"``, ``"some"`` (every 5th, as the paper's partial numbering) or ``"none"``.
    """
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    t = static.tasselli
    p = static.pressure[t.node_strip, t.node_index]
    vmax = p.max() / 1e6
    for xs, ys, dxm, dxp, pv in zip(t.node_x, t.node_y, t.node_dx_minus, t.node_dx_plus, p):
        ax.add_patch(
            Rectangle(
                ((xs - 0.5 * dxm) * MM, (ys - 0.5 * t.strip_width) * MM),
                0.5 * (dxm + dxp) * MM,
                t.strip_width * MM,
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
    return ax


def plot_htot(
    frf: FRFResult,
    peaks: np.ndarray | None = None,
    f_max: float = 300.0,
    ax: plt.Axes | None = None,
    label: str = "H_tot, FETvisco",
) -> plt.Axes:
    """Modulus of the whole-footprint-to-hub FRF in N/mm (paper Fig. 5 axes)."""
    if ax is None:
        _, ax = plt.subplots()
    keep = frf.freqs <= f_max
    ax.plot(frf.freqs[keep], np.abs(frf.H_tot[keep]) / 1e3, label=label)
    if peaks is not None:
        for f in peaks[peaks <= f_max]:
            ax.axvline(f, color="0.6", lw=0.7, ls=":")
    ax.set_xlim(0, f_max)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|H| (N/mm)")
    ax.legend()
    return ax


def plot_compounds(laws: dict, f_max: float = 400.0) -> plt.Figure:
    """Storage-modulus ratio and loss factor of each rubber compound vs frequency."""
    f = np.linspace(0.5, f_max, 400)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.6))
    for name, law in laws.items():
        a1.plot(f, law.storage(2 * np.pi * f), label=name)
        a2.plot(f, law.loss_factor(2 * np.pi * f), label=name)
    a1.set_ylabel("E'(f) / E_0")
    a2.set_ylabel("loss factor tan δ")
    for a in (a1, a2):
        a.set_xlabel("Frequency (Hz)")
        a.legend()
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
    return ax


def plot_rm_pipeline() -> plt.Figure:
    """Fig. 1 analogue: the RM pipeline, stage by stage, with the notebook of each stage."""
    stages = [
        ("FET model\nstatic: footprint, tasselli", "01", "Fig. 2-3"),
        ("FETvisco: H_tot\nsuperposition, damping", "02", "Fig. 4-5"),
        ("FET70Hz modal reduction\nlocal FRFs H_i", "02", "Fig. 5"),
        ("system identification\n8 poles / 8 zeros each", "03", "Fig. 6, Eq. 1"),
        ("state space\n(A_F, B_F, C_F, D_F)", "03", "Eq. 2-4"),
        ("cleat on drum\nfixed hub", "04", "Fig. 8-9"),
        ("moving hub\nF_M = F_F + F_H", "05", "Eq. 5-7, Fig. 7"),
        ("road textures\nthrough the footprint", "06", "weights"),
        ("quarter car\nhub accelerations", "07", "Eq. 8, Fig. 10-14"),
    ]
    fig, ax = plt.subplots(figsize=(12, 3.6))
    ax.set_xlim(0, len(stages))
    ax.set_ylim(0, 1)
    ax.axis("off")
    for i, (text, nb, figs) in enumerate(stages):
        colour = "tab:blue" if nb in ("01", "02", "03") else ("tab:orange" if nb in ("04",) else "tab:green")
        ax.add_patch(Rectangle((i + 0.06, 0.35), 0.88, 0.45, fc=colour, alpha=0.18, ec=colour))
        ax.text(i + 0.5, 0.575, text, ha="center", va="center", fontsize=7.5)
        ax.text(i + 0.5, 0.25, f"notebook {nb}\n{figs}", ha="center", va="center", fontsize=7, color="0.3")
        if i < len(stages) - 1:
            ax.annotate("", (i + 1.06, 0.575), (i + 0.94, 0.575), arrowprops={"arrowstyle": "->", "color": "0.3"})
    ax.text(1.5, 0.93, "frequency domain: FE tire → local transfer functions", ha="center", color="tab:blue")
    ax.text(6.5, 0.93, "time domain: n parallel systems driven by the road", ha="center", color="tab:green")
    fig.suptitle("Fig. 1 analogue: scheme of the RoadNoise (RM) model and where each stage lives")
    return fig


def plot_modal_procedure() -> plt.Figure:
    """Fig. 4 analogue: the procedure for the local FRFs via modal reduction."""
    boxes = {
        "visco": (0.6, 0.82, "FETvisco\nK(ω) = K_el + Σ g_c(ω) K_c"),
        "htot": (0.6, 0.5, "H_tot(ω): whole footprint → hub\n(direct solve, 0-250 Hz)"),
        "ident": (0.6, 0.18, "1. global damping identification\nω_r, η_r of the vertical modes"),
        "frozen": (2.2, 0.82, "2. moduli frozen at the most\nrelevant vertical mode (FET80Hz)"),
        "modes": (2.2, 0.5, "eigenmodes of the symmetric\nclass, up to 2 x band"),
        "local": (3.8, 0.5, "3. local FRFs H_i(ω), every tassello\n+ quasi-static residual correction"),
        "check": (3.8, 0.18, "check (Fig. 5): Σ_i H_i vs H_tot"),
    }
    arrows = [
        ((0.6, 0.74), (0.6, 0.58)),
        ((0.6, 0.42), (0.6, 0.26)),
        ((1.25, 0.82), (1.6, 0.82)),
        ((2.2, 0.74), (2.2, 0.58)),
        ((2.75, 0.5), (3.1, 0.5)),
        ((1.25, 0.2), (3.15, 0.44)),
        ((3.8, 0.42), (3.8, 0.26)),
    ]
    fig, ax = plt.subplots(figsize=(11, 4))
    ax.set_xlim(-0.2, 4.6)
    ax.set_ylim(0.02, 0.98)
    ax.axis("off")
    for x, y, text in boxes.values():
        ax.text(
            x,
            y,
            text,
            ha="center",
            va="center",
            fontsize=8.5,
            bbox={"boxstyle": "round", "fc": "tab:blue", "alpha": 0.15, "ec": "tab:blue"},
        )
    for start, end in arrows:
        ax.annotate("", end, start, arrowprops={"arrowstyle": "->", "color": "0.4"})
    fig.suptitle("Fig. 4 analogue: computation of the local FRFs via modal reduction")
    return fig


def plot_superposition(
    visco: FRFResult, modal: dict[str, FRFResult], f_max: float = 300.0, ax: plt.Axes | None = None
) -> plt.Axes:
    """Fig. 5 analogue: |H_tot| of the viscoelastic model vs |Σ H_i| of modal models (N/mm)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4.5))
    keep = visco.freqs <= f_max
    ax.plot(visco.freqs[keep], np.abs(visco.H_tot[keep]) / 1e3, "k", lw=1.6, label="H_tot, FETvisco (SISO, direct)")
    for (label, frf), style in zip(modal.items(), ["--", ":", "-."]):
        k = frf.freqs <= f_max
        ax.plot(frf.freqs[k], np.abs(frf.H_sum[k]) / 1e3, style, lw=1.4, label=f"Σ H_i, {label} (MIMO)")
    ax.set_xlim(0, f_max)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|H| (N/mm)")
    ax.legend()
    return ax


def plot_identification(visco: FRFResult, ident, f_max: float = 300.0) -> plt.Figure:
    """H_tot of the viscoelastic model and the identified modal model: modulus and phase."""
    f = visco.freqs[visco.freqs <= f_max]
    data = visco.H_tot[visco.freqs <= f_max]
    fit = ident.evaluate(f)
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    a1.semilogy(f, np.abs(data) / 1e3, "k", label="H_tot, FETvisco")
    a1.semilogy(f, np.abs(fit) / 1e3, "--", color="tab:red", label="identified modal model (0-250 Hz)")
    for fr in ident.freqs:
        a1.axvline(fr, color="0.7", lw=0.7, ls=":")
    a2.plot(f, np.degrees(np.angle(data)), "k")
    a2.plot(f, np.degrees(np.angle(fit)), "--", color="tab:red")
    a1.axvspan(ident.band[1], f_max, color="0.9")
    a1.set_ylabel("|H_tot| (N/mm)")
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend()
    fig.suptitle("Global damping identification from H_tot (grey: outside the fitted band)")
    return fig


def plot_tassello_frf(
    static: StaticState, frfs: dict[str, FRFResult], tassello: int, f_max: float = 300.0
) -> plt.Figure:
    """|H_i| and phase of one tassello (number from 1) from several models, with its position."""
    i = tassello - 1
    fig = plt.figure(figsize=(11, 4.2))
    a1 = fig.add_subplot(2, 3, (1, 2))
    a2 = fig.add_subplot(2, 3, (4, 5), sharex=a1)
    a3 = fig.add_subplot(1, 3, 3)
    for (label, frf), style in zip(frfs.items(), ["k-", "--", ":"]):
        k = frf.freqs <= f_max
        a1.plot(frf.freqs[k], np.abs(frf.H[i, k]) / 1e3, style, label=label)
        a2.plot(frf.freqs[k], np.degrees(np.angle(frf.H[i, k])), style)
    a1.set_ylabel("|H_i| (N/mm)")
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend(fontsize=7)
    t = static.tasselli
    for j, (x0, x1, y0, y1) in enumerate(t.bounds):
        a3.add_patch(
            Rectangle((x0 * MM, y0 * MM), (x1 - x0) * MM, (y1 - y0) * MM, fc="tab:red" if j == i else "0.85", ec="w")
        )
    a3.set_xlim(t.bounds[:, 0].min() * MM - 5, t.bounds[:, 1].max() * MM + 5)
    a3.set_ylim(t.bounds[:, 2].min() * MM - 5, t.bounds[:, 3].max() * MM + 5)
    a3.set_aspect("equal")
    a3.set_title(f"tassello {tassello}")
    a3.set_xlabel("x (mm) →")
    fig.suptitle(f"Local FRF of tassello {tassello}: hub force per unit displacement")
    return fig


def plot_tassello_map(
    static: StaticState,
    values: np.ndarray,
    label: str,
    ax: plt.Axes | None = None,
    cmap: str = "RdBu_r",
    symmetric: bool = True,
) -> plt.Axes:
    """A value per tassello drawn on the footprint (e.g. the static influence H_i(0))."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    t = static.tasselli
    vmax = np.max(np.abs(values))
    norm = plt.Normalize(-vmax if symmetric else np.min(values), vmax)
    cm = plt.get_cmap(cmap)
    for (x0, x1, y0, y1), v in zip(t.bounds, values):
        ax.add_patch(Rectangle((x0 * MM, y0 * MM), (x1 - x0) * MM, (y1 - y0) * MM, fc=cm(norm(v)), ec="w", lw=0.6))
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cm), ax=ax, label=label, shrink=0.8)
    ax.set_xlim(t.bounds[:, 0].min() * MM - 5, t.bounds[:, 1].max() * MM + 5)
    ax.set_ylim(t.bounds[:, 2].min() * MM - 5, t.bounds[:, 3].max() * MM + 5)
    ax.set_aspect("equal")
    ax.grid(False)
    ax.set_xlabel("x (mm), direction of travel →")
    ax.set_ylabel("y (mm)")
    return ax


def plot_hub_frf(frfs: dict[str, FRFResult], f_max: float = 300.0, ax: plt.Axes | None = None) -> plt.Axes:
    """|G_H| (hub force per unit hub displacement, footprint held) in N/mm."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for (label, frf), style in zip(frfs.items(), ["k-", "--", ":"]):
        k = frf.freqs <= f_max
        ax.plot(frf.freqs[k], np.abs(frf.G_H[k]) / 1e3, style, label=label)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel("|G_H| (N/mm)")
    ax.set_xlim(0, f_max)
    ax.legend()
    return ax


def plot_order_scan(scans: dict[str, pd.DataFrame], tolerance: float = 0.01, ax: plt.Axes | None = None) -> plt.Axes:
    """Largest and median fit error vs model order, for one or more data sets."""
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 4))
    for (label, scan), colour in zip(scans.items(), ["tab:blue", "tab:orange", "tab:green"]):
        ax.semilogy(scan.index, scan["max rms error"], "o-", color=colour, label=f"{label}: worst tassello")
        ax.semilogy(scan.index, scan["median rms error"], "s--", color=colour, mfc="none", label=f"{label}: median")
    ax.axhline(tolerance, color="k", lw=0.8, ls=":", label=f"{tolerance:.0%} target")
    ax.axvline(8, color="0.6", lw=0.8, label="paper: 8 poles / 8 zeros")
    ax.set_xlabel("poles (= zeros) per tassello")
    ax.set_ylabel("relative RMS error, 0-250 Hz")
    ax.legend(fontsize=7)
    return ax


def plot_fit(freqs: np.ndarray, target: np.ndarray, fitted: np.ndarray, title: str) -> plt.Figure:
    """Fig. 6 analogue: target (FEA) and identified FRF, modulus (N/m) and phase."""
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    a1.plot(freqs, np.abs(target), "k", lw=2.0, label="target (FEA)")
    a1.plot(freqs, np.abs(fitted), "--", color="tab:red", label="identified")
    a2.plot(freqs, np.degrees(np.angle(target)), "k", lw=2.0)
    a2.plot(freqs, np.degrees(np.angle(fitted)), "--", color="tab:red")
    a1.set_ylabel("|H_i| (N/m)")
    a1.ticklabel_format(axis="y", style="sci", scilimits=(4, 4))
    a2.set_ylabel("phase (deg)")
    a2.set_xlabel("Frequency (Hz)")
    a1.legend()
    fig.suptitle(title)
    return fig


def plot_cleat_runs(runs: dict[str, CleatRun], ax: plt.Axes | None = None, title: str = "") -> plt.Axes:
    """Fig. 8/9 analogue: hub force vs distance travelled, several runs, peaks marked."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 4.5))
    for (label, run), style in zip(runs.items(), ["--", "-", ":", "-."]):
        r = run.result
        ax.plot(r.distance, r.force, style, lw=1.4, label=label)
        ax.plot(run.peaks["distance (m)"], run.peaks["force (N)"], "o", ms=4, color=ax.lines[-1].get_color())
    ax.axhline(0, color="0.5", lw=0.6)
    ax.set_xlabel("distance travelled (m); 0 = cleat leading edge under the axle")
    ax.set_ylabel("hub force (N)")
    ax.set_title(title)
    ax.legend()
    return ax


def plot_tassello_inputs(road, static: StaticState, rows: list[int], ax: plt.Axes | None = None) -> plt.Axes:
    """Displacement histories of the centre-column tassello of some rows (the road flowing through)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 3.5))
    t = static.tasselli
    centre_column = int(np.median(t.column))
    for r in rows:
        i = np.nonzero((t.row == r) & (t.column == centre_column))[0]
        if i.size:
            ax.plot(road.distance, road.u[i[0]] * MM, label=f"tassello {i[0] + 1} (row {r + 1})")
    ax.set_xlabel("distance travelled (m)")
    ax.set_ylabel("tassello displacement (mm)")
    ax.legend(fontsize=7)
    return ax


def plot_row_inputs(roads: dict, static: StaticState, row: int = 0, samples: int = 1000) -> plt.Figure:
    """Displacement histories of every tassello of one row, one panel per road (``title -> RoadInput``).

    On a 2D road every column of the row sees the same track (the curves differ only by the
    tasselli's positions along the road); on a 3D road each column has its own.
    """
    members = np.nonzero(static.tasselli.row == row)[0]
    fig, axes = plt.subplots(1, len(roads), figsize=(6 * len(roads), 3.5), sharey=True, squeeze=False)
    for ax, (title, road) in zip(axes[0], roads.items(), strict=True):
        for i in members:
            ax.plot(road.t[:samples] * 1e3, road.u[i, :samples] * MM, lw=0.8)
        ax.set_title(f"{title} (row {row + 1})")
        ax.set_xlabel("time (ms)")
    axes[0, 0].set_ylabel("tassello displacement (mm)")
    return fig


def plot_row_influence(rows: pd.DataFrame, static: StaticState, base: float, ax: plt.Axes | None = None) -> plt.Axes:
    """Static influence of each row along the footprint, with the cleat drawn at the two peak positions."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 3.8))
    ax.bar(
        rows["x centre (mm)"],
        rows["H(0) of the row (N/mm)"],
        width=0.9 * rows["length (mm)"],
        color="tab:blue",
        alpha=0.7,
        label="H(0) of each row of tasselli",
    )
    ax.set_xlabel("x along the footprint (mm); the cleat enters on the left")
    ax.set_ylabel("static influence (N/mm)")
    ax.invert_xaxis()
    ax.legend()
    return ax


def plot_moving_hub_scheme() -> plt.Figure:
    """Fig. 7 analogue: the force on the moving hub as fixed-hub road force plus hub-motion force."""
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.2))
    titles = [
        "moving hub, road input\nF_M",
        "fixed hub, road input\nF_F = Σ_i G_i u_i",
        "moving hub, no road input\nF_H = G_H u_H",
    ]
    for ax, title, hub_moves, road_moves in zip(axes, titles, [True, False, True], [True, True, False]):
        ax.set_xlim(-1.3, 1.3)
        ax.set_ylim(-1.45, 1.3)
        ax.set_aspect("equal")
        ax.axis("off")
        ax.add_patch(Circle((0, 0.1), 1.0, fill=False, lw=2))
        ax.add_patch(Circle((0, 0.1), 0.35, fc="0.8", ec="k"))
        ax.plot([-1.2, 1.2], [-0.92, -0.92], color="tab:brown", lw=3)
        if hub_moves:
            ax.annotate("", (0, 0.75), (0, 0.1), arrowprops={"arrowstyle": "<->", "color": "tab:red", "lw": 1.5})
            ax.text(0.12, 0.55, "u_H", color="tab:red")
        else:
            ax.plot([-0.2, 0.2], [0.1, 0.1], "k", lw=4)
            ax.text(0.1, 0.25, "fixed", fontsize=8)
        if road_moves:
            for x in (-0.4, 0.0, 0.4):
                ax.annotate("", (x, -0.65), (x, -1.25), arrowprops={"arrowstyle": "->", "color": "tab:blue"})
            ax.text(0.5, -1.35, "u_i", color="tab:blue")
        ax.set_title(title, fontsize=9)
    fig.text(0.355, 0.5, "=", fontsize=22, ha="center")
    fig.text(0.68, 0.5, "+", fontsize=22, ha="center")
    fig.suptitle("Fig. 7 analogue: computation of the force on the moving hub, F_M = F_F + F_H (Eq. 5)")
    return fig


def plot_frf_pair(
    freqs: np.ndarray, curves: dict[str, np.ndarray], ylabel: str, ax: plt.Axes | None = None, log: bool = True
) -> plt.Axes:
    """Moduli of a few complex FRFs on one axis (first curve bold: the reference)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for k, (label, values) in enumerate(curves.items()):
        style = {"color": "k", "lw": 2.2} if k == 0 else {"ls": "--", "lw": 1.3}
        (ax.semilogy if log else ax.plot)(freqs, np.abs(values), label=label, **style)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel(ylabel)
    ax.legend()
    return ax


def plot_road_spectra(
    spectra: dict,
    n: np.ndarray,
    iso_classes: dict[str, float],
    ax: plt.Axes | None = None,
    measured: dict | None = None,
) -> plt.Axes:
    """Road displacement PSDs (m^3) vs wavenumber with the ISO 8608 class boundaries."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4.5))
    for name, g0 in iso_classes.items():
        ax.loglog(n, g0 * (n / 0.1) ** -2.0, color="0.8", lw=0.8)
        ax.text(n[0] * 1.05, g0 * (n[0] / 0.1) ** -2.0, name, fontsize=7, color="0.5", va="bottom")
    for (name, spectrum), colour in zip(spectra.items(), ["tab:red", "tab:blue", "tab:green"]):
        ax.loglog(n, spectrum.psd(n), lw=2, color=colour, label=f"{name} (target)")
        if measured and name in measured:
            nm, gm = measured[name]
            ax.loglog(nm[1:], gm[1:], lw=0.8, color=colour, alpha=0.7, label=f"{name} (generated, Welch)")
    ax.axvline(1 / 0.05, color="k", ls=":", lw=0.8)
    ax.text(1 / 0.05, ax.get_ylim()[1], " 5 cm", va="top", fontsize=8)
    ax.set_xlabel("wavenumber n (cycles/m)")
    ax.set_ylabel("displacement PSD G(n) (m^3)")
    ax.legend(fontsize=7)
    return ax


def plot_transmissibility(
    freqs: np.ndarray, transmissibility: np.ndarray, bands: dict, ax: plt.Axes | None = None
) -> plt.Axes:
    """Fig. 10 analogue: |a_mount / a_hub| with the paper's bands (``vehicle.FrequencyBand``) shaded."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    ax.plot(freqs, np.abs(transmissibility), "k", lw=1.8, label="quarter car (ours)")
    for band, colour in zip(bands.values(), ["tab:blue", "tab:green", "tab:orange", "tab:purple"], strict=False):
        ax.axvspan(band.f_low, band.f_high, color=colour, alpha=0.12)
        ax.text(0.5 * (band.f_low + band.f_high), 1.9, band.label, ha="center", fontsize=8, color=colour)
    ax.axhline(1.0, color="0.5", lw=0.7, ls=":")
    ax.set_ylim(0, 2.1)
    ax.set_xlim(0, 300)
    ax.set_xlabel("Frequency [Hz]")
    ax.set_ylabel("|a_upper mount / a_hub|")
    ax.legend(loc="upper left")
    return ax


def plot_spectra(
    freqs: np.ndarray,
    curves: dict[str, np.ndarray],
    ylabel: str,
    f_range: tuple[float, float],
    ax: plt.Axes | None = None,
    log: bool = False,
    predicted: dict[str, tuple] | None = None,
) -> plt.Axes:
    """Amplitude spectral densities (sqrt of PSD) of a few signals, optionally with predictions."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for (label, psd), colour in zip(curves.items(), ["tab:red", "tab:blue", "tab:green"]):
        keep = (freqs >= f_range[0]) & (freqs <= f_range[1])
        (ax.semilogy if log else ax.plot)(freqs[keep], np.sqrt(psd[keep]), color=colour, lw=1.2, label=label)
        if predicted and label in predicted:
            fp, pp = predicted[label]
            k = (fp >= f_range[0]) & (fp <= f_range[1])
            (ax.semilogy if log else ax.plot)(fp[k], np.sqrt(pp[k]), "k--", lw=0.8)
    ax.set_xlim(*f_range)
    ax.set_xlabel("Frequency (Hz)")
    ax.set_ylabel(ylabel)
    ax.legend()
    return ax


def plot_kernel_filter(
    wavelengths: np.ndarray, gains: np.ndarray, labels: list[str], ax: plt.Axes | None = None
) -> plt.Axes:
    """|K_i(1/λ)|: how much of a sinusoidal road of wavelength λ reaches each tassello."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4))
    for g, label in zip(gains, labels):
        ax.semilogx(wavelengths * 100, np.abs(g), label=label)
    ax.axvline(5.0, color="k", ls=":", lw=0.8)
    ax.text(5.0, 1.02, " 5 cm", fontsize=8)
    ax.set_xlabel("road wavelength λ (cm)")
    ax.set_ylabel("|tassello input / road amplitude|")
    ax.set_ylim(0, 1.1)
    ax.legend(fontsize=7)
    return ax


def plot_tracks(profile, length: float, ax: plt.Axes | None = None) -> plt.Axes:
    """The first ``length`` m of a 3D road: one track per belt strip, as an image."""
    if ax is None:
        _, ax = plt.subplots(figsize=(10, 2.6))
    keep = profile.s <= length
    im = ax.pcolormesh(profile.s[keep], profile.y * MM, profile.z[:, keep] * MM, shading="nearest", cmap="terrain")
    plt.colorbar(im, ax=ax, label="height (mm)")
    ax.set_xlabel("road coordinate s (m)")
    ax.set_ylabel("track y (mm)")
    ax.grid(False)
    return ax


def plot_quarter_car_scheme(vehicle) -> plt.Figure:
    """Fig. 13 analogue: the corner's masses and elements, with the RM tire under the hub."""
    names = ["body", "tower", "rod", "unsprung"]
    names = [n for n in names if n in vehicle.masses] + [n for n in vehicle.masses if n not in names]
    y = {name: 4.0 - 1.2 * k for k, name in enumerate(names)}
    x = {name: (0.6 if name == "rod" else 0.0) for name in names}
    fig, ax = plt.subplots(figsize=(6.5, 6))
    for name in names:
        ax.add_patch(Rectangle((x[name] - 0.45, y[name] - 0.25), 0.9, 0.5, fc="tab:blue", alpha=0.2, ec="tab:blue"))
        ax.text(x[name], y[name], f"{name}\n{vehicle.masses[name]:g} kg", ha="center", va="center", fontsize=8)
    ground_y = y[vehicle.hub] - 2.2
    ax.add_patch(Rectangle((-0.6, y[vehicle.hub] - 1.55), 1.2, 0.7, fc="0.3", alpha=0.25, ec="k"))
    ax.text(0, y[vehicle.hub] - 1.2, "RM tire: F_M = F_F + G_H u_H\n(Eq. 5-7)", ha="center", va="center", fontsize=8)
    ax.plot([-1.2, 1.2], [ground_y, ground_y], color="tab:brown", lw=3)
    ax.text(0, ground_y - 0.25, "road irregularities → tasselli", ha="center", fontsize=8, color="tab:brown")
    ax.annotate("", (0, ground_y + 0.05), (0, y[vehicle.hub] - 1.55), arrowprops={"arrowstyle": "-", "ls": ":"})
    for k, e in enumerate(vehicle.elements):
        ya, yb = y.get(e.a, ground_y), y.get(e.b, ground_y)
        xm = -0.65 - 0.42 * (len(vehicle.elements) - 1 - k)
        ax.plot(
            [xm, xm],
            [min(ya, yb) + 0.25, max(ya, yb) - 0.25],
            color="k",
            lw=1.0,
            ls={"spring": "-", "damper": "--", "maxwell": "-."}[e.kind],
        )
        value = (
            f"{e.stiffness / 1e3:g} N/mm"
            if e.kind == "spring"
            else f"{e.damping:g} Ns/m"
            if e.kind == "damper"
            else f"{e.damping:g} Ns/m + {e.stiffness / 1e3:g} N/mm"
        )
        ax.text(
            xm,
            max(ya, yb) - 0.2,
            f"{e.a[:5]}-{e.b[:5]}\n{e.kind}\n{value}",
            fontsize=5.5,
            ha="center",
            va="bottom",
            rotation=90,
        )
    ax.set_xlim(-0.9 - 0.42 * len(vehicle.elements), 1.6)
    ax.set_ylim(ground_y - 0.5, 4.5)
    ax.axis("off")
    fig.suptitle("Fig. 13 analogue: the quarter car (front corner, MacPherson strut)")
    return fig
