"""The loaded FE tire's own footprint in tasselli, and its FRFs in the form every tire model gives.

The contact nodes of a loaded state (:func:`.road_contact.press_on_road`) lie on the tread's rings
(one per node row around the circumference) and its columns (the section's tread nodes across
the width). Each node sits where the loading put it on the road: its deformed ``x`` (along the
road) and ``y``; the distance to the neighbouring rings' nodes of its column along ``x``, and half
the distance to its neighbours across, give the tributary strip the road's height is averaged
over (:mod:`roadnoise_utils.tire.tasselli`, the paper's weighting by the elements' shape
functions). Rows of tasselli are bands of the file's ``[tasselli] target_length`` at most, as on
the other models; columns are equal lateral bands no wider, so the tasselli are at most square
(the paper's ~8000-DOF tire: 71 tasselli).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..model import Footprint, FRFResult
from ..tasselli import Tasselli, symmetric_bands, tassellate
from .dynamics import LoadedFootprintFRF
from .road_contact import vertical_stiffness
from .statics import LoadedTire, StaticState


def contact_grid(tire: LoadedTire, state: StaticState) -> tuple[np.ndarray, np.ndarray]:
    """Ring and column (index among the section's tread nodes) of each contact node of ``state``."""
    tread = tire.tread.reshape(tire.mesh.theta.size, -1)
    where = {int(node): divmod(i, tread.shape[1]) for i, node in enumerate(tread.ravel())}
    missing = [int(node) for node in state.contact if int(node) not in where]
    if missing:
        raise ValueError(f"state: contact nodes {missing[:5]} are not tread nodes of this tire")
    ring, column = np.array([where[int(node)] for node in state.contact]).T.reshape(2, -1)
    return ring, column


def loaded_tasselli(tire: LoadedTire, state: StaticState, areas: np.ndarray | None = None) -> Tasselli:
    """The contact nodes of ``state`` in tasselli (see the module notes), each node weighted in its
    tassello by the integral of its shape function over the tread (``areas``, m^2, if computed
    already: :func:`shape_function_areas`)."""
    if state.contact.size == 0:
        raise ValueError("state: the tire touches no road (give a loaded state: road_contact.press_on_road)")
    ring, column = contact_grid(tire, state)
    position = tire.mesh.coordinates + state.u.reshape(-1, 3)
    tread = tire.tread.reshape(tire.mesh.theta.size, -1)
    n_rings = tread.shape[0]
    x = position[tread[ring, column], 0]
    ahead = position[tread[(ring + 1) % n_rings, column], 0]
    behind = position[tread[(ring - 1) % n_rings, column], 0]
    dx_plus, dx_minus = np.abs(ahead - x), np.abs(x - behind)
    across = position[tread[ring], 1]  # (P, n_columns): every column's y on the node's ring
    # a column's nodes run on one road track: its mean lateral position (they lie within ~0.2 mm of it)
    y = (np.bincount(column, weights=across[np.arange(ring.size), column]) / np.maximum(np.bincount(column), 1))[column]
    left = np.where(column > 0, across[np.arange(ring.size), np.maximum(column - 1, 0)], np.nan)
    right = np.where(
        column < tread.shape[1] - 1, across[np.arange(ring.size), np.minimum(column + 1, tread.shape[1] - 1)], np.nan
    )
    gaps = np.abs(np.stack([y - left, right - y]))
    width = np.where(np.isnan(gaps), np.nanmax(gaps, axis=0), gaps).sum(axis=0) / 2  # an edge node: its inner gap
    target = tire.spec.tasselli.target_length
    outer = (y - width / 2).min(), (y + width / 2).max()
    band, n_bands = symmetric_bands(y - outer[0], outer[1] - outer[0], target)
    hats = tassellate(
        node_strip=column,
        node_index=ring,
        node_x=x,
        node_y=y,
        node_dx_minus=dx_minus,
        node_dx_plus=dx_plus,
        strip_width=(outer[1] - outer[0]) / n_bands,
        target_length=target,
        strips_per_column=1,
        node_width=width,
        node_column=band,
    )
    area = shape_function_areas(tire, state) if areas is None else areas
    weight = area / np.bincount(hats.node_tassello, weights=area)[hats.node_tassello]
    return dataclasses.replace(hats, node_weight=weight)


def shape_function_areas(tire: LoadedTire, state: StaticState) -> np.ndarray:
    """The integral over the loaded tread of each contact node's shape function (m^2): a uniform
    pressure's nodal force per unit pressure.

    The tread's faces are quadratic along the circumference and across (corner nodes on the even
    rings and columns), so a corner node takes a sixth of each neighbouring element's length and a
    mid node two thirds of its own, in each direction (Simpson's weights), at the deformed positions.
    """
    ring, column = contact_grid(tire, state)
    position = tire.mesh.coordinates + state.u.reshape(-1, 3)
    tread = tire.tread.reshape(tire.mesh.theta.size, -1)
    n_rings, n_columns = tread.shape

    def along_ring(step: int) -> np.ndarray:
        return np.abs(position[tread[(ring + step) % n_rings, column], 0] - position[tread[ring, column], 0])

    def across(step: int) -> np.ndarray:
        other = np.clip(column + step, 0, n_columns - 1)
        return np.abs(position[tread[ring, other], 1] - position[tread[ring, column], 1])

    length = np.where(ring % 2 == 0, (along_ring(-2) + along_ring(2)) / 6, 2 * (along_ring(-1) + along_ring(1)) / 3)
    width = np.where(column % 2 == 0, (across(-2) + across(2)) / 6, 2 * (across(-1) + across(1)) / 3)
    return length * width


def loaded_footprint(tire: LoadedTire, state: StaticState, load: float | None = None) -> Footprint:
    """The loaded state as every model's :class:`~roadnoise_utils.tire.model.Footprint` on its road.

    The deflection is the road's lift from touching the inflated tire; the contact pressure at a
    node is its road reaction along the road's normal over its shape function's area (the pressure a uniform field would
    give it: no checkerboard of the quadratic faces' 1/6 : 2/3 split); ``K_v`` is the condensed
    tangent's, the contact set held. ``load`` (N): the load case the state was loaded to (its
    ``force_balance`` compares the rim's reaction with it); default the road's force.
    """
    areas = shape_function_areas(tire, state)
    tasselli = loaded_tasselli(tire, state, areas)
    load = state.road_force if load is None else float(load)
    return Footprint(
        road=state.road,
        load=load,
        deflection=state.road_lift,
        hub_force=float(-state.reactions[tire.fixed[tire.fixed % 3 == 2]].sum()),
        vertical_stiffness=vertical_stiffness(tire, state),
        tasselli=tasselli,
        node_pressure=_normal_force(state) / areas,
    )


def _normal_force(state: StaticState) -> np.ndarray:
    """Each contact node's force from the road along the road's normal (N): vertical on the flat road,
    radial on a drum (where a node's force has its normal's small fore-aft part too)."""
    force = state.reactions.reshape(-1, 3)[state.contact]
    return np.sign(force[:, 2]) * np.hypot(force[:, 0], force[:, 2])


def frf_result(frf: LoadedFootprintFRF, tasselli: Tasselli) -> FRFResult:
    """The loaded tire's FRFs as every model's :class:`~roadnoise_utils.tire.model.FRFResult`: ``H`` per
    tassello (the sum of its nodes' transfers: its nodes moving together), ``H_points`` per node."""
    if tasselli.node_x.size != frf.hub.shape[1]:
        raise ValueError(
            f"tasselli hold {tasselli.node_x.size} contact nodes, the FRFs {frf.hub.shape[1]}: give the tasselli "
            "of the state the FRFs were computed about (loaded_tasselli)"
        )
    return FRFResult(
        freqs=frf.freqs,
        H=tasselli.membership() @ frf.hub.T,
        H_tot=frf.H_tot,
        G_H=frf.G_H,
        H_points=frf.hub.T,
        method="loaded FE tire: linearised about its nonlinear loaded state, Craig-Bampton reduced",
    )
