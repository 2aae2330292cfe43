"""Verification of the cross-section tire against closed forms, membrane theory and a 3-D assembly.

The checks as functions returning tables, shared by the tests (which assert them)
and notebook 09 (which shows them):

* :func:`ring_check` (a): one thin, stiff layer under tension and follower pressure on a radial
  and tangential foundation, against the closed-form ring frequencies (Gong 1993,
  :func:`roadnoise_utils.tire.ring_theory.ring_frequencies`);
* :func:`torus_check` (b): the linear inflation of a thin torus against the membrane forces
  :math:`N_\\theta = pa/2`, :math:`N_\\varphi = pa(r + R_0)/(2r)` (Timoshenko &
  Woinowsky-Krieger, *Theory of Plates and Shells*, 1959, section 107);
* :func:`three_d_check` (e): the harmonic sum of the receptance against a direct 3-D assembly
  of the same cross-section (physical components, trapezoidal rule around, Fourier
  differentiation matrix: Trefethen, *Spectral Methods in MATLAB*, 2000, ch. 3).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import scipy.linalg as sla

from ..ring_theory import RingParameters, ring_frequencies
from ..rubber import FractionalZener
from . import laminate
from .contact import angular_sums
from .dynamics import direct_receptance
from .mesh import Ply, structured_mesh
from .operators import harmonic_operators
from .waveguide import element_dofs, face_springs, harmonic_weight, point_geometry

#: One compound law for the check structures (its frequency dependence is exercised by the 3-D check).
LAW = {"c": FractionalZener(2.0, 1e-4, 0.5)}


def band(radius=0.3, width=0.1, thickness=0.002, modulus=2e9, density=1200.0, n_el=6, poisson=0.0):
    """A thin cylindrical band: one layered element through the thickness, ``n_el`` across."""
    y = np.linspace(-width / 2, width / 2, 2 * n_el + 1)
    r = np.linspace(radius - thickness / 2, radius + thickness / 2, 3)
    node_r, node_y = np.meshgrid(r, y)
    ply = Ply("ring", 1.0, laminate.isotropic(modulus, poisson), density, "c")
    return structured_mesh(node_r, node_y, [[[ply]] for _ in range(n_el)])


def harmonic_frequencies(ops, n: int, extra=None) -> np.ndarray:
    """Natural frequencies (Hz, ascending) of harmonic ``n`` of the rim-clamped tire at the static moduli.

    ``extra``: a stiffness per radian added to the harmonic's (e.g. a foundation's springs).
    """
    free = ops.free
    k = ops.stiffness(n, storage_only=True)
    if extra is not None:
        k = k + harmonic_weight(n) * extra
    k = k.toarray()[np.ix_(free, free)]
    m = ops.mass_matrix(n).toarray()[np.ix_(free, free)]
    return np.sqrt(np.abs(sla.eigh(k, m, eigvals_only=True))) / (2 * np.pi)


def ring_check(
    radius: float = 0.3,
    width: float = 0.1,
    thickness: float = 0.002,
    modulus: float = 2e9,
    density: float = 1200.0,
    tension: float = 2000.0,
    k_r: float = 1.5e5,
    k_t: float = 2.0e5,
) -> pd.DataFrame:
    """(a) First frequency of n = 1..6 of a thin ring on a foundation: ours against the closed form.

    ``tension`` (N) is the hoop pre-stress times the section, balanced by the pressure on the
    inner face; ``k_r, k_t`` (N/m^2) per unit length of ring; ``u_y`` is held (in-plane ring).
    """
    mesh = band(radius, width, thickness, modulus, density)
    inner = radius - thickness / 2
    stress = np.zeros((mesh.points.element.size, 6))
    stress[:, 1] = tension / (width * thickness)
    ops = harmonic_operators(mesh, LAW, tension / (inner * width), fixed=np.arange(2, mesh.n_dof, 3), prestress=stress)
    springs = face_springs(mesh.r, mesh.y, mesh.face_lines(0), k_r / width, k_t / width, mesh.n_dof)
    ring = RingParameters(
        radius,
        modulus * width * thickness**3 / 12,
        tension,
        k_r * radius / inner,
        k_t * radius / inner,
        density * width * thickness,
    )
    n = np.arange(1, 7)
    ours = np.array([harmonic_frequencies(ops, k, springs)[0] for k in n])
    closed = ring_frequencies(n, ring)
    with np.errstate(divide="ignore", invalid="ignore"):  # a free ring's n = 1 is a rigid motion (0 Hz)
        error = np.where(closed > 0, 100 * (ours / closed - 1), np.nan)
    return pd.DataFrame(
        {"closed form (Hz)": closed, "cross-section model (Hz)": ours, "error (%)": error},
        index=pd.Index(n, name="n"),
    )


def torus(r0=0.2, a=0.05, h=0.0005, n_el=21, gap=0.5):
    """A thin isotropic torus of circular section, open over ``gap`` rad on the axle side (the beads)."""
    psi = np.linspace(-(np.pi - gap / 2), np.pi - gap / 2, 2 * n_el + 1)
    offset = np.array([-h / 2, 0.0, h / 2])
    node_r = (r0 + a * np.cos(psi))[:, None] + np.cos(psi)[:, None] * offset[None, :]
    node_y = (a * np.sin(psi))[:, None] + np.sin(psi)[:, None] * offset[None, :]
    ply = Ply("shell", 1.0, laminate.isotropic(2e9, 0.3), 1000.0, "c")
    return structured_mesh(node_r, node_y, [[[ply]] for _ in range(n_el)]), psi


def torus_check(r0: float = 0.2, a: float = 0.05, h: float = 0.0005, p: float = 1.0e5, n_el: int = 41) -> pd.DataFrame:
    """(b) Membrane forces of a thin inflated torus at the crown and +/- 40 deg, ours against membrane theory.

    Away from the parallels at +/- 90 deg, where the torus's membrane state has a bending layer
    (zero Gaussian curvature, width ~ (a^2 h)^(1/3)), and from the clamps on the axle side.
    """
    mesh, psi = torus(r0, a, h, n_el=n_el)
    ops = harmonic_operators(mesh, LAW, p)
    pts = mesh.points
    rows = []
    for element in (n_el // 2 - 6, n_el // 2, n_el // 2 + 6):
        mid = (pts.element == element) & np.isclose(pts.xi, 0.0)
        angle = psi[2 * element + 1]
        s_r, s_y = -np.sin(angle), np.cos(angle)
        sig = ops.stress[mid]
        weight = pts.weight[mid] / pts.weight[mid].sum() * h  # through-thickness integration
        r = r0 + a * np.cos(angle)
        rows.append(
            {
                "angle (deg)": np.degrees(angle),
                "N_theta (N/m)": weight @ sig[:, 1],
                "N_theta, membrane (N/m)": p * a / 2,
                "N_phi (N/m)": weight @ (sig[:, 0] * s_r**2 + sig[:, 2] * s_y**2 + 2 * sig[:, 4] * s_r * s_y),
                "N_phi, membrane (N/m)": p * a * (r + r0) / (2 * r),
            }
        )
    table = pd.DataFrame(rows).set_index("angle (deg)")
    table["error N_theta (%)"] = 100 * (table["N_theta (N/m)"] / table["N_theta, membrane (N/m)"] - 1)
    table["error N_phi (%)"] = 100 * (table["N_phi (N/m)"] / table["N_phi, membrane (N/m)"] - 1)
    return table


def three_d_operators(mesh, stress, n_theta):
    """Direct 3-D assembly of the same cross-section with ``n_theta`` stations and spectral theta-derivatives.

    Independent of the harmonic operators: strains and displacement gradients in physical
    components, trapezoidal integration around, Fourier differentiation matrix (odd n_theta,
    Trefethen, *Spectral Methods in MATLAB*, 2000, ch. 3).
    """
    g = point_geometry(mesh.r, mesh.y, mesh.elements, mesh.points)
    q = g.shape.shape[0]
    inv_r = g.shape / g.radius[:, None]
    p0, p1 = np.zeros((q, 6, 9, 3)), np.zeros((q, 6, 9, 3))
    p0[:, 0, :, 0] = g.d_r
    p0[:, 1, :, 0] = inv_r
    p1[:, 1, :, 1] = inv_r
    p0[:, 2, :, 2] = g.d_y
    p0[:, 3, :, 1] = g.d_y
    p1[:, 3, :, 2] = inv_r
    p0[:, 4, :, 0] = g.d_y
    p0[:, 4, :, 2] = g.d_r
    p0[:, 5, :, 1] = g.d_r - inv_r
    p1[:, 5, :, 0] = inv_r
    g0, g1 = np.zeros((q, 3, 3, 9, 3)), np.zeros((q, 3, 3, 9, 3))
    for k in range(3):
        g0[:, k, 0, :, k], g0[:, k, 2, :, k] = g.d_r, g.d_y
        g1[:, k, 1, :, k] = inv_r
    g0[:, 0, 1, :, 1] = -inv_r  # (du_r/dth - u_t)/r
    g0[:, 1, 1, :, 0] = inv_r  # (du_t/dth + u_r)/r
    s = np.zeros((q, 3, 3))
    for col, (i, j) in enumerate(((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))):
        s[:, i, j] = s[:, j, i] = stress[:, col]
    dofs = element_dofs(mesh.elements)[mesh.points.element]
    n = mesh.n_dof

    def assemble(a, b, middle):
        blocks = (
            np.einsum("qia,qij,qjb->qab", a.reshape(q, -1, 27), middle, b.reshape(q, -1, 27)) * g.volume[:, None, None]
        )
        out = np.zeros((n, n))
        np.add.at(out, (dofs[:, :, None], dofs[:, None, :]), blocks)
        return out

    c = mesh.points.stiffness
    big_s = np.einsum("kl,qij->qkilj", np.eye(3), s).reshape(q, 9, 9)
    elastic = [assemble(x, y, c) for x, y in ((p0, p0), (p0, p1), (p1, p1))]
    geometric = [assemble(x, y, big_s) for x, y in ((g0, g0), (g0, g1), (g1, g1))]
    shape = np.zeros((q, 3, 9, 3))
    for k in range(3):
        shape[:, k, :, k] = g.shape
    mass = assemble(shape, shape, np.broadcast_to(np.eye(3) * mesh.points.density[:, None, None], (q, 3, 3)))
    m = np.arange(n_theta)
    diff = m[:, None] - m[None, :]
    with np.errstate(divide="ignore"):
        d = np.where(diff == 0, 0.0, (-1.0) ** diff / (2 * np.sin(np.pi * diff / n_theta)))
    h = 2 * np.pi / n_theta

    def three_d(a00, a01, a11):
        return h * (np.kron(np.eye(n_theta), a00) + np.kron(d, a01) + np.kron(d.T, a01.T) + np.kron(d.T @ d, a11))

    return three_d(*elastic), three_d(*geometric), h * np.kron(np.eye(n_theta), mass)


def three_d_check(n_theta: int = 15, frequency: float = 120.0, hoop_stress: float = 2.0e6) -> float:
    """(e) Largest difference of the vertical receptance, harmonic sum against the 3-D solve, relative (-).

    A clamped band (two elements across, one through) with a hoop pre-stress, the compound law
    at ``frequency`` (Hz); vertical point forces at stations 0 and 3, response at every station.
    """
    mesh = band(n_el=2, poisson=0.3)
    stress = np.zeros((mesh.points.element.size, 6))
    stress[:, 1] = hoop_stress
    ops = harmonic_operators(mesh, LAW, 0.0, prestress=stress)
    omega = 2 * np.pi * frequency
    elastic, geometric, mass = three_d_operators(mesh, stress, n_theta)
    # the pre-stress stiffness is lossless here (no [pneumatic] law; no pressure on the band)
    dynamic = LAW["c"].ratio(omega) * elastic + geometric - omega**2 * mass
    per_station = mesh.n_dof
    free = (np.arange(n_theta)[:, None] * per_station + ops.free[None, :]).ravel()
    node = mesh.node(2, 2)  # mid-width node of the outer face
    dofs = np.array([3 * node, 3 * node + 1])
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    flex = np.stack([direct_receptance(ops, dofs, n, omega) for n in range(n_theta // 2 + 1)])
    sums = angular_sums(flex, theta, 0.0)  # response at theta_m to a force at 0; point forces
    worst = 0.0
    for b in (0, 3):  # a force at station 0 and at station 3 (exercises the r-theta coupling terms)
        f_r, f_t = -np.cos(theta[b]), np.sin(theta[b])
        load = np.zeros(n_theta * per_station, complex)
        load[b * per_station + 3 * node] = f_r
        load[b * per_station + 3 * node + 1] = f_t
        u = np.zeros_like(load)
        u[free] = np.linalg.solve(dynamic[np.ix_(free, free)], load[free])
        u = u.reshape(n_theta, per_station)
        u_z = -np.cos(theta) * u[:, 3 * node] + np.sin(theta) * u[:, 3 * node + 1]
        shifted = sums[(np.arange(n_theta) - b) % n_theta]  # offset theta_m - theta_b
        u_r = shifted[:, 0, 0] * f_r + shifted[:, 0, 1] * f_t
        u_t = shifted[:, 1, 0] * f_r + shifted[:, 1, 1] * f_t
        harmonic = -np.cos(theta) * u_r + np.sin(theta) * u_t
        worst = max(worst, float(np.abs(harmonic - u_z).max() / np.abs(u_z).max()))
    return worst
