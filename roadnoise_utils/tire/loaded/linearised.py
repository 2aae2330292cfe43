"""The loaded tire linearised about a static state: the tread's contact compliance and the flat road on it.

Switching the geometric nonlinearity off means linearising about the inflated state: the tangent
:math:`K_t` there (material stiffness, the inflation pre-stress's geometric stiffness and the
pressure's load stiffness, :func:`.statics.residual_and_tangent`) stays the tire's stiffness
however far the road presses. Condensed on the tread nodes near the road, its inverse is the
vertical compliance the waveguide tire gives for its contact grid, and the same frictionless
one-sided contact (:func:`roadnoise_utils.tire.active_set.active_set`) solves the flat road on
both. The nonlinear loaded state (:func:`.road_contact.press_on_road`) differs from this one by
the loading's geometric nonlinearity alone, and tends to it as the road's lift tends to zero.

The waveguide tire linearises once more: about the round, unstressed tire, with the stress of its
linear inflation (:func:`round_linearisation`, :func:`.solid.prestressed_tangent`). Linearised so,
the solids differ from it only by their discretisations, which is how they are checked against
it: on the same section they have its frequencies and its K_v. The exact tangent at the
inflated state differs from it by what that initial-stress linearisation leaves out (on the
165/65 R14 at 2.3 bar: the inflation's largest displacement 0.76 mm against the linear 0.96 mm,
the n = 0 and 1 modes 3 % lower). It is the waveguide's equivalent, not the consistent tangent
about any inflated state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ... import guards
from ..active_set import active_set, held_contact
from ..symmetric_factor import SymmetricFactor
from . import pressure, solid
from .road_contact import tread_heights
from .statics import LoadedTire, StaticState, residual_and_tangent

#: Default depth (m) of the band of tread nodes above the lowest that may touch the road.
CONTACT_DEPTH = 0.05


@dataclass(frozen=True)
class ContactCompliance:
    """Vertical compliance of the tread nodes that may touch a flat road, about a static state.

    Attributes
    ----------
    nodes : ndarray of int
        The candidate tread nodes.
    gap : ndarray
        Height (m) of each above the lowest tread node at the state.
    matrix : ndarray (n, n)
        Vertical displacement of each node per unit upward force on each (m/N), rim held.
    depth : float
        The candidates are every free tread node less than ``depth`` (m) above the lowest.
    """

    nodes: np.ndarray
    gap: np.ndarray
    matrix: np.ndarray
    depth: float

    def columns(self, index: np.ndarray) -> np.ndarray:
        """The compliance's columns ``index`` (the callable :func:`~roadnoise_utils.tire.active_set.active_set` takes)."""
        return self.matrix[:, index]


@dataclass(frozen=True)
class LinearisedContact:
    """The flat road on the tire linearised about a static state.

    Attributes
    ----------
    forces : ndarray
        Upward force of the road on each candidate node (N).
    deflection : float
        How far the road rose from touching the lowest tread node (m).
    stiffness : float
        Tangent vertical stiffness with the contact set held (N/m).
    contact : ndarray of int
        The tread nodes the road pushes.
    """

    forces: np.ndarray
    deflection: float
    stiffness: float
    contact: np.ndarray

    @property
    def load(self) -> float:
        """Vertical force of the road on the tire (N)."""
        return float(self.forces.sum())


@dataclass(frozen=True)
class RoundLinearisation:
    """The solids linearised as the waveguide tire: about the round tire, pre-stressed by its linear inflation.

    Attributes
    ----------
    state : StaticState
        The round tire at the pressure (no displacement): the geometry the road's gaps are taken on.
    inflation : ndarray (n_dof,)
        Displacement of the linear inflation (m).
    tangent : scipy.sparse.csr_matrix
        Small-strain stiffness, the geometric stiffness of the inflation's stress and the pressure's
        load stiffness on the round tire (N/m).
    """

    state: StaticState
    inflation: np.ndarray
    tangent: sp.csr_matrix


def round_linearisation(tire: LoadedTire, p: float | None = None) -> RoundLinearisation:
    """:class:`RoundLinearisation` at pressure ``p`` (Pa; default the tire file's)."""
    p = tire.spec.operating.inflation_pressure if p is None else guards.real("p", p, 0.0, lo_open=True, unit="Pa")
    round_tire = np.zeros(tire.n_dof)
    stiffness = solid.prestressed_tangent(tire.groups, round_tire, tire.n_dof)
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    inflation = np.zeros(tire.n_dof)
    load = pressure.pressure_load(tire.mesh, tire.surface, round_tire, p)
    inflation[free] = SymmetricFactor(stiffness[free][:, free]).solve(load[free])
    tangent = solid.prestressed_tangent(tire.groups, inflation, tire.n_dof) - pressure.pressure_stiffness(
        tire.mesh, tire.surface, round_tire, p
    )
    return RoundLinearisation(StaticState(u=round_tire, pressure=p), inflation, tangent.tocsr())


def contact_compliance(
    tire: LoadedTire, state: StaticState, depth: float = CONTACT_DEPTH, tangent: sp.spmatrix | None = None
) -> ContactCompliance:
    """The tread's vertical compliance about ``state`` (the rim held, every other node free), see :class:`ContactCompliance`.

    ``tangent``: the stiffness to invert (N/m); default the exact tangent at ``state``. One symmetric
    factor and one solve per candidate node.
    """
    depth = guards.real("depth", depth, 0.0, 0.5, lo_open=True, unit="m")
    heights = tread_heights(tire, state.u)
    vertical = 3 * tire.tread + 2
    candidate = (heights < heights.min() + depth) & ~np.isin(vertical, tire.fixed)
    nodes = tire.tread[candidate]
    free = np.setdiff1d(np.arange(tire.n_dof), tire.fixed)
    guards.check_memory(8.0 * free.size * nodes.size, f"the compliance of {nodes.size} tread nodes", "depth")
    k = residual_and_tangent(tire, state.u, state.pressure)[1] if tangent is None else sp.csr_matrix(tangent)
    rows = np.searchsorted(free, 3 * nodes + 2)
    unit = np.zeros((free.size, nodes.size))
    unit[rows, np.arange(nodes.size)] = 1.0
    matrix = SymmetricFactor(k[free][:, free]).solve(unit)[rows]
    return ContactCompliance(
        nodes=nodes, gap=heights[candidate] - heights.min(), matrix=0.5 * (matrix + matrix.T), depth=depth
    )


def flat_road_at_load(compliance: ContactCompliance, load: float) -> LinearisedContact:
    """The flat road pressed on the linearised tire until it carries ``load`` (N): the waveguide tire's contact solve."""
    load = guards.real("load", load, 0.0, lo_open=True, unit="N")
    forces, deflection, stiffness, _ = active_set(
        compliance.columns, compliance.gap, np.zeros(compliance.gap.size), load
    )
    return _checked(compliance, forces, deflection, stiffness)


def flat_road_at_lift(compliance: ContactCompliance, lift: float) -> LinearisedContact:
    """The flat road raised ``lift`` (m) from touching the lowest tread node, on the linearised tire."""
    lift = guards.real("lift", lift, 0.0, lo_open=True, unit="m")
    penetration = lift - compliance.gap
    forces, active, _ = held_contact(compliance.columns, penetration, penetration > 0.0, np.zeros(penetration.size))
    stiffness = float(np.linalg.solve(compliance.matrix[np.ix_(active, active)], np.ones(active.sum())).sum())
    return _checked(compliance, forces, lift, stiffness)


def _checked(
    compliance: ContactCompliance, forces: np.ndarray, deflection: float, stiffness: float
) -> LinearisedContact:
    """Refuse a contact that could reach tread nodes beyond the candidates' depth."""
    if deflection > 0.5 * compliance.depth:
        raise ValueError(
            f"the road rose {deflection * 1e3:.1f} mm, more than half the contact depth of "
            f"{compliance.depth * 1e3:.0f} mm: give a larger depth to contact_compliance"
        )
    return LinearisedContact(
        forces=forces, deflection=float(deflection), stiffness=float(stiffness), contact=compliance.nodes[forces > 0.0]
    )
