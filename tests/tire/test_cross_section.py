"""The cross-section (waveguide) FE tire: element checks against closed forms and a 3-D assembly.

Issue 13, verification (a), (b), (e) and the element properties; the loaded tire is in
``test_section_static.py``.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from roadnoise_utils.tire import laminate
from roadnoise_utils.tire.closed_form import RingParameters, ring_frequencies
from roadnoise_utils.tire.rubber import FractionalZener
from roadnoise_utils.tire.section_mesh import Ply, structured_mesh
from roadnoise_utils.tire.section_model import harmonic_operators
from roadnoise_utils.tire.waveguide import face_springs, harmonic_weight, pressure_operators

LAW = {"c": FractionalZener(2.0, 1e-4, 0.5)}


def _band(radius=0.3, width=0.1, thickness=0.002, modulus=2e9, density=1200.0, n_el=6, poisson=0.0):
    """A thin cylindrical band: one layered element through the thickness, ``n_el`` across."""
    y = np.linspace(-width / 2, width / 2, 2 * n_el + 1)
    r = np.linspace(radius - thickness / 2, radius + thickness / 2, 3)
    node_r, node_y = np.meshgrid(r, y)
    ply = Ply("ring", 1.0, laminate.isotropic(modulus, poisson), density, "c")
    return structured_mesh(node_r, node_y, [[[ply]] for _ in range(n_el)])


def _eig(ops, n, extra=None):
    free = ops.free
    k = ops.stiffness(n, storage_only=True)
    if extra is not None:
        k = k + harmonic_weight(n) * extra
    k = k.toarray()[np.ix_(free, free)]
    m = ops.mass_matrix(n).toarray()[np.ix_(free, free)]
    return np.sqrt(np.abs(sla.eigh(k, m, eigvals_only=True))) / (2 * np.pi)


def test_thin_ring_on_foundation_matches_the_closed_form():
    """(a) One thin stiff layer, tension and follower pressure, radial/tangential foundation: DESIGN section 2."""
    radius, width, h, e, rho = 0.3, 0.1, 0.002, 2e9, 1200.0
    tension, k_r, k_t = 2000.0, 1.5e5, 2.0e5  # N, N/m^2, N/m^2 (per unit length of ring)
    mesh = _band(radius, width, h, e, rho)
    inner = radius - h / 2
    stress = np.zeros((mesh.points.element.size, 6))
    stress[:, 1] = tension / (width * h)  # hoop pre-stress
    pressure = tension / (inner * width)  # the pressure that balances it on the inner face
    # in-plane ring: u_y held (the closed form has no lateral motion)
    ops = harmonic_operators(mesh, LAW, pressure, fixed=np.arange(2, mesh.n_dof, 3), prestress=stress)
    springs = face_springs(mesh.r, mesh.y, mesh.face_lines(0), k_r / width, k_t / width, mesh.n_dof)
    ring = RingParameters(
        radius, e * width * h**3 / 12, tension, k_r * radius / inner, k_t * radius / inner, rho * width * h
    )
    ours = np.array([_eig(ops, n, springs)[0] for n in range(1, 7)])
    closed = ring_frequencies(np.arange(1, 7), ring)
    assert np.max(np.abs(ours / closed - 1)) < 0.01


def test_free_thin_ring_bending_frequencies():
    """(a) Without tension or foundation the flexural modes n = 2..6 agree to 0.1 %."""
    mesh = _band()
    ops = harmonic_operators(
        mesh, LAW, 0.0, fixed=np.arange(2, mesh.n_dof, 3), prestress=np.zeros((mesh.points.element.size, 6))
    )
    ring = RingParameters(0.3, 2e9 * 0.1 * 0.002**3 / 12, 0.0, 0.0, 0.0, 1200.0 * 0.1 * 0.002)
    for n in range(2, 7):
        assert _eig(ops, n)[0] == pytest.approx(ring_frequencies(n, ring), rel=1e-3)


def test_rigid_body_motions_store_no_strain_energy():
    """The strain operators: translation (n = 0 along y, n = 1 across) and rotation about the axle are free."""
    mesh = _band(n_el=3, poisson=0.3)
    ops = harmonic_operators(mesh, LAW, 0.0, fixed=np.array([], int), prestress=np.zeros((mesh.points.element.size, 6)))
    k0, k1 = ops.stiffness(0, storage_only=True), ops.stiffness(1, storage_only=True)
    axial = np.zeros(mesh.n_dof)
    axial[2::3] = 1.0
    spin = np.zeros(mesh.n_dof)
    spin[1::3] = mesh.r  # u_theta = r
    across = np.zeros(mesh.n_dof)
    across[0::3], across[1::3] = 1.0, -1.0  # u = e_r cos - e_t sin: a rigid translation
    scale = abs(k0).max()
    for k, u in ((k0, axial), (k0, spin), (k1, across)):
        assert np.abs(k @ u).max() < 1e-9 * scale * np.abs(u).max()


def test_pressure_volume_matches_the_exact_deformed_volume():
    """The load stiffness is -p times the Hessian of the volume: second-order volume of a ring deformation."""
    mesh = _band(n_el=4)
    dv, h0, h1 = pressure_operators(mesh.r, mesh.y, mesh.face_lines(0), mesh.n_dof)
    inner, width = 0.3 - 0.001, 0.1
    assert harmonic_weight(0) * dv[0::3].sum() == pytest.approx(2 * np.pi * inner * width)
    theta = np.linspace(0, 2 * np.pi, 4001)[:-1]
    for n, a_r, a_t in ((2, 1.0, -0.5), (3, 0.7, 0.4)):
        a = np.zeros(mesh.n_dof)
        a[0::3], a[1::3] = a_r, a_t
        ours = harmonic_weight(n) * 0.5 * a @ ((h0 + n * h1) @ a)

        # exact area inside the curve r = inner + u_r, tangential u_t, second order in the amplitude
        def area(eps, n=n, a_r=a_r, a_t=a_t):
            ur, ut = eps * a_r * np.cos(n * theta), eps * a_t * np.sin(n * theta)
            x = (inner + ur) * np.cos(theta) - ut * np.sin(theta)
            z = (inner + ur) * np.sin(theta) + ut * np.cos(theta)
            dx = np.gradient(np.concatenate([x[-1:], x, x[:1]]), 2 * np.pi / theta.size)[1:-1]
            dz = np.gradient(np.concatenate([z[-1:], z, z[:1]]), 2 * np.pi / theta.size)[1:-1]
            return 0.5 * np.mean(x * dz - z * dx) * 2 * np.pi

        eps = 1e-3
        exact = width * (area(eps) + area(-eps) - 2 * area(0.0)) / (2 * eps**2)
        assert ours == pytest.approx(exact, rel=1e-5)


def _torus(r0=0.2, a=0.05, h=0.0005, n_el=21, gap=0.5):
    """A thin isotropic torus of circular section, open over ``gap`` rad on the axle side (the beads)."""
    psi = np.linspace(-(np.pi - gap / 2), np.pi - gap / 2, 2 * n_el + 1)
    offset = np.array([-h / 2, 0.0, h / 2])
    node_r = (r0 + a * np.cos(psi))[:, None] + np.cos(psi)[:, None] * offset[None, :]
    node_y = (a * np.sin(psi))[:, None] + np.sin(psi)[:, None] * offset[None, :]
    ply = Ply("shell", 1.0, laminate.isotropic(2e9, 0.3), 1000.0, "c")
    return structured_mesh(node_r, node_y, [[[ply]] for _ in range(n_el)]), psi


def test_inflated_torus_carries_the_membrane_forces():
    """(b) Linear inflation of a thin torus: N_theta = p a / 2 and N_phi = p a (r + R0) / (2 r) (membrane theory,
    Timoshenko & Woinowsky-Krieger, *Theory of Plates and Shells*, 1959, section 107)."""
    r0, a, h, p = 0.2, 0.05, 0.0005, 1.0e5
    mesh, psi = _torus(r0, a, h, n_el=41)
    ops = harmonic_operators(mesh, LAW, p)
    pts = mesh.points
    n_el = mesh.elements.shape[0]
    # the crown and +/- 40 deg: away from the parallels at +/- 90 deg, where the torus's membrane state has a
    # bending layer (zero Gaussian curvature, width ~ (a^2 h)^(1/3) = 11 mm), and from the clamps
    for element in (n_el // 2, n_el // 2 - 6, n_el // 2 + 6):
        mid = (pts.element == element) & np.isclose(pts.xi, 0.0)
        angle = psi[2 * element + 1]
        s_r, s_y = -np.sin(angle), np.cos(angle)
        sig = ops.stress[mid]
        weight = pts.weight[mid] / pts.weight[mid].sum() * h  # through-thickness integration
        n_theta = weight @ sig[:, 1]
        n_phi = weight @ (sig[:, 0] * s_r**2 + sig[:, 2] * s_y**2 + 2 * sig[:, 4] * s_r * s_y)
        r = r0 + a * np.cos(angle)
        assert n_theta == pytest.approx(p * a / 2, rel=0.015)
        assert n_phi == pytest.approx(p * a * (r + r0) / (2 * r), rel=0.015)


def _three_d_operators(mesh, stress, n_theta):
    """Direct 3-D assembly of the same cross-section with ``n_theta`` stations and spectral theta-derivatives.

    Independent of the harmonic operators: strains and displacement gradients in physical
    components, trapezoidal integration around, Fourier differentiation matrix (odd n_theta,
    Trefethen, *Spectral Methods in MATLAB*, 2000, ch. 3).
    """
    from roadnoise_utils.tire.waveguide import element_dofs, point_geometry

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


def test_harmonic_sum_equals_a_direct_three_d_assembly():
    """(e) Receptance of a clamped band under a vertical point force: harmonic sum = 3-D solve to 1e-6."""
    from roadnoise_utils.tire.section_contact import angular_sums
    from roadnoise_utils.tire.section_dynamics import direct_receptance

    mesh = _band(n_el=2, poisson=0.3)
    stress = np.zeros((mesh.points.element.size, 6))
    stress[:, 1] = 2.0e6  # hoop pre-stress (Pa)
    ops = harmonic_operators(mesh, LAW, 0.0, prestress=stress)
    n_theta, omega = 15, 2 * np.pi * 120.0
    elastic, geometric, mass = _three_d_operators(mesh, stress, n_theta)
    # the layer's law scales its elastic and its pre-stress stiffness (section_model)
    dynamic = LAW["c"].ratio(omega) * (elastic + geometric) - omega**2 * mass
    per_station = mesh.n_dof
    free_section = ops.free
    free = (np.arange(n_theta)[:, None] * per_station + free_section[None, :]).ravel()
    node = mesh.node(2, 2)  # mid-width node of the outer face
    dofs = np.array([3 * node, 3 * node + 1])
    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    flex = np.stack([direct_receptance(ops, dofs, n, omega) for n in range(n_theta // 2 + 1)])
    sums = angular_sums(flex, theta, 0.0)  # response at theta_m to a force at 0; point forces
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
        assert np.abs(harmonic - u_z).max() < 1e-6 * np.abs(u_z).max()
