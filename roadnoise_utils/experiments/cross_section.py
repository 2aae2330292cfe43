"""Tables of notebook 09, the cross-section FE tire: its construction, free modes, convergence, the two models.

Each function takes tire names (files in ``data/tires``) or specs and returns a pandas table;
the heavy stages come from the cache (:mod:`roadnoise_utils.tire.cross_section.stages`).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..response.modal_reduction import ModalReduction, identify_modes
from ..tire.cross_section import stages as section_stages
from ..tire.cross_section.dynamics import harmonic_modes
from ..tire.cross_section.spec import LAYER_KINDS, CordLayer, CrossSectionSpec
from ..tire.cross_section.static import SectionTire, section_summary
from ..tire.model import FRFResult, tire_model


def layer_table(spec: CrossSectionSpec) -> pd.DataFrame:
    """The construction, layer by layer: kind, thickness, density, in-plane moduli, compound and its loss."""
    rows = []
    omega = 2 * np.pi * 80.0
    for name, layer in spec.layers.items():
        compliance = np.linalg.inv(layer.stiffness())  # layer axes (n, theta, s)
        stacks = [region for region, names in spec.construction.items() if name in names]
        law = spec.compounds[layer.compound].law()
        rows.append(
            {
                "layer": name,
                "kind": next(kind for kind, cls in LAYER_KINDS.items() if isinstance(layer, cls)),
                "stacks": ", ".join(stacks),
                "thickness (mm)": layer.thickness * 1e3,
                "density (kg/m^3)": getattr(layer, "effective_density", layer.density),
                "E circumferential (MPa)": 1e-6 / compliance[1, 1],
                "E meridional (MPa)": 1e-6 / compliance[2, 2],
                "E normal (MPa)": 1e-6 / compliance[0, 0],
                "cord angle (deg)": layer.cord_angle if isinstance(layer, CordLayer) else np.nan,
                "compound": layer.compound,
                "loss factor at 80 Hz": float(law.loss_factor(omega)),
            }
        )
    return pd.DataFrame(rows).set_index("layer")


def free_dispersion(tire: SectionTire, n_max: int = 12, f_max: float = 400.0, per_harmonic: int = 3) -> pd.DataFrame:
    """Free-tire (rim fixed, unloaded) natural frequencies by harmonic: the dispersion of the tire.

    Storage moduli at 80 Hz. Each mode is labelled by where its tread-centre motion points:
    ``radial``, ``tangential`` or ``lateral`` (the largest component at the crown centre node).
    """
    omega = 2 * np.pi * 80.0
    ops, mesh = tire.ops, tire.mesh
    centre = mesh.node(mesh.n_stations // 2, mesh.n_rows - 1)
    free = ops.free
    rows = []
    for n in range(n_max + 1):
        phi = harmonic_modes(ops, n, omega, f_max, max_modes=40)
        k = ops.free_stiffness(n, omega, storage_only=True)
        m = ops.free_mass(n)
        for j in range(min(per_harmonic, phi.shape[1])):
            v = np.zeros(ops.n_dof)
            v[free] = phi[:, j]
            f = float(np.sqrt((phi[:, j] @ (k @ phi[:, j])) / (phi[:, j] @ (m @ phi[:, j]))) / (2 * np.pi))
            kind = ("radial", "tangential", "lateral")[int(np.argmax(np.abs(v[3 * centre : 3 * centre + 3])))]
            rows.append({"n": n, "order": j + 1, "frequency (Hz)": f, "crown motion": kind})
    return pd.DataFrame(rows).set_index(["n", "order"])


def convergence_table(tire: str | CrossSectionSpec, harmonics=(300, 400, 600), crown=(10, 14, 18)) -> pd.DataFrame:
    """Loaded-tire numbers against the number of harmonics and of crown elements."""
    spec = section_stages.load_section_tire(tire)
    cases = [("harmonics", h, {"mesh.harmonics": h}) for h in harmonics]
    cases += [("crown elements", c, {"mesh.crown_elements": c}) for c in crown]
    rows = []
    for what, value, change in cases:
        model = tire_model(spec.replace(**change))
        state = model.load(model.case("flat"))
        s = section_summary(state)
        rows.append(
            {
                "varied": what,
                "value": value,
                "deflection (mm)": s["deflection (mm)"],
                "K_v (N/mm)": s["vertical stiffness, tangent (N/mm)"],
                "footprint length (mm)": s["footprint length (mm)"],
                "footprint width (mm)": s["footprint width (mm)"],
                "peak pressure (MPa)": s["peak contact pressure (MPa)"],
            }
        )
    return pd.DataFrame(rows).set_index(["varied", "value"])


def model_comparison(ring: str = "165_65R14", cross: str = "165_65R14_cross_section") -> pd.DataFrame:
    """The two tire models of one tire side by side: size, statics, first vertical mode."""
    out = {}
    for label, name in (("ring", ring), ("cross-section", cross)):
        model = tire_model(name)
        case = model.case("flat")
        dof, summary, frf = model.degrees_of_freedom(), model.load(case).summary(), model.fixed_hub_frfs(case)
        modes = identify_modes(frf.freqs, frf.H_tot)
        out[label] = {
            "DOF": dof,
            "deflection (mm)": summary["deflection (mm)"],
            "K_v (N/mm)": summary["vertical stiffness, tangent (N/mm)"],
            "footprint length (mm)": summary["footprint length (mm)"],
            "footprint width (mm)": summary["footprint width (mm)"],
            "peak contact pressure (MPa)": summary["peak contact pressure (MPa)"],
            "contact points": summary["contact points"],
            "tasselli": summary["tasselli"],
            "first vertical mode, modal fit (Hz)": float(modes.table()["frequency (Hz)"].iloc[0]),
            "zeta1, modal fit": float(modes.damping[0]),
        }
    return pd.DataFrame(out)


def loaded_modes(reduced: ModalReduction, floor: float = 1e-9) -> pd.DataFrame:
    """The loaded modes of a modal reduction, static shares below ``floor`` (N/mm, round-off) shown as 0.

    The modes the symmetric road cannot drive have hub and road gains that cancel: their static
    share is round-off, whose printed digits would change with the BLAS build.
    """
    modes = reduced.mode_table()
    share = modes["static share (N/mm)"]
    return modes.assign(**{"static share (N/mm)": share.where(share.abs() > floor, 0.0)})


def resonance_phases(direct: FRFResult, variants: dict[str, ModalReduction], f_max: float = 250.0) -> pd.Series:
    """Phase of :math:`H_{tot}` (deg) at its largest resonance below ``f_max`` (Hz): direct and each modal variant.

    The index is ``"direct"`` and each variant's name up to its first ``":"`` or ``" +"``; the
    resonance's frequency (Hz) is in ``attrs["f"]``.
    """
    band = np.asarray(direct.freqs) <= f_max
    k = int(np.argmax(np.abs(direct.H_tot[band])))
    phases = {"direct": np.angle(direct.H_tot[k], deg=True)}
    for name, variant in variants.items():
        phases[name.split(":")[0].split(" +")[0]] = np.angle(variant.frf.H_tot[k], deg=True)
    series = pd.Series(phases, name="phase (deg)")
    series.attrs["f"] = float(direct.freqs[k])
    return series


def tire_mass(tire: SectionTire) -> float:
    """Mass of the meshed tire (kg): the n = 0 mass of a uniform radial motion."""
    ops = tire.ops
    radial = np.zeros(ops.n_dof)
    radial[0::3] = 1.0
    return float(radial @ (ops.mass_matrix(0) @ radial))


def membrane_forces(tire: SectionTire) -> pd.DataFrame:
    """Meridional and hoop forces of the inflation pre-stress at each element station (N/m).

    The stresses at the element's middle integration points (``xi = 0``) of both element layers,
    integrated through the thickness; ``N_s r`` is constant along a radial carcass (membrane).
    """
    mesh, ops, line = tire.mesh, tire.ops, tire.line
    pts = mesh.points
    n_layers = (mesh.n_rows - 1) // 2
    rows = []
    for e in range((mesh.n_stations - 1) // 2):
        station = 2 * e + 1
        s_r, s_y = -line.normal_y[station], line.normal_r[station]  # meridian tangent
        n_s = n_t = 0.0
        for layer in range(n_layers):
            element = e * n_layers + layer
            sel = (pts.element == element) & np.isclose(pts.xi, 0.0)
            thickness_weight = pts.weight[sel] / (8.0 / 9.0) * _thickness_jacobian(mesh, element, pts.eta[sel])
            sig = ops.stress[sel]
            n_s += thickness_weight @ (sig[:, 0] * s_r**2 + sig[:, 2] * s_y**2 + 2 * sig[:, 4] * s_r * s_y)
            n_t += thickness_weight @ sig[:, 1]
        radius = line.r[station]
        rows.append(
            {
                "y (mm)": line.y[station] * 1e3,
                "r (mm)": radius * 1e3,
                "region": "crown" if line.crown[station] else "sidewall",
                "N_s (N/m)": n_s,
                "N_theta (N/m)": n_t,
                "N_s r (N)": n_s * radius,
            }
        )
    table = pd.DataFrame(rows)
    p = ops.pressure_value
    table["N_s r, membrane (N)"] = np.where(
        table["region"] == "sidewall", 0.5 * p * (line.natural_r0**2 - line.widest_radius**2), np.nan
    )
    return table


def _thickness_jacobian(mesh, element: int, eta: np.ndarray) -> np.ndarray:
    """The modulus ``|dx/deta|`` at the middle of the element (m per unit eta)."""
    from ..tire.cross_section.waveguide import lagrange3

    nodes = mesh.elements[element]
    n_xi, _ = lagrange3(np.zeros(eta.size))
    _, d_eta = lagrange3(eta)
    shape = (n_xi[:, None, :] * d_eta[None, :, :]).reshape(9, -1)
    return np.hypot(mesh.r[nodes] @ shape, mesh.y[nodes] @ shape)


def damping_sources(tire: SectionTire, harmonics=(0, 1, 2, 3), frequency: float = 80.0) -> pd.DataFrame:
    """Where the first free-tire modes store their strain energy, and the damping ratio it gives.

    For the first radial-dominated mode of each harmonic (rim fixed, storage moduli at
    ``frequency``): the share of strain energy in each compound's layers and in the pneumatic
    stiffness, and the modal-strain-energy estimate :math:`\\zeta = \\tfrac12\\sum_c \\eta_c E_c/E`
    with the pneumatic stiffness lossless and with the tire file's ``[pneumatic]`` law.
    """
    ops = tire.ops
    omega = 2 * np.pi * frequency
    free = ops.free
    centre = tire.mesh.node(tire.mesh.n_stations // 2, tire.mesh.n_rows - 1)
    rows = []
    for n in harmonics:
        phi = harmonic_modes(ops, n, omega, 400.0)
        for j in range(phi.shape[1]):
            v = np.zeros(ops.n_dof)
            v[free] = phi[:, j]
            if np.argmax(np.abs(v[3 * centre : 3 * centre + 3])) == 0:  # radial at the crown centre
                break
        w = 2 * np.pi if n == 0 else np.pi
        parts = {name: w * float(v @ (ops.layers(name, n) @ v)) for name in ops.elastic}
        parts["pneumatic"] = w * float(v @ (ops.pneumatic(n) @ v))
        storage = {name: float(ops.laws[name].storage(omega)) for name in ops.laws}
        loss = {name: float(ops.laws[name].loss_factor(omega)) for name in ops.laws}
        energy = {name: e * storage[name] for name, e in parts.items() if name in ops.elastic}
        law = ops.pneumatic_law
        energy["pneumatic"] = parts["pneumatic"] * (storage[law] if law else 1.0)
        total = sum(energy.values())
        lossy = sum(energy[name] * loss[name] for name in ops.elastic)
        row = {"n": n, "frequency (Hz)": np.sqrt(total / float(v @ (ops.mass_matrix(n) @ v))) / (2 * np.pi)}
        row.update({f"{name} share": e / total for name, e in energy.items()})
        row["zeta, pneumatic lossless"] = 0.5 * lossy / total
        row[f"zeta, pneumatic with the {law} law" if law else "zeta, file"] = (
            0.5 * (lossy + (energy["pneumatic"] * loss[law] if law else 0.0)) / total
        )
        rows.append(row)
    return pd.DataFrame(rows).set_index("n")
