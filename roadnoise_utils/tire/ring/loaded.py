"""The loaded tire as a linear dynamic system about its static state.

After the static analysis (:mod:`roadnoise_utils.tire.ring.static`) the paper linearises the FET about the loaded
configuration and computes frequency responses with the hub fixed ("The FET Model"). Here:

* free DOF: all belt DOF; the hub (rim) DOF are held (fixed hub);
* every tread point in contact is tied to the road by its tread element: a normal spring
  (vertical) and a shear spring (longitudinal, the footprint sticks to the road as in the
  adhesion zone of a rolling tire), both of compound ``tread``;
* the input of contact point ``n`` is a vertical road displacement :math:`u_n`, which pushes
  the belt node through the tread spring with :math:`g_{tread}(\\omega)\\,k_n u_n`;
* the output is the vertical force the tire exerts on the hub (positive upward): with the
  hub held it is :math:`F = -K_{hf}(\\omega)\\,u_f`.

Sign convention: a road that rises under the footprint pushes the hub up, so
:math:`H(0) > 0`; a hub that moves up with the footprint held is pulled down, so
:math:`G_H(0) < 0` (the paper's :math:`F_M = F_F + F_H`, Eq. 5, then adds both).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..cavity import CavityCoupling
from .mechanics import UX, UZ, FETModel
from .static import StaticState, check_same_tire


@dataclass(frozen=True, eq=False)
class LoadedTire:
    """Matrices of the loaded tire on the free (belt) DOF.

    Attributes
    ----------
    fet, static : FETModel, StaticState
        The model and the state it is linearised about.
    free : ndarray of int
        Indices of the free DOF in the full DOF vector.
    M : csr_matrix
        Mass on the free DOF (kg).
    K_elastic : csr_matrix
        Frequency-independent stiffness on the free DOF (N/m).
    K_compound : dict of str to csr_matrix
        Compound stiffness at static modulus on the free DOF, including ``"tread"``
        (the contact springs) (N/m).
    hub_elastic, hub_compound : ndarray, dict of str to ndarray
        Hub-vertical row of the stiffness on the free DOF, elastic and per compound (N/m).
    hub_hub_elastic, hub_hub_compound : float, dict of str to float
        Hub-vertical diagonal stiffness, elastic and per compound (N/m).
    road_input : csr_matrix (n_free, n_contact)
        Force on the free DOF per unit road displacement of each contact point, at static
        tread modulus (N/m); scaled by :math:`g_{tread}(\\omega)`.
    cavity : CavityCoupling, optional
        The air cavity coupled to the belt and the rim (:func:`roadnoise_utils.tire.ring.cavity.ring_cavity_coupling`):
        :meth:`cavity_terms` is its low-rank share of the dynamic stiffness, included in
        :meth:`hub_row` and :meth:`hub_diagonal` (the pressure on the rim). None: no cavity (the paper's model).
    """

    fet: FETModel
    static: StaticState
    free: np.ndarray
    M: sp.csr_matrix
    K_elastic: sp.csr_matrix
    K_compound: dict[str, sp.csr_matrix]
    hub_elastic: np.ndarray
    hub_compound: dict[str, np.ndarray]
    hub_hub_elastic: float
    hub_hub_compound: dict[str, float]
    road_input: sp.csr_matrix
    cavity: CavityCoupling | None = None

    def cavity_terms(self, omega: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """``(V_free, C, W_free, v_hub, w_hub)``: the cavity adds :math:`-V C W^T` to the dynamic stiffness
        (:meth:`.tire.cavity.CavityCoupling.terms`); ``V_free``, ``W_free`` (n_free, modes) on the free DOF,
        ``v_hub``, ``w_hub`` (modes,) their hub-vertical rows. At rest ``C`` is diagonal and ``W = V``."""
        if self.cavity is None:
            return None
        last = self.__dict__.get("_cavity_terms_at")
        if last is not None and last[0] == omega:  # hub_row, hub_column, hub_diagonal and the solve: one frequency
            return last[1]
        hub = self.fet.mesh.hub_dofs[1]
        c, w = self.cavity.terms(omega)
        v = self.cavity.volume
        v_free = v[self.free]
        terms = v_free, c, (v_free if w is v else w[self.free]), v[hub], w[hub]
        object.__setattr__(self, "_cavity_terms_at", (omega, terms))  # the last frequency's, not an input
        return terms

    @property
    def n_contact(self) -> int:
        """Number of contact points (inputs)."""
        return self.road_input.shape[1]

    def ratios(self, omega: float, storage_only: bool = False) -> dict[str, complex]:
        """:math:`g_c(\\omega)` of every compound (real parts if ``storage_only``)."""
        out = {name: self.fet.modulus_ratio(name, omega) for name in self.K_compound}
        return {k: complex(v.real) for k, v in out.items()} if storage_only else out

    def stiffness(self, omega: float, storage_only: bool = False) -> sp.csr_matrix:
        """Stiffness on the free DOF at ``omega`` (rad/s)."""
        g = self.ratios(omega, storage_only)
        total = self.K_elastic.astype(float if storage_only else complex)
        for name, kc in self.K_compound.items():
            total = total + (g[name].real if storage_only else g[name]) * kc
        return total.tocsr()

    def dynamic_stiffness(self, omega: float, storage_only: bool = False) -> sp.csc_matrix:
        """:math:`D(\\omega) = K(\\omega) - \\omega^2 M` on the free DOF (complex symmetric)."""
        return (self.stiffness(omega, storage_only) - omega**2 * self.M).tocsc()

    def hub_row(self, omega: float, storage_only: bool = False) -> np.ndarray:
        """Hub-vertical row :math:`K_{hf}(\\omega)` on the free DOF (N/m): the hub force per unit motion of each DOF."""
        row = self._hub_elastic_row(omega, storage_only)
        terms = self.cavity_terms(omega)
        if terms is not None:  # the pressure the belt's motion makes, on the rim
            _, c, w_free, v_hub, _ = terms
            row = row - w_free @ (c.T @ v_hub)
        return row

    def hub_column(self, omega: float, storage_only: bool = False) -> np.ndarray:
        """Hub-vertical column :math:`K_{fh}(\\omega)` on the free DOF (N/m): the force on each DOF per unit hub
        motion; :meth:`hub_row` but for a rolling cavity, whose coupling is not reciprocal."""
        column = self._hub_elastic_row(omega, storage_only)
        terms = self.cavity_terms(omega)
        if terms is not None:  # the pressure the rim's motion makes, on the belt
            v_free, c, _, _, w_hub = terms
            column = column - v_free @ (c @ w_hub)
        return column

    def _hub_elastic_row(self, omega: float, storage_only: bool) -> np.ndarray:
        g = self.ratios(omega, storage_only)
        row = self.hub_elastic.astype(complex)
        for name, r in self.hub_compound.items():
            row = row + g[name] * r
        return row

    @property
    def rolling(self) -> bool:
        """Whether the coupled cavity's air streams (:func:`.tire.cavity.rolling_coupling`): no mirror symmetry."""
        return self.cavity is not None and self.cavity.rolling

    def hub_diagonal(self, omega: float, storage_only: bool = False) -> complex:
        """Hub-vertical diagonal stiffness :math:`K_{hh}(\\omega)` (N/m)."""
        g = self.ratios(omega, storage_only)
        diagonal = self.hub_hub_elastic + sum(g[name] * v for name, v in self.hub_hub_compound.items())
        terms = self.cavity_terms(omega)
        if terms is not None:  # the pressure the rim's own motion makes, on the rim
            _, c, _, v_hub, w_hub = terms
            diagonal = diagonal - v_hub @ c @ w_hub
        return diagonal


def _contact_springs(fet: FETModel, static: StaticState, stick: bool) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """Tread springs of the contact points (full DOF) and the road-input matrix (full DOF x contact)."""
    mesh = fet.mesh
    t = static.tasselli
    strip, node = t.node_strip, t.node_index
    dz = mesh.dof(strip, node, UZ)
    dx = mesh.dof(strip, node, UX)
    kn = fet.tread_normal[strip, node]
    ks = fet.tread_shear[strip, node]
    diag = np.zeros(fet.n_dof)
    diag[dz] += kn
    if stick:
        diag[dx] += ks
    k_tread = sp.diags(diag).tocsr()
    b = sp.csr_matrix((kn, (dz, np.arange(strip.size))), shape=(fet.n_dof, strip.size))
    return k_tread, b


def loaded_tire(
    fet: FETModel, static: StaticState, stick: bool = True, cavity: CavityCoupling | None = None
) -> LoadedTire:
    """Linearise the FET about a static state, fixed hub, footprint tied to the road.

    The inputs are the contact points in the order of ``static.tasselli`` (``node_*`` arrays).
    With ``stick=False`` the contact points slide freely along the road (no tread shear
    spring): the paper's check that "lateral and longitudinal displacements of the footprint
    nodes give an insignificant contribution" to the vertical hub force.
    """
    check_same_tire(fet, static)
    mesh = fet.mesh
    free = np.setdiff1d(np.arange(fet.n_dof), mesh.hub_dofs)
    hub = mesh.hub_dofs[1]
    k_tread, b = _contact_springs(fet, static, stick)
    compounds = dict(fet.K_compound)
    compounds["tread"] = k_tread

    def restrict(k: sp.csr_matrix) -> sp.csr_matrix:
        return k[free][:, free].tocsr()

    def hub_of(k: sp.csr_matrix) -> np.ndarray:
        return np.asarray(k[hub].toarray()).ravel()[free]

    return LoadedTire(
        fet=fet,
        static=static,
        free=free,
        M=restrict(fet.M),
        K_elastic=restrict(fet.K_elastic),
        K_compound={name: restrict(k) for name, k in compounds.items()},
        hub_elastic=hub_of(fet.K_elastic),
        hub_compound={name: hub_of(k) for name, k in compounds.items()},
        hub_hub_elastic=float(fet.K_elastic[hub, hub]),
        hub_hub_compound={name: float(k[hub, hub]) for name, k in compounds.items()},
        road_input=b[free].tocsr(),
        cavity=cavity,
    )
