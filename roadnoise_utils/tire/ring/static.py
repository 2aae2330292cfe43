"""Static analysis of the FET: inflate, load against a flat road or a drum (paper Fig. 2-3).

The paper's FET analysis mounts the rim, inflates the tire and loads it vertically before
any dynamics ("The FET Model"). Our FET is linear about the inflated state (pre-tension and
pressure load stiffness included, :mod:`.fet`); the nonlinearity of loading is the unilateral
contact, solved with a primal active set on the tread springs:

* a tread point is in contact when the road penetrates it; its contact force is the tread
  spring force :math:`\\lambda_n = k_n\\,(z_{road} - z_{tread} - u_{z,n}) \\ge 0`;
* contact is frictionless (vertical forces only) while loading;
* the road rises by the deflection :math:`\\delta` until the contact forces sum to the load.

The belt response to contact forces is condensed onto the tread points with the influence
(compliance) matrix :math:`C = E^T K^{-1} E`, computed column by column only for the points
that enter the active set, so each active-set iteration is a small dense solve and the whole
load-deflection curve is cheap. The hub is fixed; the force
it receives equals the load to round-off.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ... import guards
from ..active_set import active_set
from ..banded import BandedCholesky
from ..model import Footprint, check_load
from ..surface import RoadSurface, make_road
from ..tasselli import Tasselli, tassellate
from .mechanics import UZ, FETModel
from .spec import TireSpec, to_dict

#: Nodes within this angle of the bottom of the tire are contact candidates (rad).
CANDIDATE_ANGLE = np.deg2rad(45.0)


@dataclass(frozen=True, eq=False)
class StaticState(Footprint):
    """The inflated ring tire loaded against the road: its :class:`~.model.Footprint` and the FE state.

    Attributes
    ----------
    road, load, deflection, hub_force, vertical_stiffness, tasselli, node_pressure
        As :class:`~.model.Footprint`.
    contact : ndarray of bool (n_strips, n_elements)
        Tread points in contact.
    contact_force : ndarray (n_strips, n_elements)
        Vertical contact force at each tread point (N), zero outside contact.
    pressure : ndarray (n_strips, n_elements)
        Contact force per gross tread area of the point (Pa).
    displacement : ndarray (n_dof,)
        Displacement from the inflated state (m, rad); zero at the fixed hub.
    iterations : int
        Active-set iterations used.
    tire : TireSpec
        The tire it was solved for (:func:`check_same_tire` refuses another tire's FE model).
    """

    contact: np.ndarray
    contact_force: np.ndarray
    pressure: np.ndarray
    displacement: np.ndarray
    iterations: int
    road_height: np.ndarray = field(repr=False)
    tire: TireSpec | None = field(default=None, repr=False)

    def force_balance(self) -> float:
        """Largest relative imbalance of the load against the hub force and the contact forces' sum (-)."""
        return max(abs(self.hub_force / self.load - 1.0), abs(self.contact_force.sum() / self.load - 1.0))

    def summary(self) -> pd.Series:
        """:meth:`~.model.Footprint.summary` and the contact solve's active-set iterations."""
        return pd.concat([super().summary(), pd.Series({"active-set iterations": self.iterations})])


@dataclass(eq=False)
class ContactProblem:
    """The loaded-tire contact problem condensed onto the candidate tread points.

    Build it once per tire and road (:func:`contact_problem`); :meth:`solve` then costs a few
    small dense solves per load. Columns of the compliance matrix are computed lazily, only
    for the tread points that ever enter the active set (C is symmetric, so those columns
    also give the displacement of every other candidate).
    """

    fet: FETModel
    road: RoadSurface
    free: np.ndarray  # DOF indices not fixed (all but the hub)
    candidates: np.ndarray  # flat indices (strip * n_el + node) of candidate tread points
    candidate_dofs: np.ndarray  # their uz DOF, as positions in ``free``
    stiffness_tread: np.ndarray  # k_n of candidates (N/m)
    gap0: np.ndarray  # tread point height above the road top before loading, at zero rise (m)
    road_height0: np.ndarray  # road height under each candidate before loading (m)
    lu: BandedCholesky  # factor of K on the free DOF
    _columns: np.ndarray = field(init=False, repr=False)  # C[:, j] once computed (m/N)
    _known: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        n = self.candidates.size
        self._columns = np.zeros((n, n))
        self._known = np.zeros(n, bool)

    def compliance(self, columns: np.ndarray) -> np.ndarray:
        """Columns ``C[:, columns]`` of the compliance matrix :math:`E^T K^{-1} E` (m/N)."""
        missing = columns[~self._known[columns]]
        if missing.size:
            rhs = np.zeros((self.free.size, missing.size))
            rhs[self.candidate_dofs[missing], np.arange(missing.size)] = 1.0
            self._columns[:, missing] = self.lu.solve(rhs)[self.candidate_dofs]
            self._known[missing] = True
        return self._columns[:, columns]

    def solve(self, load: float, max_iterations: int = 200) -> tuple[np.ndarray, float, float, int]:
        """Active-set solve at ``load`` (N): (forces on candidates, deflection, tangent stiffness, iterations)."""
        return active_set(self.compliance, self.gap0, 1.0 / self.stiffness_tread, load, max_iterations)

    def full_displacement(self, forces: np.ndarray) -> np.ndarray:
        """Displacement of all DOF (hub fixed) under vertical forces on the candidates."""
        f = np.zeros(self.free.size)
        f[self.candidate_dofs] = forces
        u = np.zeros(self.fet.n_dof)
        u[self.free] = self.lu.solve(f)
        return u


def check_contact_memory(n_dof: int, n_candidates: int, n_strips: int) -> None:
    """Refuse meshes whose contact problem would exceed the memory limit, before it is factorised.

    The compliance of the candidate tread points is dense (candidates^2), each batch of its
    columns is a dense solve (DOF x candidates), and the banded factor holds about
    DOF x 12 x strips entries (its band spans two rings of nodes, three DOF each).
    """
    n_bytes = 8.0 * (n_candidates**2 + n_dof * n_candidates + 12 * n_dof * n_strips)
    guards.check_memory(n_bytes, f"the contact problem of {n_dof} DOF and {n_candidates} tread points", "[mesh]")


def contact_problem(fet: FETModel, road: RoadSurface) -> ContactProblem:
    """Factorise the static stiffness (hub fixed) and set up the candidate tread points."""
    mesh = fet.mesh
    theta = np.angle(np.exp(1j * mesh.theta))  # in (-pi, pi]
    strip, node = np.nonzero(np.broadcast_to(np.abs(theta) <= CANDIDATE_ANGLE, (mesh.n_strips, mesh.n_elements)))
    check_contact_memory(fet.n_dof, strip.size, mesh.n_strips)
    free = np.setdiff1d(np.arange(fet.n_dof), mesh.hub_dofs)
    k_static = fet.K(0.0, storage_only=True)[free][:, free].tocsc()
    lu = BandedCholesky(k_static)
    candidates = strip * mesh.n_elements + node
    tx, tz = mesh.tread_xz()
    top = tz.min()
    road_height0 = top - road.drop(tx.ravel()[candidates])
    return ContactProblem(
        fet=fet,
        road=road,
        free=free,
        candidates=candidates,
        candidate_dofs=np.searchsorted(free, mesh.dof(strip, node, UZ)),
        stiffness_tread=fet.tread_normal.ravel()[candidates],
        gap0=tz.ravel()[candidates] - road_height0,
        road_height0=road_height0,
        lu=lu,
    )


def check_mesh_resolution(fet: FETModel) -> None:
    """The contact points must resolve a row of tasselli: refuse one point per row or fewer, warn below two."""
    spec = fet.spec
    spacing = 2 * np.pi * spec.geometry.outer_radius / spec.mesh.n_elements
    row = spec.tasselli.target_length
    needed = int(np.ceil(4 * np.pi * spec.geometry.outer_radius / row))
    message = (
        f"[mesh] n_elements = {spec.mesh.n_elements} puts the contact points {spacing * 1e3:.1f} mm apart against "
        f"{row * 1e3:.1f} mm rows of tasselli"
    )
    if spacing > row:
        raise ValueError(f"{message}: valid range is n_elements >= {needed // 2 + 1} (n_elements >= {needed} advised)")
    if spacing > 0.5 * row:
        guards.warn(f"{message}: rows hold a single point; n_elements >= {needed} resolves them", stacklevel=4)


def _tasselli_of(fet: FETModel, contact: np.ndarray) -> Tasselli:
    mesh = fet.mesh
    tx, _ = mesh.tread_xz()
    strip, node = np.nonzero(contact)
    ne = mesh.n_elements
    x = tx[strip, node]
    x_prev = tx[strip, (node - 1) % ne]
    x_next = tx[strip, (node + 1) % ne]
    spec = fet.spec.tasselli
    return tassellate(
        node_strip=strip,
        node_index=node,
        node_x=x,
        node_y=mesh.y[strip],
        node_dx_minus=x - x_prev,
        node_dx_plus=x_next - x,
        strip_width=mesh.strip_width,
        target_length=spec.target_length,
        strips_per_column=spec.strips_per_column,
    )


def solve_static(
    fet: FETModel, road: str = "flat", load: float | None = None, drum_radius: float | None = None
) -> StaticState:
    """Inflate and load the tire against a flat road or a drum.

    Parameters
    ----------
    fet : FETModel
        The tire (:func:`.fet.build_fet`).
    road : {"flat", "drum"}
        Road surface.
    load : float, optional
        Vertical load (N); default the tire's nominal load.
    drum_radius : float, optional
        Drum radius (m), required for ``road="drum"`` (the paper's drum, 1.25 m, is
        ``experiments.cleat_conditions().drum_radius``; ``ru.solve_static`` fills it in).

    Returns
    -------
    StaticState
        Contact set, contact forces and pressures, deflection, tangent vertical stiffness,
        displacement field and tasselli.
    """
    if not isinstance(fet, FETModel):
        raise TypeError(
            f"fet must be an FETModel (ru.build_fet(tire)), got {type(fet).__name__}; "
            "ru.stages.solve_static takes a tire name"
        )
    surface = make_road(road, drum_radius)
    load = fet.spec.operating.vertical_load if load is None else check_load(load)
    check_mesh_resolution(fet)
    problem = contact_problem(fet, surface)
    forces, delta, k_tan, iterations = problem.solve(load)
    check_deflection(fet, delta, load)
    return _state_from_solution(problem, forces, delta, k_tan, iterations, load)


#: Deflection / section height above which a result is doubtful (warning) or impossible (error).
DEFLECTION_WARNING, DEFLECTION_LIMIT = 0.35, 0.60


def check_deflection(fet: FETModel, deflection: float, load: float) -> None:
    """Refuse a deflection beyond :data:`DEFLECTION_LIMIT` of the section height; warn beyond :data:`DEFLECTION_WARNING`.

    A linear belt on a foundation has no rim to hit: past ~60 % of the section height the tire
    would bottom out, and past ~35 % the small-deflection model is stretched.
    """
    g = fet.spec.geometry
    height = g.section_width * g.aspect_ratio
    ratio = deflection / height
    what = (
        f"load = {load:g} N at {fet.spec.operating.inflation_pressure / 1e5:g} bar deflects the tire "
        f"{deflection * 1e3:.1f} mm, {ratio:.0%} of its {height * 1e3:.0f} mm section height"
    )
    if ratio > DEFLECTION_LIMIT:
        raise ValueError(f"{what}: valid range is <= {DEFLECTION_LIMIT:.0%} (lower the load or raise the pressure)")
    if ratio > DEFLECTION_WARNING:
        guards.warn(f"{what}; beyond {DEFLECTION_WARNING:.0%} the linear model is stretched", stacklevel=4)


def _state_from_solution(
    problem: ContactProblem, forces: np.ndarray, delta: float, k_tan: float, iterations: int, load: float
) -> StaticState:
    fet = problem.fet
    mesh = fet.mesh
    shape = (mesh.n_strips, mesh.n_elements)
    theta = np.angle(np.exp(1j * mesh.theta[problem.candidates % mesh.n_elements]))
    if np.max(np.abs(theta[forces > 0])) >= CANDIDATE_ANGLE - 2 * np.pi / mesh.n_elements:
        raise RuntimeError("contact reaches the edge of the candidate zone; the load is too high for this tire")
    u = problem.full_displacement(forces)
    _check_no_hidden_penetration(problem, u, delta)
    contact_force = np.zeros(shape)
    contact_force.ravel()[problem.candidates] = forces
    road_height = np.full(shape, np.nan)
    road_height.ravel()[problem.candidates] = problem.road_height0 + delta
    hub_row = fet.K(0.0, storage_only=True)[mesh.hub_dofs[1]]
    hub_force = -float((hub_row @ u)[0])
    contact = contact_force > 0
    pressure = contact_force / mesh.tread_area()
    tasselli = _tasselli_of(fet, contact)
    return StaticState(
        road=problem.road,
        load=load,
        deflection=float(delta),
        contact=contact,
        contact_force=contact_force,
        pressure=pressure,
        node_pressure=pressure[tasselli.node_strip, tasselli.node_index],
        displacement=u,
        hub_force=hub_force,
        vertical_stiffness=float(k_tan),
        tasselli=tasselli,
        iterations=iterations,
        road_height=road_height,
        tire=fet.spec,
    )


def check_same_tire(fet: FETModel, static: StaticState) -> None:
    """Refuse an FE model and a static state of different tires (their pairing would be silently wrong).

    Raises
    ------
    TypeError
        ``fet`` is not an :class:`FETModel` or ``static`` not a :class:`StaticState`.
    ValueError
        ``static`` was solved for a tire whose parameters differ from ``fet``'s; names them.
    """
    if not isinstance(fet, FETModel):
        raise TypeError(f"fet must be an FETModel (ru.build_fet(tire)), got {type(fet).__name__}")
    if not isinstance(static, StaticState):
        raise TypeError(f"static must be a StaticState (ru.solve_static(fet)), got {type(static).__name__}")
    if static.tire is None:
        return
    a, b = _flat(to_dict(static.tire)), _flat(to_dict(fet.spec))
    differ = sorted(k for k in a.keys() | b.keys() if a.get(k) != b.get(k))
    if differ:
        shown = ", ".join(f"{k} ({a.get(k)!r} vs {b.get(k)!r})" for k in differ[:3])
        raise ValueError(
            f"static was solved for another tire than fet: {shown}{' ...' if len(differ) > 3 else ''}; "
            "solve the static state of this FE model (ru.solve_static(fet, ...))"
        )


def _flat(data: dict, prefix: str = "") -> dict:
    out = {}
    for key, value in data.items():
        if isinstance(value, dict):
            out.update(_flat(value, f"{prefix}{key}."))
        else:
            out[f"{prefix}{key}"] = value
    return out


def _check_no_hidden_penetration(problem: ContactProblem, u: np.ndarray, delta: float) -> None:
    """Every tread point outside the candidate zone must stay clear of the road."""
    mesh = problem.fet.mesh
    tx, tz = mesh.tread_xz()
    j, k = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    uz = u[mesh.dof(j, k, UZ)]
    top = tz.min()
    lower_half = np.cos(mesh.theta)[None, :] > 0
    gap = tz + uz - (top + delta - problem.road.drop(np.where(lower_half, tx, 0.0)))
    outside = np.ones(mesh.n_strips * mesh.n_elements, bool)
    outside[problem.candidates] = False
    if np.any(gap.ravel()[outside] < 0):
        raise RuntimeError("a tread point outside the candidate zone penetrates the road")


def load_deflection(
    fet: FETModel, loads: np.ndarray, road: str = "flat", drum_radius: float | None = None
) -> np.ndarray:
    """Deflection (m) at each load (N): the load-deflection curve of the tire."""
    loads = np.atleast_1d(np.asarray(loads, dtype=object))
    if loads.size == 0 or loads.ndim != 1:
        raise ValueError(f"loads must be a non-empty list of loads (N), got shape {loads.shape}")
    loads = [guards.real(f"loads[{k}]", w, *guards.LOAD_RANGE, unit="N") for k, w in enumerate(loads)]
    problem = contact_problem(fet, make_road(road, drum_radius))
    return np.array([problem.solve(w)[1] for w in loads])


def static_summary(states: dict[str, StaticState]) -> pd.DataFrame:
    """Key numbers of one or more static states (columns), in the paper's units (:meth:`StaticState.summary`)."""
    return pd.DataFrame({name: state.summary() for name, state in states.items()})
