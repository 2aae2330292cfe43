"""The air cavity in the cross-section tire's footprint FRFs (beyond the paper).

The loaded cavity (:mod:`roadnoise_utils.tire.cross_section.cavity`) carries plane waves whose modes
:math:`\\phi_m(\\theta)` (Webster's equation on the loaded area, mass-normalised) have the
modal pressures :math:`q_m = c_m(\\omega) V_m`, :math:`V_m = \\int \\phi_m \\Delta V'\\,d\\theta`
the modal volume change and :math:`c_m` the gains of :class:`.tire.cavity.CavityCoupling`. The
footprint FRFs are vertical and fore-aft even (:mod:`roadnoise_utils.tire.cross_section.footprint`), so only the even
modes take part (the vertical component of the loaded doublet; the fore-aft one drives the
hub fore and aft). Their content in harmonic ``n`` is :math:`\\alpha_{mn} = \\int \\phi_m \\cos
n\\theta\\,d\\theta`; harmonics up to :data:`CONTENT_TOLERANCE`'s truncation carry them.

**Per harmonic** (exact sparse solves of :math:`D_n(\\omega) = K_n(\\omega) - \\omega^2 M_n`,
beads clamped): :math:`z_n = D_n^{-1} g` for the wall's load ``g`` (:func:`roadnoise_utils.tire.cross_section.cavity.wall_volume`:
by reciprocity the pressure's load is the volume change's vector). With the contact points'
vertical displacement per unit modal pressure ``B`` (P, M), the volume change of the wall under
the modal pressures ``Q`` (M, M), and ``tau`` (M,) the hub force per unit modal pressure (the
``n = 1`` rim reaction, the beads' load and the rim's base face), the pressures are
:math:`q = Y B^T \\lambda` for contact forces :math:`\\lambda`, :math:`Y = (I - cQ)^{-1} c`
(symmetric), and

.. math:: C_{eff} = C + B Y B^T, \\quad t_{eff} = t + B Y \\tau, \\quad
          D_{rim,eff} = D_{rim} - \\tau^T Y \\tau,

so the fixed-hub transfer is :math:`h = C_{eff}^{-1} t_{eff}` and
:math:`G_H = -(D_{rim,eff} + t_{eff}^T h)`: the structure of the solve without the cavity, one
low-rank (Woodbury) update of the footprint's even receptance. A rigid vertical rim motion
changes the volume by :math:`\\tau` too (reciprocity): the bead DOF move with it and the base
face sweeps :math:`r_{base} w_{rim} \\cos\\theta` per radian. A rigid translation of the whole
wheel changes the section's volume per radian by :math:`-A\\cos\\theta` (the wall's and the base's
shares together, tested), so at rest a :math:`\\cos\\theta` pressure puts :math:`-\\pi A` on the hub,
as on a free body.

**Known limit: the air's static stiffening.** The uniform mode couples through the linear
volume change about the round tire, :math:`dV/d\\delta \\approx -2\\cdot10^{-4}` m^2 on the
165/65 R14, which stiffens the tire by ~4e-6 of :math:`K_v`. The loaded tire's own pressure
sensitivity gives, through the Maxwell relation :math:`\\partial V/\\partial\\delta =
-\\partial F/\\partial p_0`, a tangent of ~-1.4e-2 m^2 (70 % of the membrane bound :math:`F/p_0`), so
~2 % of :math:`K_v`: the difference is the belt's second-order,
inextensible deformation, which a linear tire does not have. A rank-one term from two static
solves at :math:`p_0 \\pm \\delta p` would make the limit exact; not done yet.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla

from ..cavity import modal_gains, webster_modes
from .cavity import SectionCavity, loaded_area, section_cavity
from .dynamics import rim_vector
from .static import SectionStaticState, SectionTire

#: The modes' harmonic content is kept up to the harmonic beyond which every even mode has less
#: than this share of its squared content (-).
CONTENT_TOLERANCE = 1e-8


@dataclass(frozen=True, eq=False)
class SectionCavityCoupling:
    """The loaded cavity's even modes, ready to couple with the cross-section tire.

    Attributes
    ----------
    cavity : SectionCavity
    area : ndarray (J,)
        Loaded Webster area at equal angles from the footprint centre (m^2).
    omegas : ndarray (M,)
        Even modes' angular frequencies (rad/s), the uniform mode's 0.
    shapes : ndarray (M, J)
        Their pressure shapes at the nodes, normalised by the waveguide's mass.
    content : ndarray (M, N + 1)
        :math:`\\alpha_{mn}`, harmonics ``0..N`` (rad, in the shapes' units).
    damping_ratio : float
    """

    cavity: SectionCavity
    area: np.ndarray
    omegas: np.ndarray
    shapes: np.ndarray
    content: np.ndarray
    damping_ratio: float

    @property
    def harmonics(self) -> int:
        """The last harmonic carrying the modes."""
        return self.content.shape[1] - 1

    def gains(self, omega: float) -> np.ndarray:
        """:math:`c_m(\\omega)` of the even modes (:func:`.tire.cavity.modal_gains`)."""
        air = self.cavity.cavity
        return modal_gains(self.omegas, omega, air.density, air.sound_speed, self.damping_ratio)


def section_cavity_coupling(
    tire: SectionTire, static: SectionStaticState, n_modes: int | None = None, damping_ratio: float | None = None
) -> SectionCavityCoupling:
    """The even modes of the loaded cavity (``n_modes`` waveguide modes, both parities, before the
    odd are left out; defaults from the tire file's ``[cavity]``) and their harmonic content."""
    spec = tire.spec.cavity
    n_modes = spec.modes if n_modes is None else n_modes
    damping = spec.damping_ratio if damping_ratio is None else damping_ratio
    cavity = section_cavity(tire)
    area = loaded_area(tire, static, cavity=cavity)
    modes = webster_modes(cavity.cavity, area, n_modes)
    even = modes.parity > 0
    shapes = modes.shapes[even]
    n_nodes = area.size
    dtheta = 2.0 * np.pi / n_nodes
    theta = dtheta * np.arange(n_nodes)
    last = min(tire.harmonics, n_nodes // 2)
    content = shapes @ np.cos(np.outer(theta, np.arange(last + 1))) * dtheta
    energy = np.cumsum((content**2)[:, ::-1], axis=1)[:, ::-1]  # energy from harmonic n upwards
    beyond = np.all(energy <= CONTENT_TOLERANCE * energy[:, :1], axis=0)
    keep = int(np.argmax(beyond)) if beyond.any() else last + 1
    omegas = 2.0 * np.pi * modes.freqs[even]
    omegas[0] = 0.0  # the uniform pressure
    return SectionCavityCoupling(cavity, area, omegas, shapes, content[:, :keep], float(damping))


@dataclass(frozen=True, eq=False)
class CavityTerms:
    """The cavity's terms of the footprint solve at each frequency (see the module notes).

    ``points`` (n_f, P, M): vertical displacement of each contact point (``static.points`` order)
    per unit modal pressure (m per modal unit); ``volume`` (n_f, M, M): the wall's modal volume
    change per unit modal pressure; ``rim`` (n_f, M): vertical force on the fixed rim per unit
    modal pressure (N); ``gains`` (n_f, M).
    """

    points: np.ndarray
    volume: np.ndarray
    rim: np.ndarray
    gains: np.ndarray

    def coupled(self) -> np.ndarray:
        """:math:`Y = (I - cQ)^{-1} c` per frequency, (n_f, M, M)."""
        m = self.gains.shape[1]
        scaled = self.gains[:, :, None] * self.volume
        return np.linalg.solve(np.eye(m)[None] - scaled, np.eye(m)[None] * self.gains[:, None, :])


def cavity_terms(
    tire: SectionTire,
    static: SectionStaticState,
    coupling: SectionCavityCoupling,
    omegas: np.ndarray,
    reduced: list | None = None,
) -> CavityTerms:
    """:class:`CavityTerms` at angular frequencies ``omegas`` (rad/s), harmonics ``0..coupling.harmonics``
    with the tire's own compound laws.

    ``n = 1`` (which also carries the rim) is solved exactly, one sparse solve per frequency; the
    others from their Ritz-reduced harmonics in ``reduced`` (``reduced[n]``) when those carry the
    wall's load (:func:`roadnoise_utils.tire.cross_section.dynamics.reduce_harmonic` with ``wall``), else exactly too.
    """
    ops, grid = tire.ops, tire.grid
    free, fixed = ops.free, ops.fixed
    wall = coupling.cavity.wall
    col, row = static.points
    th = grid.theta[row]
    c = grid.n_cols
    position = np.searchsorted(free, grid.dofs)
    rim_b = rim_vector(ops)[fixed]
    omegas = np.asarray(omegas, float)
    n_f, n_modes = omegas.size, coupling.omegas.size
    points = np.zeros((n_f, col.size, n_modes), complex)
    volume = np.zeros((n_f, n_modes, n_modes), complex)
    rim = np.zeros((n_f, n_modes), complex)
    for n in range(coupling.harmonics + 1):
        alpha = coupling.content[:, n]
        spread = np.sinc(n * grid.dtheta / (2 * np.pi))
        radial = -np.cos(th) * np.cos(n * th) * spread
        tangential = np.sin(th) * np.sin(n * th) * spread
        harmonic = reduced[n] if reduced is not None and n < len(reduced) else None
        if n != 1 and harmonic is not None and harmonic.n == n and harmonic.projected.wall is not None:
            at, wall_z = harmonic.wall_response(ops.laws, omegas)  # (n_f, d), (n_f,)
            points += (radial * at[:, col] + tangential * at[:, c + col])[:, :, None] * alpha[None, None, :]
            volume += wall_z[:, None, None] * np.outer(alpha, alpha)[None]
            continue
        mass = ops.free_mass(n)
        for i, omega in enumerate(omegas):
            z = spla.splu((ops.free_stiffness(n, omega) - omega**2 * mass).tocsc()).solve(wall[free].astype(complex))
            at = z[position]
            shift = radial * at[col] + tangential * at[c + col]  # (P,): per unit harmonic pressure
            points[i] += shift[:, None] * alpha[None, :]
            volume[i] += (wall[free] @ z) * np.outer(alpha, alpha)
            if n == 1:
                d_fb = (ops.stiffness(1, omega) - omega**2 * ops.mass_matrix(1)).tocsr()[free][:, fixed]
                reaction = -(z @ (d_fb @ rim_b)) + wall[fixed] @ rim_b + coupling.cavity.rim_face
                rim[i] = reaction * alpha
    gains = np.stack([coupling.gains(omega) for omega in omegas])
    return CavityTerms(points=points, volume=volume, rim=rim, gains=gains)


def effective_rim(transfer: np.ndarray, free_rim: np.ndarray, terms: CavityTerms, coupled: np.ndarray):
    """:math:`t_{eff} = t + B Y \\tau` (n_f, P) and :math:`D_{rim,eff} = D_{rim} - \\tau^T Y \\tau` (n_f,)."""
    through = np.einsum("fmk,fk->fm", coupled, terms.rim)  # Y tau
    return (
        transfer + np.einsum("fpm,fm->fp", terms.points, through),
        free_rim - np.einsum("fm,fm->f", terms.rim, through),
    )


def woodbury_solve(solve, load: np.ndarray, points: np.ndarray, coupled: np.ndarray, weight: np.ndarray) -> np.ndarray:
    """``y`` (b, R) with :math:`(S W + B Y B^T W)\\,y = load` from ``solve(rhs)`` = :math:`(S W)^{-1} rhs`
    (rhs (b, R, k)): the even receptance ``comp = S W`` of :mod:`roadnoise_utils.tire.cross_section.footprint` updated by the
    cavity (``points`` B (b, R, M) of the representatives, ``coupled`` Y (b, M, M), ``weight`` W (R,))."""
    z = solve(np.concatenate([load[..., None], points], axis=2))
    z_load, z_points = z[..., 0], z[..., 1:]
    v_t = np.matmul(coupled, np.swapaxes(points * weight[None, :, None], 1, 2))  # (b, M, R)
    small = np.eye(coupled.shape[1])[None] + np.matmul(v_t, z_points)
    correction = np.linalg.solve(small, np.matmul(v_t, z_load[..., None]))
    return z_load - np.matmul(z_points, correction)[..., 0]
