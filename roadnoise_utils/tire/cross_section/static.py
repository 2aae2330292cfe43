"""The cross-section tire loaded on a flat road or a drum: footprint, pressure map, K_v.

The tire is linear about its inflated state (pre-stress and pressure load stiffness included,
:mod:`roadnoise_utils.tire.cross_section.operators`); loading adds one-sided vertical, frictionless contact on the contact
grid (:mod:`roadnoise_utils.tire.cross_section.contact`), solved by the primal active set shared with the ring model
(:func:`.active_set.active_set`). This neglects what a nonlinear FE solve of the loading would
add: the change of the pre-stress and of the geometry with the 20-25 mm deflection (the
sidewalls' bulge), friction in the footprint, the tread's own nonlinearity, the horizontal
motion of the contact points (the gap is measured vertically at their undeformed positions)
and the compression of the cavity's air (the pressure stays constant); the rubber is nearly
incompressible at Poisson 0.49 in displacement elements.

The hub force is computed independently of the contact solve, as the rim's reaction in the
``n = 1`` harmonic (:func:`roadnoise_utils.tire.cross_section.dynamics.rim_transfer`); it equals the load to round-off
once each contact force is taken as the arc-spread load the Green's functions assume (its
vertical resultant is ``sinc(dtheta / 2)`` of the centre value: 5e-6 at 3 mm).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ... import guards
from ..active_set import active_set
from ..model import Footprint, check_load
from ..surface import RoadSurface, make_road
from ..tasselli import Tasselli, tassellate
from .contact import ContactGrid, contact_grid, harmonic_flexibility, vertical_compliance
from .dynamics import rim_transfer
from .geometry import Meridian, section_mesh
from .mesh import SectionMesh
from .operators import HarmonicOperators, harmonic_operators
from .spec import CrossSectionSpec


@dataclass(frozen=True, eq=False)
class SectionTire:
    """A cross-section tire built from its file: mesh, harmonic operators, contact grid."""

    spec: CrossSectionSpec
    mesh: SectionMesh
    line: Meridian
    ops: HarmonicOperators
    grid: ContactGrid

    @property
    def harmonics(self) -> int:
        return self.spec.mesh.harmonics


def build_section_tire(spec: CrossSectionSpec) -> SectionTire:
    """Mesh the cross-section, integrate its harmonic matrices and inflate it."""
    mesh, line = section_mesh(spec)
    ops = harmonic_operators(mesh, spec.laws(), spec.operating.inflation_pressure, pneumatic_law=spec.pneumatic_law)
    grid = contact_grid(mesh, line, spec.mesh.contact_spacing, spec.geometry.outer_radius)
    return SectionTire(spec=spec, mesh=mesh, line=line, ops=ops, grid=grid)


@dataclass(frozen=True, eq=False)
class SectionStaticState(Footprint):
    """The loaded cross-section tire: its :class:`~.model.Footprint` and the contact grid's state.

    Arrays over the contact grid are (n_cols, n_rows): ``contact`` (bool), ``contact_force``
    (vertical, N), ``pressure`` (force over the point's tread area, Pa). ``hub_force`` is the
    vertical force on the fixed rim from the ``n = 1`` reaction (N); ``vertical_stiffness`` the
    tangent dF/d(delta) with the contact set frozen (N/m).
    """

    contact: np.ndarray
    contact_force: np.ndarray
    pressure: np.ndarray
    iterations: int
    grid: ContactGrid = field(repr=False)
    tire: CrossSectionSpec | None = field(default=None, repr=False)

    def force_balance(self) -> float:
        """Largest relative imbalance of the load against the contact forces and the rim's reaction (-).

        The rim's ``n = 1`` reaction is compared with the load with the arc spreading of the contact
        points removed (``sinc`` of half a grid step): both balances hold to round-off, so the value
        is a check, not a result (about 1e-12 on the tire files; it varies with the BLAS build).
        """
        spread = np.sinc(self.grid.dtheta / (2 * np.pi))
        hub = abs(self.hub_force / (self.load * spread) - 1.0)
        contact = abs(float(np.sum(self.contact_force)) / self.load - 1.0)
        return max(hub, contact)

    @property
    def points(self) -> tuple[np.ndarray, np.ndarray]:
        """Column and row index of every point in contact (contact order of the FRFs)."""
        return np.nonzero(self.contact)


def check_contact_memory(grid: ContactGrid, harmonics: int) -> None:
    """Refuse a contact grid whose dense compliance would exceed the memory limit, before any solve.

    The vertical compliance of the ``P`` candidate points is dense (P^2), built from four
    (r, theta) blocks of the same size; the harmonic flexibilities hold (N + 1) (2 n_cols)^2.
    """
    points = grid.n_cols * grid.n_rows
    n_bytes = 8.0 * (6 * points**2 + (harmonics + 1) * (2 * grid.n_cols) ** 2)
    guards.check_memory(n_bytes, f"the contact compliance of {points} points", "[mesh] contact_spacing")


def _candidates(grid: ContactGrid, road: RoadSurface) -> np.ndarray:
    x, z = grid.xz()
    top = z.min()
    return (z - top + road.drop(x)).ravel()


def _rim_force(tire: SectionTire, forces: np.ndarray) -> float:
    """Vertical force on the fixed rim (N) from the ``n = 1`` reaction to the contact forces."""
    grid = tire.grid
    transfer = rim_transfer(tire.ops, grid.dofs, np.array([0.0])).contact[0].real
    q_r, q_t = n1_loads(grid, forces)
    c = grid.n_cols
    return float(transfer[:c] @ q_r + transfer[c:] @ q_t)


def n1_loads(grid: ContactGrid, forces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Generalised ``n = 1`` symmetric-set loads (r, theta) per column of vertical point forces (n_cols, n_rows)."""
    spread = np.sinc(grid.dtheta / (2 * np.pi))
    th = grid.theta[None, :]
    return (-(np.cos(th) ** 2) * forces).sum(1) * spread, ((np.sin(th) ** 2) * forces).sum(1) * spread


def section_tasselli(tire: SectionTire, contact: np.ndarray) -> Tasselli:
    """Tasselli of a contact set: rows of ``target_length``, columns of equal lateral bands."""
    grid, spec = tire.grid, tire.spec.tasselli
    col, row = np.nonzero(contact)
    x, _ = grid.xz()
    dx = grid.radius[col] * grid.dtheta
    spacing = grid.width.sum() / (grid.n_cols - 1)
    edges = grid.y - 0.5 * grid.width
    left, right = edges.min(), (grid.y + 0.5 * grid.width).max()
    n_bands = max(1, int(round((right - left) / (spacing * spec.strips_per_column))))
    band = np.clip(((grid.y - left) / ((right - left) / n_bands)).astype(int), 0, n_bands - 1)
    return tassellate(
        node_strip=col,  # each column of contact points has its own lateral position: its own road track
        node_index=row,
        node_x=x[col, row],
        node_y=grid.y[col],
        node_dx_minus=dx,
        node_dx_plus=dx,
        strip_width=(right - left) / n_bands,
        target_length=spec.target_length,
        strips_per_column=1,
        node_width=grid.width[col],
        node_column=band[col],
    )


def solve_section_static(
    tire: SectionTire, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> SectionStaticState:
    """Load the cross-section tire against a flat road or a drum (see the module notes)."""
    return solve_section_statics(tire, road, [load], drum_radius)[0]


def solve_section_statics(
    tire: SectionTire, road: str = "flat", loads=(None,), drum_radius: float | None = None
) -> list[SectionStaticState]:
    """:func:`solve_section_static` at several ``loads`` (N; ``None``: the tire file's), one compliance for all."""
    surface = make_road(road, drum_radius)
    loads = [tire.spec.operating.vertical_load if load is None else check_load(load) for load in loads]
    grid = tire.grid
    check_contact_memory(grid, tire.harmonics)
    flex = harmonic_flexibility(tire.ops, grid.dofs, tire.harmonics)
    compliance = vertical_compliance(grid, flex)
    gap0 = _candidates(grid, surface)
    states = []
    for load in loads:
        forces, delta, k_tan, iterations = active_set(lambda cols: compliance[:, cols], gap0, np.zeros(gap0.size), load)
        forces = forces.reshape(grid.n_cols, grid.n_rows)
        contact = forces > 0
        if contact[:, [0, -1]].any():
            raise RuntimeError(
                f"contact reaches the end of the contact grid at {load:g} N; the load is too high for this tire "
                f"(grid +/- {grid.theta[-1] * grid.radius.max() * 1e3:.0f} mm)"
            )
        states.append(
            SectionStaticState(
                road=surface,
                load=load,
                deflection=float(delta),
                contact=contact,
                contact_force=forces,
                pressure=forces / grid.area(),
                node_pressure=(forces / grid.area())[np.nonzero(contact)],
                hub_force=_rim_force(tire, forces),
                vertical_stiffness=float(k_tan),
                tasselli=section_tasselli(tire, contact),
                iterations=iterations,
                grid=grid,
                tire=tire.spec,
            )
        )
    return states


def loaded_amplitudes(tire: SectionTire, states: SectionStaticState | list[SectionStaticState]):
    """Per harmonic, the loaded tire's static amplitudes under the contact forces: yields
    ``(n, symmetric, antisymmetric)``, each (n_dof, n_states) in m (one sparse factorisation with
    the static moduli per harmonic for all the states; a single state gives (n_dof, 1)).

    The symmetric set is ``u_r = a_r cos n theta, u_theta = a_theta sin n theta, u_y = a_y cos n theta``,
    the antisymmetric one ``(sin, -cos, sin)`` (:mod:`roadnoise_utils.tire.cross_section.waveguide`).
    """
    import scipy.sparse.linalg as spla

    states = [states] if isinstance(states, SectionStaticState) else list(states)
    grid, ops = tire.grid, tire.ops
    free = ops.free
    points = []
    for state in states:
        col, row = np.nonzero(state.contact)
        force = state.contact_force[col, row]
        th_b = grid.theta[row]
        points.append((grid.nodes[col], th_b, -force * np.cos(th_b), force * np.sin(th_b)))
    k = len(states)
    for n in range(tire.harmonics + 1):
        spread = np.sinc(n * grid.dtheta / (2 * np.pi))
        loads = np.zeros((ops.n_dof, 2 * k))
        for j, (nodes, th_b, f_r, f_t) in enumerate(points):
            cos_b, sin_b = np.cos(n * th_b) * spread, np.sin(n * th_b) * spread
            np.add.at(loads[:, j], 3 * nodes, f_r * cos_b)  # symmetric set
            np.add.at(loads[:, j], 3 * nodes + 1, f_t * sin_b)
            np.add.at(loads[:, k + j], 3 * nodes, f_r * sin_b)  # antisymmetric set
            np.add.at(loads[:, k + j], 3 * nodes + 1, -f_t * cos_b)
        amplitude = np.zeros((ops.n_dof, 2 * k))
        amplitude[free] = spla.splu(ops.free_stiffness(n, storage_only=True)).solve(loads[free])
        yield n, amplitude[:, :k], amplitude[:, k:]


def loaded_displacement(tire: SectionTire, state: SectionStaticState, theta: np.ndarray) -> np.ndarray:
    """Displacement of every cross-section node at angles ``theta`` under the contact forces (m).

    Returns (n_theta, n_nodes, 3) components ``u_r, u_theta, u_y``: the harmonic sum of the
    symmetric and antisymmetric sets (:func:`loaded_amplitudes`).
    """
    theta = np.atleast_1d(np.asarray(theta, float))
    out = np.zeros((theta.size, tire.mesh.n_nodes, 3))
    for n, symmetric, antisymmetric in loaded_amplitudes(tire, state):
        sym, anti = symmetric[:, 0].reshape(-1, 3), antisymmetric[:, 0].reshape(-1, 3)
        c, s = np.cos(n * theta)[:, None], np.sin(n * theta)[:, None]
        out[:, :, 0] += c * sym[:, 0] + s * anti[:, 0]
        out[:, :, 1] += s * sym[:, 1] - c * anti[:, 1]
        out[:, :, 2] += c * sym[:, 2] + s * anti[:, 2]
    return out


def section_summary(state: SectionStaticState) -> pd.Series:
    """Key numbers of a loaded cross-section tire, in the paper's units (:meth:`SectionStaticState.summary`)."""
    return state.summary()


def force_balance(state: SectionStaticState) -> float:
    """:meth:`SectionStaticState.force_balance`."""
    return state.force_balance()
