"""What the loaded FE tire's chapter shows: its mesh, its load steps, what the loaded state changes.

The loaded FE tire (``[tire] model = "loaded-fe"``, :mod:`roadnoise_utils.tire.loaded`) is the
paper's own kind of FE tire ("The FET Model": mounting, inflation and vertical loading by nonlinear
statics, the dynamics linearised about that loaded state). Beside it, any other tire model through
the interface: the same load on the same road, the same numbers.

=============================  ==================================================================
function                       what it gives
=============================  ==================================================================
:func:`mesh_summary`           the solid mesh's size (DOF, elements, arcs) and its footprint grading
:func:`newton_steps`           each load step's Newton iterations, contact-set updates and order
:func:`load_curves`            deflection, tangent K_v and footprint size against load, per model
:func:`round_stiffness`        the K_v with the geometric nonlinearity switched off (the round tire)
:func:`cleat_sampling`         the quasi-static cleat peak with three ways of sampling the cleat
:func:`modal_variants`         the paper's modal reduction (Fig. 4) three ways, against the direct FRFs
=============================  ==================================================================
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from ..analysis import band_errors
from ..repro.stages import Tire
from ..response.modal_reduction import ModalReduction
from ..tire.loaded import stages
from ..tire.loaded.model import LoadedFEModel
from ..tire.loaded.statics import StaticState
from ..tire.model import TireModel, tire_model
from .cleat import point_sampled_peak, quasi_static_peak

#: Relative out-of-balance force below which a Newton iteration is at round-off (its order is not measured
#: there): the production mesh's converged states end at 2e-13 to 3e-12.
ROUND_OFF = 1e-11


def loaded_model(tire: Tire) -> LoadedFEModel:
    """``tire`` as the loaded FE tire's model; any other model is refused naming the one it is."""
    model = tire_model(tire)
    if not isinstance(model, LoadedFEModel):
        raise ValueError(f"tire = {tire!r}: a {model.kind!r} tire; this needs a {LoadedFEModel.kind!r} tire file")
    return model


def mesh_summary(tire: Tire) -> pd.Series:
    """The solid mesh of a loaded FE tire: its size and its grading around the wheel (mm where a length)."""
    model = loaded_model(tire)
    built = stages.built_tire(model.spec)
    mesh = built.mesh
    ends = np.append(mesh.theta[::2], mesh.theta[0] + 2.0 * np.pi)
    arcs = np.diff(ends) * model.spec.construction.geometry.outer_radius
    return pd.Series(
        {
            "degrees of freedom": built.n_dof,
            "free degrees of freedom (beads held on the rim)": built.n_dof - built.fixed.size,
            "nodes": mesh.n_nodes,
            "27-node solid elements": mesh.elements.shape[0],
            "section elements (swept)": mesh.section.elements.shape[0],
            "arcs around the wheel": mesh.n_arcs,
            "shortest arc at the tread (mm)": 1e3 * arcs.min(),
            "longest arc at the tread (mm)": 1e3 * arcs.max(),
            "tread nodes across the crown": 2 * model.spec.solid_mesh.crown_elements + 1,
        },
        dtype=object,  # the counts stay integers
    )


def newton_steps(state: StaticState) -> pd.DataFrame:
    """Each load step of a static state (inflation first): its contact sets, the residuals evaluated
    (a Newton solve after each but the last; each contact set's first the state it starts from), the
    relative out-of-balance force of each iteration with the final contact set (the set fixed), and
    their convergence order.

    The order is :math:`\\log(r_{k+1}/r_k) / \\log(r_k/r_{k-1})` of the last three relative residuals
    above round-off (:data:`ROUND_OFF`): 2 for Newton's quadratic convergence with a consistent
    tangent, 1 for a linear one; NaN where fewer than three lie above round-off.
    """
    rows = []
    for step, sets in enumerate(state.history):
        final = np.asarray(sets[-1], dtype=float)
        above = final[final > ROUND_OFF]
        order = np.nan
        if above.size >= 3:
            r0, r1, r2 = above[-3:]
            order = np.log(r2 / r1) / np.log(r1 / r0)
        rows.append(
            {
                "step": "inflation" if step == 0 else f"road step {step}",
                "contact sets": len(sets),
                "residuals evaluated": sum(len(s) for s in sets),
                "last residual": float(final[-1]),
                "residuals, contact set fixed": " ".join(f"{r:.0e}" for r in final),
                "order of the last iterations": order,
            }
        )
    return pd.DataFrame(rows).set_index("step")


def load_curves(tires: Mapping[str, Tire], loads: Sequence[float]) -> pd.DataFrame:
    """Deflection, tangent K_v and footprint size on the flat road at each of ``loads`` (N), per model.

    Each model's :meth:`~roadnoise_utils.tire.model.TireModel.load_curve`: the loaded FE tire's one
    loading through the loads, any other model's cached static solve at each load. One row per model and load:
    ``model``, ``load (kN)``, ``deflection (mm)``, ``K_v (N/mm)``, ``footprint length (mm)``,
    ``footprint width (mm)``, ``peak pressure (kPa)``.
    """
    loads = tuple(sorted(loads))
    rows = []
    for label, tire in tires.items():
        for f in tire_model(tire).load_curve(loads):
            rows.append(
                {
                    "model": label,
                    "load (kN)": f.load / 1e3,
                    "deflection (mm)": 1e3 * f.deflection,
                    "K_v (N/mm)": f.vertical_stiffness / 1e3,
                    "footprint length (mm)": 1e3 * f.footprint_length,
                    "footprint width (mm)": 1e3 * f.footprint_width,
                    "peak pressure (kPa)": f.node_pressure.max() / 1e3,
                }
            )
    return pd.DataFrame(rows)


def round_stiffness(tire: Tire, load: float | None = None) -> float:
    """The loaded FE tire's K_v (N/m) at ``load`` (N; default its file's) with the geometric nonlinearity
    switched off: linearised about the round tire under its linear inflation, as the waveguide tire
    is, the flat road's contact solved on that linear tire (:func:`.tire.loaded.stages.round_stiffness`,
    cached)."""
    model = loaded_model(tire)
    return stages.round_stiffness(model.spec, model.default_load if load is None else load)


def cleat_sampling(tire: TireModel | Tire, height: float, base: float, drum_radius: float) -> pd.Series:
    """The quasi-static cleat peak :math:`\\max_X \\sum_i H_i(0)\\,u_i(X)` (N) on the drum, the cleat
    (``height``, ``base``: m, a triangle) sampled three ways: averaged over each contact node's shape
    function (the RM chain's input, :func:`.cleat.quasi_static_peak`), at the contact nodes (an FE
    model's nodal road) and at the tassello centres (:func:`.cleat.point_sampled_peak`). Any tire
    model with FRFs at 0 Hz."""
    model = tire_model(tire)
    case = model.case("drum", None, drum_radius)
    static = model.load(case)
    h0 = model.fixed_hub_frfs(case, np.array([0.0])).H[:, 0].real
    return pd.Series(
        {
            "averaged over the nodes' shape functions": quasi_static_peak(model, height, base, "triangle", drum_radius),
            "at the contact nodes": point_sampled_peak(static, h0, height, base, at="nodes"),
            "at the tassello centres": point_sampled_peak(static, h0, height, base, at="centres"),
        }
    )


#: The modal reduction's variants the chapter compares: (frozen moduli, damping) by label.
MODAL_VARIANTS = {
    "complex moduli, the model's own loss": ("complex", "model"),
    "complex moduli, identified damping": ("complex", "identified"),
    "paper: storage moduli, identified damping": ("storage", "identified"),
}


def modal_variants(tire: Tire) -> tuple[dict[str, ModalReduction], pd.DataFrame]:
    """The paper's modal reduction of ``tire`` on the flat road at its load, each of :data:`MODAL_VARIANTS`
    (cached stages), and a table per variant: the relative RMS error of its :math:`H_{tot}` against the
    direct one at 0-100 and 150-250 Hz (Fig. 5's bands), its phase at the direct :math:`H_{tot}`'s
    largest peak below 150 Hz (deg; the direct one's on its own row) and the loss factor of its first
    mode seen in :math:`H_{tot}` (the lowest whose hub gain passes 1e-3 of the largest: the mode the
    identified damping goes to, :func:`~roadnoise_utils.response.modal_reduction.apply_identified_damping`)."""
    model = tire_model(tire)
    case = model.case("flat")
    direct = model.fixed_hub_frfs(case)
    low = direct.freqs <= 150.0
    peak = int(np.argmax(np.abs(direct.H_tot[low])))
    reductions = {
        label: model.modal_reduction(case, frozen=frozen, damping=damping)
        for label, (frozen, damping) in MODAL_VARIANTS.items()
    }
    rows = {"direct": {"phase at the peak (deg)": float(np.degrees(np.angle(direct.H_tot[peak])))}}
    for label, reduction in reductions.items():
        errors = band_errors(direct.freqs, direct.H_tot, reduction.frf.H_tot, ((0.0, 100.0), (150.0, 250.0)))
        gain = np.abs(reduction.model.hub_gain)
        seen = int(np.flatnonzero(gain > 1e-3 * gain.max())[0])
        rows[label] = {
            "error 0-100 Hz": errors["complex rel. RMS"].iloc[0],
            "error 150-250 Hz": errors["complex rel. RMS"].iloc[1],
            "phase at the peak (deg)": float(np.degrees(np.angle(reduction.frf.H_tot[peak]))),
            "loss factor of its first mode seen": float(reduction.model.loss_factor[seen]),
        }
    table = pd.DataFrame(rows).T
    table.attrs["peak (Hz)"] = float(direct.freqs[low][peak])
    return reductions, table
