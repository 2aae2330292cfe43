"""The loaded FE tire's own footprint in tasselli, and its FRFs in the form every tire model gives.

The contact nodes of a loaded state (:func:`.statics.press_on_flat_road`) lie on the tread's rings
(one per node row around the circumference) and its columns (the section's tread nodes across
the width). Each node sits where the loading put it on the road: its deformed ``x`` (along the
road) and ``y``; the distance to the neighbouring rings' nodes of its column along ``x``, and half
the distance to its neighbours across, give the tributary strip the road's height is averaged
over (:mod:`roadnoise_utils.tire.tasselli`, the paper's weighting by the elements' shape
functions). Rows of tasselli are bands of the file's ``[tasselli] target_length`` at most, as on
the other models; columns are equal lateral bands of about that width, so the tasselli are about
square (the paper's ~8000-DOF tire: 71 tasselli).
"""

from __future__ import annotations

import numpy as np

from ..model import Footprint, FRFResult, LoadCase
from ..tasselli import Tasselli, tassellate
from .dynamics import LoadedFootprintFRF
from .statics import LoadedTire, StaticState, vertical_stiffness


def contact_grid(tire: LoadedTire, state: StaticState) -> tuple[np.ndarray, np.ndarray]:
    """Ring and column (index among the section's tread nodes) of each contact node of ``state``."""
    tread = tire.tread.reshape(tire.mesh.theta.size, -1)
    where = {int(node): divmod(i, tread.shape[1]) for i, node in enumerate(tread.ravel())}
    missing = [int(node) for node in state.contact if int(node) not in where]
    if missing:
        raise ValueError(f"state: contact nodes {missing[:5]} are not tread nodes of this tire")
    ring, column = np.array([where[int(node)] for node in state.contact]).T.reshape(2, -1)
    return ring, column


def loaded_tasselli(tire: LoadedTire, state: StaticState) -> Tasselli:
    """The contact nodes of ``state`` in tasselli (see the module notes)."""
    if state.contact.size == 0:
        raise ValueError("state: the tire touches no road (give a loaded state: statics.press_on_flat_road)")
    ring, column = contact_grid(tire, state)
    position = tire.mesh.coordinates + state.u.reshape(-1, 3)
    tread = tire.tread.reshape(tire.mesh.theta.size, -1)
    n_rings = tread.shape[0]
    x = position[tread[ring, column], 0]
    ahead = position[tread[(ring + 1) % n_rings, column], 0]
    behind = position[tread[(ring - 1) % n_rings, column], 0]
    dx_plus, dx_minus = np.abs(ahead - x), np.abs(x - behind)
    across = position[tread[ring], 1]  # (P, n_columns): every column's y on the node's ring
    y = across[np.arange(ring.size), column]
    left = np.where(column > 0, across[np.arange(ring.size), np.maximum(column - 1, 0)], np.nan)
    right = np.where(
        column < tread.shape[1] - 1, across[np.arange(ring.size), np.minimum(column + 1, tread.shape[1] - 1)], np.nan
    )
    gaps = np.abs(np.stack([y - left, right - y]))
    width = np.where(np.isnan(gaps), np.nanmax(gaps, axis=0), gaps).sum(axis=0) / 2  # an edge node: its inner gap
    target = tire.spec.tasselli.target_length
    edges = (y - width / 2).min(), (y + width / 2).max()
    n_bands = max(1, int(round((edges[1] - edges[0]) / target)))
    band_width = (edges[1] - edges[0]) / n_bands
    band = np.clip(((y - edges[0]) / band_width).astype(int), 0, n_bands - 1)
    return tassellate(
        node_strip=column,
        node_index=ring,
        node_x=x,
        node_y=y,
        node_dx_minus=dx_minus,
        node_dx_plus=dx_plus,
        strip_width=band_width,
        target_length=target,
        strips_per_column=1,
        node_width=width,
        node_column=band,
    )


def loaded_footprint(tire: LoadedTire, state: StaticState) -> Footprint:
    """The loaded state as every model's :class:`~roadnoise_utils.tire.model.Footprint` on the flat road.

    The deflection is the road's lift from touching the inflated tire; the contact pressure at a
    node is its road reaction over its tributary strip's area (so the pressures times the areas
    sum to the load); ``K_v`` is the condensed tangent's, the contact set held.
    """
    tasselli = loaded_tasselli(tire, state)
    area = 0.5 * (tasselli.node_dx_minus + tasselli.node_dx_plus) * tasselli.widths
    load = state.road_force
    return Footprint(
        road=LoadCase.of("flat", load).road,
        load=load,
        deflection=state.road_lift,
        hub_force=float(-state.reactions[tire.fixed[tire.fixed % 3 == 2]].sum()),
        vertical_stiffness=vertical_stiffness(tire, state),
        tasselli=tasselli,
        node_pressure=state.reactions[3 * state.contact + 2] / area,
    )


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
