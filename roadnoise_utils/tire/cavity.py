"""The tire's air cavity as an acoustic waveguide around the wheel (beyond the paper).

The air between the rim and the belt is a torus; below its first cross-sectional mode (~1 kHz
for a passenger tire) the sound in it is a plane wave running around the circumference, and a
torus of mean radius :math:`R` has its circumferential modes at

.. math:: f_n = \\frac{n\\,c}{2\\pi R}, \\qquad n = 1, 2, \\dots

(the rigid torus; ~200-230 Hz for :math:`n = 1` on passenger tires, inside the paper's band).
Each is a doublet: :math:`\\cos n\\theta` and :math:`\\sin n\\theta` at one frequency.

**Webster's equation.** A duct whose cross-section area :math:`A(s)` varies slowly along its
axis :math:`s = R\\theta` carries :math:`(A p')' + k^2 A p = 0`, :math:`k = \\omega/c`. Loaded,
the footprint flattens the belt and the cavity is shallower there: :math:`A(\\theta)` dips at
:math:`\\theta = 0`, the symmetry is broken and the doublet splits. The even mode (pressure
antinodes at the footprint and the top: its pressure pushes the rim up and down, the
*vertical* mode) loses inertia where it has most pressure and rises; the odd mode (a node at
the footprint, pressure pushing the rim fore and aft) loses stiffness where its pressure
gradient is largest and falls. To first order (Rayleigh's quotient on the unloaded shapes),
with :math:`\\Delta A(\\theta)` the area the loaded belt takes out of the section,

.. math:: \\frac{\\delta f_{v,fa}}{f_1} = \\pm \\frac{1}{2}\\,\\frac{\\int \\Delta A \\cos 2\\theta\\, ds}{\\pi R A},
          \\qquad \\frac{f_v - f_{fa}}{f_1} = \\frac{\\int \\Delta A \\cos 2\\theta\\, ds}{\\pi R A}:

the split weighs the area lost at the footprint (:math:`\\cos 2\\theta = 1`) and the area
*gained* at the front and the back (:math:`\\cos 2\\theta = -1`, where a nearly inextensible
belt bulges out) alike, so the belt's ovalisation splits the doublet more than the volume the
footprint takes out (on the 195/65 R15 at 4000 N: 5.2 Hz against 0.2 Hz from the net volume
change alone; 10.4 Hz on the 165/65 R14 at 4512 N). Measured splits: 4-14 Hz at rated load on passenger tires, nearly quadratic in
the load (Choi & Bolton, INTER-NOISE 2020, pp. 213-228), 2.0-11.2 Hz on 24 tires with a
steeper, up to fourth-order, load dependence (Choi & Bolton, AIP Advances 2026,
doi:10.1063/5.0315230), the fore-aft mode below the vertical one in both. A linear tire model
gives a split linear in the load.

:func:`webster_modes` solves the equation by periodic linear finite elements on any
:math:`A(\\theta)`; :func:`loaded_area` takes :math:`A(\\theta)` from the loaded ring tire's
belt. :func:`ring_cavity_coupling` couples the modes with the ring tire: the belt's radial
motion and the rim's change the cavity's volume, the pressure pushes on both (one matrix, by
reciprocity), and eliminating the pressure leaves a low-rank, frequency-dependent term in the
tire's dynamic stiffness that the fixed-hub FRFs take in (:func:`roadnoise_utils.tire.ring.frf.frf_visco`,
``cavity=``), and through them the fits, G_H and the RM chain when the tire file's
``[cavity] enabled`` is on. :func:`rolling_modes` gives the doublet of the rolling tire and
:func:`rolling_coupling` puts the rolling air into the FRFs (the convected waveguide, the tire's
structure at rest). The cross-section tire's cavity is :mod:`roadnoise_utils.tire.cross_section.cavity` and
:mod:`roadnoise_utils.tire.cross_section.cavity_frf` (at rest). :func:`air_coordinates` makes the modes
coordinates of their own, which the loaded FE tire's modal reduction and one-sided cleat runs step
or reduce with the tire; the ring and the cross-section tires' FE stages that step or reduce the
tire refuse the cavity.

**Limits found so far (a review of the physics):**

* the sidewalls bulge as inextensible arcs (:func:`sidewall_gain`); without them the split was
  19.5 Hz on the 165/65 R14 at its 4512 N, above the measured 2-14 Hz.
* the uniform mode's volume change per unit footprint rise is ~1e-3 m^2 where a real tire's is
  near its contact area (1-2e-2 m^2, the pneumatic work balance): the air's compressibility adds
  1e-4 of K_v instead of ~2 % (the sidewalls' volume change and the dynamic pressure's change of
  the inflation pre-stress are left out).
* the waveguide's area is the section's volume per radian over the centroid's radius in both its
  stiffness and its mass, which puts the rigid torus's modes ~0.65 % low against the uniform
  pressure's Rayleigh quotient with the stiffness weighted by :math:`R_c\\int dA/r` (243.6 against
  242.1 Hz on the 165/65 R14 cross-section), on both tire models.
* the ring tire is calibrated to measured modes, which include the air: the cavity on top lowers
  its first vertical mode by ~3 Hz (80 -> 77 Hz on the 165/65 R14) until it is recalibrated.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp

from .. import guards

#: Ratio of specific heats and specific gas constant of dry air (-, J/(kg K)).
GAMMA_AIR, R_AIR = 1.4, 287.05


def air(temperature: float = 20.0, gauge_pressure: float = 2.3e5, ambient: float = 101325.0) -> tuple[float, float]:
    """Speed of sound (m/s) and density (kg/m^3) of the inflation air (ideal gas) at ``temperature`` (deg C)."""
    t = guards.real("temperature", temperature, -50.0, 150.0, unit="deg C") + 273.15
    p = guards.real("gauge_pressure", gauge_pressure, 0.0, 2.0e6, unit="Pa") + ambient
    return float(np.sqrt(GAMMA_AIR * R_AIR * t)), float(p / (R_AIR * t))


@dataclass(frozen=True)
class Cavity:
    """The unloaded cavity as a waveguide: mean radius (m), cross-section area (m^2), air (m/s, kg/m^3).

    ``inner_radius`` is the rim's and ``outer_radius`` the belt's inner surface: the torus lies
    between them, ``mean_radius`` their mean (the waveguide's axis).
    """

    inner_radius: float
    outer_radius: float
    width: float
    sound_speed: float
    density: float

    def __post_init__(self) -> None:
        guards.real("inner_radius", self.inner_radius, 0.05, 1.0, unit="m")
        guards.real("outer_radius", self.outer_radius, self.inner_radius, 1.5, lo_open=True, unit="m (above the rim's)")
        guards.real("width", self.width, 0.02, 1.0, unit="m")
        guards.real("sound_speed", self.sound_speed, 200.0, 500.0, unit="m/s")
        guards.real("density", self.density, 0.1, 20.0, unit="kg/m^3")

    @property
    def mean_radius(self) -> float:
        return 0.5 * (self.inner_radius + self.outer_radius)

    @property
    def area(self) -> float:
        """Cross-section area (m^2): the section between rim and belt, ``width`` wide."""
        return (self.outer_radius - self.inner_radius) * self.width

    @property
    def volume(self) -> float:
        return 2.0 * np.pi * self.mean_radius * self.area


def rigid_torus_frequencies(cavity: Cavity, orders: np.ndarray | int) -> np.ndarray:
    """:math:`f_n = n c / (2\\pi R)` of the rigid, unloaded torus (Hz)."""
    n = np.atleast_1d(np.asarray(orders, float))
    return n * cavity.sound_speed / (2.0 * np.pi * cavity.mean_radius)


@dataclass(frozen=True, eq=False)
class CavityModes:
    """Modes of the waveguide: frequencies (Hz), pressure shapes (modes, nodes) at ``theta`` (rad,
    from the footprint centre), normalised by the waveguide's mass (:math:`\\phi^T M_a \\phi = 1`,
    :math:`M_a = \\int A N N^T ds`), and each mode's symmetry about the footprint (+1 even, -1 odd)."""

    freqs: np.ndarray
    shapes: np.ndarray
    theta: np.ndarray
    parity: np.ndarray

    def split(self) -> tuple[float, float]:
        """The first doublet: (fore-aft, vertical) frequencies (Hz), the odd and the even mode of ``n = 1``."""
        first = np.argsort(self.freqs)[1:3]  # mode 0 is the uniform pressure (0 Hz)
        by_parity = {int(self.parity[k]): float(self.freqs[k]) for k in first}
        if sorted(by_parity) != [-1, 1]:
            raise RuntimeError("the first doublet is not one even and one odd mode: is the area symmetric about 0?")
        return by_parity[-1], by_parity[1]


def waveguide_matrices(cavity: Cavity, area: np.ndarray) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """Periodic linear elements of Webster's equation on nodes at equal angles: :math:`K_a = \\int A N' N'^T ds`
    and :math:`M_a = \\int A N N^T ds` (element areas the mean of their nodes'), sparse."""
    area = np.asarray(area, float)
    if area.ndim != 1 or area.size < 32 or not np.all(np.isfinite(area)) or np.any(area <= 0):
        raise ValueError("area must be positive and finite at >= 32 equally spaced angles (m^2)")
    n = area.size
    h = 2.0 * np.pi * cavity.mean_radius / n
    a = 0.5 * (area + np.roll(area, -1))  # element e joins nodes e and e + 1
    i, j = np.arange(n), (np.arange(n) + 1) % n
    rows, cols = np.concatenate([i, j, i, j]), np.concatenate([i, j, j, i])
    stiffness = sp.csr_matrix((np.concatenate([a, a, -a, -a]) / h, (rows, cols)), shape=(n, n))
    mass = sp.csr_matrix((np.concatenate([2 * a, 2 * a, a, a]) * h / 6.0, (rows, cols)), shape=(n, n))
    return stiffness, mass


def webster_modes(cavity: Cavity, area: np.ndarray | None = None, n_modes: int = 7) -> CavityModes:
    """Plane-wave modes of the cavity from Webster's equation (:func:`waveguide_matrices`).

    ``area`` (m^2): the cross-section at equally spaced angles from the footprint centre (one per
    element node; default ``cavity.area`` everywhere, 720 nodes). Mode 0 (uniform pressure) is
    included. The discretisation error is ~(n dtheta)^2 / 24 relative (3e-6 at n = 1, 720 nodes).
    """
    area = np.full(720, cavity.area) if area is None else np.asarray(area, float)
    stiffness, mass = waveguide_matrices(cavity, area)
    n = area.size
    k2, shapes = sla.eigh(stiffness.toarray(), mass.toarray(), subset_by_index=[0, min(n_modes, n) - 1])
    theta = 2.0 * np.pi * np.arange(n) / n
    mirror = (-np.arange(n)) % n  # theta -> -theta
    parity = np.sign(np.sum(shapes * shapes[mirror], axis=0))
    freqs = cavity.sound_speed * np.sqrt(np.clip(k2, 0.0, None)) / (2.0 * np.pi)
    return CavityModes(freqs=freqs, shapes=shapes.T, theta=theta, parity=parity.astype(int))


#: Damping ratio of the cavity's plane-wave modes (-): measured cavity resonances of passenger
#: tires have quality factors of ~30-60 (half-power bandwidths of 4-7 Hz at ~220 Hz; e.g. Feng &
#: Gu, IMAC 2011, spindle and cavity-pressure spectra): zeta ~0.01.
DAMPING_RATIO = 0.01


@dataclass(frozen=True, eq=False)
class RollingFlow:
    """The air of the rolling tire streaming through the loaded cavity at ``speed`` :math:`U` (m/s, hub frame),
    in a coupling's modes (:func:`rolling_coupling`).

    ``convection`` :math:`g = \\Phi^T C_A \\Phi` (1/m; :math:`C_A = \\int A N N'^T ds`, :func:`convection_matrix`);
    ``slope`` and ``curvature`` (n_dof, modes): :math:`G^T C_0^T \\Phi^T/\\Delta s` and
    :math:`G^T K_0 \\Phi^T/\\Delta s`, the wall's volume change carried along by the flow
    (:math:`C_0, K_0` the unweighted convection and stiffness matrices, :math:`\\Delta s` the node spacing).
    """

    speed: float
    convection: np.ndarray
    slope: np.ndarray
    curvature: np.ndarray

    def terms(self, coupling: CavityCoupling, omega: float) -> tuple[np.ndarray, np.ndarray]:
        """``(C, W)`` of :meth:`CavityCoupling.terms` at ``omega`` > 0 (rad/s), the air streaming.

        The convected Webster equation with the wall's motion as a volume source seen by the moving air,
        :math:`\\frac{A}{c^2} D_t^2 p - (A p')' = -\\rho D_t^2 q`, :math:`D_t = \\partial_t + U \\partial_s`
        (Myers' condition on a wall the flow runs along: the tire's belt turns with its air), in the modes
        at rest, :math:`p = \\Phi^T a` (:math:`x = \\omega/c`, :math:`\\beta = U/c`):

        .. math:: [(1 - \\beta^2) \\Lambda (1 + 2 i \\zeta) - x^2 I + 2 i x \\beta g]\\, a
                  = \\rho c^2 (x^2 V - 2 i x \\beta V_s + \\beta^2 V_{ss})^T u,

        so :math:`C = \\rho c^2 [\\dots]^{-1}` and :math:`W = x^2 V - 2 i x\\beta V_s + \\beta^2 V_{ss}`; at
        :math:`\\beta = 0` they are :meth:`CavityCoupling.gains` and :math:`V`. The uniform mode's row carries
        :math:`x` on both sides and is divided by it (finite as :math:`\\omega \\to 0`).
        """
        c = coupling.sound_speed
        beta, x = self.speed / c, omega / c
        lam = (coupling.omegas / c) ** 2 * (1.0 + 2j * coupling.damping_ratio)
        operator = (1.0 - beta**2) * np.diag(lam) - x**2 * np.eye(lam.size) + 2j * x * beta * self.convection
        wall = x**2 * coupling.volume - 2j * x * beta * self.slope + beta**2 * self.curvature
        uniform = coupling.omegas == 0.0
        operator[uniform] /= x
        wall[:, uniform] /= x
        return coupling.density * c**2 * np.linalg.inv(operator), wall


@dataclass(frozen=True, eq=False)
class CavityCoupling:
    """The cavity's modes coupled to a ring tire's DOF (all of them, hub included).

    ``wall`` (nodes, n_dof): the volume change at each waveguide node per unit displacement of
    each DOF (m^3/m; :math:`G`), ``area`` the loaded section at the nodes (m^2);
    ``volume`` (n_dof, modes): the modal volume change per unit displacement of each DOF,
    :math:`\\Phi^T G` transposed (m^3 per m, in the modes' normalisation); ``omegas`` the modes'
    angular frequencies on the loaded area (rad/s; the first is the uniform pressure, 0).

    Eliminating the pressure, :math:`p = \\rho\\omega^2 c^2 \\sum_m \\phi_m \\phi_m^T G u /
    (\\omega_m^2 (1 + 2 i \\zeta) - \\omega^2)`, adds to the tire's dynamic stiffness the
    low-rank, frequency-dependent term :math:`-V\\,\\mathrm{diag}(c_m(\\omega))\\,V^T`
    (:meth:`gains`): the air's stiffness and inertia seen by the belt and the rim.
    """

    volume: np.ndarray
    omegas: np.ndarray
    density: float
    sound_speed: float
    damping_ratio: float
    modes: CavityModes
    wall: sp.csr_matrix
    area: np.ndarray
    flow: RollingFlow | None = None

    def gains(self, omega: float) -> np.ndarray:
        """:func:`modal_gains` of these modes at ``omega`` (rad/s), the cavity at rest."""
        return modal_gains(self.omegas, omega, self.density, self.sound_speed, self.damping_ratio)

    @property
    def rolling(self) -> bool:
        """Whether the air streams through the footprint (:func:`rolling_coupling`)."""
        return self.flow is not None and self.flow.speed != 0.0

    def terms(self, omega: float) -> tuple[np.ndarray, np.ndarray]:
        """``(C, W)``: the cavity adds :math:`-V C W^T` to the tire's dynamic stiffness at ``omega`` (rad/s).

        At rest :math:`C = \\mathrm{diag}(c_m)` (:meth:`gains`) and :math:`W = V` (reciprocity);
        rolling, :math:`C` and :math:`W` are those of the convected waveguide (:class:`RollingFlow`).
        """
        if (
            not self.rolling or omega == 0.0
        ):  # at 0 Hz: the air's compressibility (the flow's O(beta^2) static pressure left out)
            return np.diag(self.gains(omega)), self.volume
        return self.flow.terms(self, omega)


def modal_gains(
    omegas: np.ndarray, omega: float, density: float, sound_speed: float, damping_ratio: float
) -> np.ndarray:
    """:math:`c_m(\\omega) = \\rho c^2 \\omega^2 / (\\omega_m^2 (1 + 2 i \\zeta) - \\omega^2)` (Pa/m^3 in
    modal units) of modes at ``omegas`` (rad/s); the uniform mode's (``omegas == 0``) is
    :math:`-\\rho c^2` (the air's compressibility). The modes are normalised by the waveguide's mass."""
    rc2 = density * sound_speed**2
    omegas = np.asarray(omegas, float)
    out = np.empty(omegas.size, complex)
    rigid = omegas == 0.0
    out[rigid] = -rc2
    w2 = omegas[~rigid] ** 2 * (1.0 + 2j * damping_ratio)
    out[~rigid] = rc2 * omega**2 / (w2 - omega**2)
    return out


def rolling_modes(
    cavity: Cavity, area: np.ndarray, flow_speed: float, n_basis: int = 13
) -> tuple[np.ndarray, np.ndarray]:
    """Plane-wave frequencies (Hz) of the loaded cavity whose air streams through the fixed footprint.

    Rolling, the air turns with the tire while the loaded section :math:`A(\\\\theta)` stays put under
    the axle: seen from the hub the air flows around the waveguide at ``flow_speed``
    :math:`U = \\\\Omega R` (m/s). The convected Webster equation
    :math:`\\\\frac{1}{c^2}(\\\\partial_t + U\\\\partial_s)^2 p = \\\\frac{1}{A}(A p')'` couples the standing
    waves, and on a uniform torus each doublet becomes two travelling waves at
    :math:`f_n (1 \\\\pm U/c)`: the doublet's split, the footprint's at rest, turns into one that
    grows with the speed. With :math:`U = \\Omega R` the shift :math:`f_1 U/c` is the wheel's rotation
    frequency :math:`\\Omega/2\\pi` whatever the size, and on the loaded torus the first doublet is
    close to :math:`\\bar f \\pm \\sqrt{(\\Delta_0/2)^2 + (\\Omega/2\\pi)^2}` (:math:`\\Delta_0` its split at
    rest). Solved on the ``n_basis`` lowest modes at rest (the quadratic eigenvalue problem
    linearised); returns the frequencies at rest and rolling, both ascending, from the first doublet
    on (the uniform mode left out).
    """
    beta = guards.real("flow_speed", flow_speed, 0.0, 0.5 * cavity.sound_speed, unit="m/s (half the speed of sound)")
    beta /= cavity.sound_speed
    stiffness, _ = waveguide_matrices(cavity, area)
    convection = convection_matrix(flux_area(area))
    rest = webster_modes(cavity, area, n_basis)
    phi = rest.shapes.T  # (n, m), mass-normalised
    lam = np.diag(phi.T @ (stiffness @ phi))  # k_m^2 (1/m^2)
    g = phi.T @ (convection @ phi)  # skew-symmetric
    # (x^2 - 2 i beta x g... ) in x = omega / c: x^2 I - 2 i beta x G - (1 - beta^2) K = 0, linearised
    m = lam.size
    companion = np.block([[np.zeros((m, m)), np.eye(m)], [(1.0 - beta**2) * np.diag(lam), 2j * beta * g]])
    x = np.linalg.eigvals(companion)
    # the uniform mode's double root at 0 (and round-off about it) is left out
    freqs = np.sort(x.real[x.real > 1e-3 * np.sqrt(lam[1])]) * cavity.sound_speed / (2.0 * np.pi)
    return rest.freqs[1:], freqs[: m - 1]


def convection_matrix(area: np.ndarray) -> sp.csr_matrix:
    """:math:`C_A = \\int A N N'^T ds` of :func:`waveguide_matrices`' periodic linear elements (-, times m^2):
    on each element :math:`[[-1, 1], [-1, 1]]\\, a/2` (``a`` the element's mean area)."""
    area = np.asarray(area, float)
    n = area.size
    a = 0.5 * (area + np.roll(area, -1))
    i, j = np.arange(n), (np.arange(n) + 1) % n
    rows, cols = np.concatenate([i, i, j, j]), np.concatenate([i, j, i, j])
    return sp.csr_matrix((np.concatenate([-a, a, -a, a]) / 2.0, (rows, cols)), shape=(n, n))


def flux_area(area: np.ndarray) -> np.ndarray:
    """The convection's weight :math:`A U / \\bar U` (m^2): the mean section everywhere, the air's mass flux
    :math:`A(s) U(s)` being the same through every section (mean-flow continuity: faster where the footprint
    narrows the cavity) with :math:`U` its mean speed."""
    area = np.asarray(area, float)
    return np.full(area.shape, area.mean())


def rolling_coupling(coupling: CavityCoupling, cavity: Cavity, flow_speed: float) -> CavityCoupling:
    """``coupling`` with its air streaming through the footprint at ``flow_speed`` (m/s): the rolling tire's cavity.

    Rolling, the air turns with the wheel while the loaded section stays under the axle: seen from the
    hub it flows around the waveguide at :math:`U = \\Omega R` (:func:`rolling_modes`). The coupled FRFs
    (:func:`roadnoise_utils.tire.ring.frf.frf_visco`) then carry the rolling doublet instead of the one at rest; the
    flow mixes the even (vertical) and odd (fore-aft) modes, so the FRFs are solved without the
    mirror-symmetric reduction. The tire's structure is the paper's, linearised about the tire at
    rest (its own gyroscopic and centrifugal terms are left out; the belt mode the cavity's
    vertical mode sits beside would split with the speed too, an effect at least as large as the
    air's); the air's convection is the change. ``flow_speed = 0`` gives the coupling at rest.

    The convection carries the mean flow's continuity (:func:`flux_area`: its first-order term);
    its second-order term :math:`\\beta^2` keeps the section's weight and the wall's source
    omits :math:`U' q`, together ~1-2 % of the rolling FRF's peak. At
    0 Hz the coupling falls back to the air's compressibility at rest: the flow's static pressure,
    ~0.2 % of the hub's own stiffness just above 0 Hz, is left out.
    """
    speed = guards.real("flow_speed", flow_speed, 0.0, 0.5 * cavity.sound_speed, unit="m/s (half the speed of sound)")
    if speed == 0.0:
        return replace(coupling, flow=None)
    n = coupling.area.size
    spacing = 2.0 * np.pi * cavity.mean_radius / n
    ones = np.ones(n)
    phi = coupling.modes.shapes.T  # (nodes, modes)
    stiffness0, _ = waveguide_matrices(cavity, ones)
    flow = RollingFlow(
        speed=speed,
        convection=phi.T @ (convection_matrix(flux_area(coupling.area)) @ phi),
        slope=np.asarray(coupling.wall.T @ (convection_matrix(ones).T @ phi)) / spacing,
        curvature=np.asarray(coupling.wall.T @ (stiffness0 @ phi)) / spacing,
    )
    return replace(coupling, flow=flow)


@dataclass(frozen=True, eq=False)
class AirCoordinates:
    """The cavity's resonant modes as coordinates of their own, appended to a model's ``r`` coordinates.

    Eliminating them gives back the low-rank term :math:`-V C(\\omega) V^T` of
    :meth:`CavityCoupling.terms` (at rest): each resonant mode ``m`` is a mass
    :math:`\\rho c^2/\\omega_m^2` on a spring :math:`\\rho c^2` driven by the volume change
    :math:`V_m^T q`, and the uniform pressure a spring :math:`\\rho c^2 V_0 V_0^T` alone. The
    elastic part of the mode's pressure amplitude is :math:`-\\rho c^2 (V_m^T q - s_m b_m)`, ``b_m``
    its coordinate.

    * ``causal=False`` (the FRFs' air): :math:`s_m = \\sqrt{1 + 2 i \\zeta}` and the spring
      :math:`\\rho c^2 (1 + 2 i \\zeta)` on ``b_m``; eliminating ``b_m`` gives
      :math:`c_m = \\rho c^2\\omega^2/(\\omega_m^2(1 + 2 i\\zeta) - \\omega^2)` exactly, at every
      frequency (a constant complex stiffness: fit for a frequency-domain or frozen model; it has
      a pole in the right half-plane and no causal impulse response).
    * ``causal=True`` (for time stepping): :math:`s_m = 1`, lossless springs, and a dashpot
      :math:`\\zeta\\rho c^2/(2\\omega_m)` on :math:`V_m^T q - 2 b_m`, which adds
      :math:`\\zeta\\rho c^2/(2\\omega_m)(V_m^T\\dot q - 2\\dot b_m)` to the pressure's amplitude.
      Eliminated,
      :math:`c_m = \\rho c^2 (\\omega^2 - i\\zeta\\omega(\\omega_m^2 - \\omega^2)/(2\\omega_m)) / (\\omega_m^2 + 2i\\zeta\\omega_m\\omega - \\omega^2)`:
      the hysteretic gain exactly at the mode's own frequency. Among the passive dashpots on the
      mode's two motions (:math:`V_m^T q` and :math:`b_m`) that are exact there, this rank-one one
      has the least loss below the resonance: about :math:`\\zeta\\omega_m/(2\\omega) + 2\\zeta\\omega/\\omega_m`
      of the air's inertia against the hysteretic :math:`2\\zeta` (0.024 against 0.021 at a quarter of
      the mode's frequency). A dashpot on :math:`V_m^T q - b_m` gives :math:`1 + 2i\\zeta` times the
      hysteretic gain at resonance, one on ``b_m`` alone :math:`1 - 2i\\zeta` times; the viscous
      oscillator's own gain, :math:`\\rho c^2\\omega^2/(\\omega_m^2 + 2i\\zeta\\omega_m\\omega - \\omega^2)`, needs a
      third, massless node (a spring and a dashpot in series), and is farther from the hysteretic
      gain below the resonance (on the loaded FE test tire, :math:`H_{tot}` 3.3e-3 of its peak off
      below 100 Hz, against 5.6e-5 for this form; both 0.8 % near the resonance).

    Attributes
    ----------
    stiffness : ndarray (r + a, r + a)
        The air's stiffness on the model's coordinates and its own (N/m in modal units; complex
        unless ``causal``).
    mass : ndarray (a,)
        The resonant modes' masses.
    damping : ndarray (r + a, r + a) or None
        The dashpots (``causal`` only).
    pressure, pressure_rate : ndarray (modes, r + a)
        Each mode's pressure amplitude per coordinate and per coordinate velocity (zero unless
        ``causal``), :math:`a = P [q; b] + P_v [\\dot q; \\dot b]` (the coupling's normalisation: the
        force on the model's coordinates is :math:`V a`).
    """

    stiffness: np.ndarray
    mass: np.ndarray
    damping: np.ndarray | None
    pressure: np.ndarray
    pressure_rate: np.ndarray

    @property
    def size(self) -> int:
        """How many coordinates the air adds."""
        return self.mass.size


def air_coordinates(coupling: CavityCoupling, causal: bool = False, lossless: bool = False) -> AirCoordinates:
    """:class:`AirCoordinates` of the coupling's modes at rest (``lossless``: every mode undamped)."""
    if coupling.rolling:
        raise ValueError(
            "coupling: the air's coordinates are those of the cavity at rest; valid couplings have no flow"
        )
    volume = np.asarray(coupling.volume)
    rc2 = coupling.density * coupling.sound_speed**2
    resonant = coupling.omegas > 0.0
    omegas = coupling.omegas[resonant]
    r, a = volume.shape[0], int(resonant.sum())
    zeta = 0.0 if lossless else coupling.damping_ratio
    scale = np.ones(a) if causal else np.full(a, np.sqrt(1.0 + 2j * zeta))
    drive = np.vstack([volume[:, resonant], -np.diag(scale)])  # (r + a, a): V_m^T q - s_m b_m
    uniform = np.vstack([volume[:, ~resonant], np.zeros((a, int((~resonant).sum())))])
    stiffness = rc2 * (drive @ drive.T + uniform @ uniform.T)
    pressure = np.zeros((volume.shape[1], r + a), float if causal else complex)
    pressure[resonant] = -rc2 * drive.T
    pressure[~resonant] = -rc2 * uniform.T
    rate, damping = np.zeros((volume.shape[1], r + a)), None
    if causal:
        dashpot = np.vstack([volume[:, resonant], -2.0 * np.eye(a)])  # V_m^T q - 2 b_m
        coefficient = zeta * rc2 / (2.0 * omegas)
        damping = (dashpot * coefficient) @ dashpot.T
        rate[resonant] = -coefficient[:, None] * dashpot.T
    return AirCoordinates(stiffness=stiffness, mass=rc2 / omegas**2, damping=damping, pressure=pressure,
                          pressure_rate=rate)  # fmt: skip
