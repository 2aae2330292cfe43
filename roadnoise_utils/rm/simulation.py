"""Fast time-domain simulation of the (block-diagonal) state-space tire.

The fixed-hub tire of Eq. 3 has ~1000 states but a block-diagonal :math:`A_F`: every
tassello, every pole pair, is an independent second-order system driven by one input. We
exploit it instead of stepping a dense 1000-state recursion:

1. the state matrix is split into its independent blocks (connected components of its
   sparsity pattern) and each small block is diagonalised, unless its eigenvectors are
   ill-conditioned (a repeated pole, a Jordan chain, poles a hair apart: the modal gains
   would be huge and cancel), in which case the block is stepped by its exact discretisation
   (:class:`ExactBlock`);
2. each mode is discretised *exactly* for an input that varies linearly between samples
   (first-order hold, FOH; the same assumption as python-control's ``forced_response``):
   :math:`x_{k+1} = e^{p h} x_k + \\gamma_0 v_k + \\gamma_1 v_{k+1}`;
3. a conjugate pair becomes one real second-order IIR section, a real pole a first-order one,
   run by ``scipy.signal.lfilter`` (compiled), and the sections' outputs are summed.

No Python loop over time steps or states; the cost is one IIR pass per pole pair. The result
equals python-control's ``forced_response`` on the same model to round-off (tested).
"""

from __future__ import annotations

from dataclasses import dataclass

import control
import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.signal import lfilter
from scipy.sparse.csgraph import connected_components

from .. import guards
from ..parallel import thread_map
from ..road.input import RoadInput

#: Parts the IIR sections are run in (on :func:`..parallel.threads` threads: scipy's lfilter releases the GIL).
PARTS = 2
#: Modes of :func:`response` stepped and summed together (their histories are held at once).
MODES_AT_ONCE = 16
#: Largest condition number of a (balanced) block's eigenvectors for which it is simulated as
#: modal sections. The sections' gains then cancel by at most this factor, so round-off stays
#: below ~1e-10 of the response (the whole car's 74-state block, balanced: 1.6e5); a block above it
#: (defective or nearly so) is an :class:`ExactBlock`.
CONDITION_LIMIT = 3e5


@dataclass(frozen=True)
class Section:
    """One first-order (real pole) or second-order (conjugate pair) modal section.

    ``pole`` (1/s), ``gain`` (output per unit modal input: residue x input weight), ``source``
    the input it is driven by.
    """

    pole: complex
    gain: complex
    source: int


@dataclass(frozen=True, eq=False)
class ExactBlock:
    """A block of the state matrix that cannot be diagonalised safely (repeated poles, a Jordan
    chain), stepped by its exact FOH discretisation.

    ``a`` (m, m) the block, balanced; ``b`` (m, n_inputs) its input matrix; ``c`` (n_outputs, m)
    its output matrix. :meth:`output` is exact for any ``a``: the discretisation of
    ``scipy.linalg.expm`` (as ``forced_response`` and ``scipy.signal.lsim`` do), then the
    discrete recursion in the complex Schur basis of the step matrix, one first-order filter
    per state from the last to the first (upper triangular: each is driven by the ones after it).
    """

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray

    @classmethod
    def balanced(cls, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> ExactBlock:
        """The block with its states scaled to balance ``a`` (a companion form's entries span decades)."""
        balanced_a, (scale, _) = sla.matrix_balance(a, permute=False, separate=True)
        return cls(balanced_a, b / scale[:, None], np.atleast_2d(c) * scale[None, :])

    def output(self, u: np.ndarray, dt: float) -> np.ndarray:
        """Outputs (n_outputs, n_samples) for inputs ``u`` (n_inputs, n_samples) from rest, FOH, step ``dt``."""
        m = self.a.shape[0]
        # the drive, its Schur form and the states are held whole (complex: 16 bytes a value)
        guards.check_memory(56.0 * m * u.shape[1], f"the exact simulation of a {m}-state block", "the inputs' length")
        v = self.b @ u  # the block's drive, piecewise linear as u
        augmented = np.zeros((3 * m, 3 * m))
        augmented[:m, :m], augmented[:m, m : 2 * m], augmented[m : 2 * m, 2 * m :] = (
            self.a * dt,
            np.eye(m) * dt,
            np.eye(m),
        )
        step = sla.expm(augmented)
        ad, bd1 = step[:m, :m], step[:m, 2 * m :]
        bd0 = step[:m, m : 2 * m] - bd1
        # x[k+1] = Ad x[k] + Bd0 v[k] + Bd1 v[k+1]; w = x - Bd1 v: w[k+1] = Ad w[k] + (Ad Bd1 + Bd0) v[k]
        t, q = sla.schur(ad.astype(complex), output="complex")
        drive = q.conj().T @ ((ad @ bd1 + bd0) @ v)
        start = -(q.conj().T @ (bd1 @ v[:, 0]))  # x[0] = 0
        z = np.empty_like(drive)
        for i in range(m - 1, -1, -1):
            z[i] = lfilter([0.0, 1.0], [1.0, -t[i, i]], drive[i] + t[i, i + 1 :] @ z[i + 1 :], zi=[start[i]])[0]
        return (self.c @ q @ z).real + self.c @ (bd1 @ v)


def well_conditioned(block: np.ndarray) -> bool:
    """Whether a block's eigenvectors are independent enough to simulate it as modal sections.

    Judged on the block balanced (states rescaled, :func:`scipy.linalg.matrix_balance`): a model in
    physical units (positions in m, velocities in m/s, a 1000 rad/s mode) has eigenvectors whose
    condition number is set by those units, not by how close the block is to defective.
    """
    if block.shape[0] == 1:
        return True
    _, vectors = np.linalg.eig(sla.matrix_balance(block, permute=False)[0])
    return bool(np.linalg.cond(vectors) <= CONDITION_LIMIT)


@dataclass(frozen=True, eq=False)
class ModalSections:
    """A state-space model as parallel modal sections plus its direct term.

    Build with :func:`modal_sections`; it is the form :func:`simulate` runs. ``blocks``: the
    blocks of the state matrix simulated exactly instead (:class:`ExactBlock`; none in a fitted tire).
    """

    sections: list[Section]
    direct: np.ndarray  # (n_inputs,) feedthrough to the (single) output
    n_inputs: int
    n_states: int
    blocks: tuple[ExactBlock, ...] = ()


def modal_sections(system: control.StateSpace, tol: float = 1e-12) -> ModalSections:
    """Split a single-output state-space model into independent modal sections.

    The state matrix is divided into blocks that do not interact (connected components of its
    sparsity pattern); each block is diagonalised on its own, so a block-diagonal model of any
    size costs nothing but its small blocks. A block whose eigenvectors are ill-conditioned
    (:data:`CONDITION_LIMIT`) is kept whole as an :class:`ExactBlock`.
    """
    system = as_continuous_statespace(system)
    if system.noutputs != 1:
        raise ValueError(f"simulate needs a single-output model (the hub force), got {system.noutputs} outputs")
    a, b, c, d = (np.asarray(m, dtype=float) for m in (system.A, system.B, system.C, system.D))
    n = a.shape[0]
    pattern = sp.csr_matrix(np.abs(a) > 0) + sp.identity(n, format="csr")
    n_blocks, labels = connected_components(pattern, directed=False)
    sections: list[Section] = []
    blocks: list[ExactBlock] = []
    poles: list[complex] = []
    for block in range(n_blocks):
        idx = np.nonzero(labels == block)[0]
        lam, vec = np.linalg.eig(a[np.ix_(idx, idx)])
        poles += list(lam)
        if not well_conditioned(a[np.ix_(idx, idx)]):
            blocks.append(ExactBlock.balanced(a[np.ix_(idx, idx)], b[idx, :], c[:1, idx]))
            continue
        b_modal = np.linalg.solve(vec, b[idx, :])
        c_modal = c[0, idx] @ vec
        scale = max(np.max(np.abs(lam)), 1.0)
        for k, p in enumerate(lam):
            if p.imag < -tol * scale:
                continue  # the conjugate partner of a pair handled with its upper member
            for source in np.nonzero(np.abs(b_modal[k]) > tol * np.max(np.abs(b_modal)))[0]:
                gain = c_modal[k] * b_modal[k, source]
                if abs(p.imag) <= tol * scale:
                    sections.append(Section(complex(p.real), complex(gain.real), int(source)))
                else:
                    sections.append(Section(complex(p), complex(gain), int(source)))
    unstable = [p for p in poles if p.real > 0]
    if unstable:
        guards.warn(
            f"the model has {len(unstable)} unstable pole(s) (largest real part {max(p.real for p in unstable):.3g} 1/s): "
            "its response grows without bound; a tire model should be stable"
        )
    return ModalSections(sections=sections, direct=d[0].copy(), n_inputs=b.shape[1], n_states=n, blocks=tuple(blocks))


def foh_coefficients(pole: complex, dt: float) -> tuple[complex, complex, complex]:
    """``(E, g0, g1)`` of the exact FOH discretisation of ``x' = p x + v``.

    :math:`E = e^{ph}`, :math:`\\gamma_1 = (E - 1 - ph)/(p^2 h)`, :math:`\\gamma_0 = (E-1)/p - \\gamma_1`;
    a Taylor series replaces the cancelling closed form for small :math:`|ph|`.
    """
    z = pole * dt
    e = np.exp(z)
    if abs(z) < 0.1:
        terms = np.array([z**k for k in range(10)])
        fact = np.array([float(np.prod(np.arange(1, k + 1))) for k in range(12)])
        g1 = dt * np.sum(terms / fact[2:12])  # (e - 1 - z)/z^2 = sum z^k/(k+2)!
        first = dt * np.sum(terms / fact[1:11])  # (e - 1)/z = sum z^k/(k+1)!
    else:
        g1 = dt * (np.expm1(z) - z) / z**2
        first = dt * np.expm1(z) / z
    return complex(e), complex(first - g1), complex(g1)


def section_filter(section: Section, dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Real IIR coefficients (b, a) of a section's FOH response, and the filter state that starts it at rest.

    ``lfilter`` with zero initial conditions would let the input ramp up from 0 during the
    step before the first sample; the returned ``zi`` (per unit first input sample) instead
    makes the modal state start at exactly zero, as python-control does.
    """
    e, g0, g1 = foh_coefficients(section.pole, dt)
    c = section.gain
    if section.pole.imag == 0.0:
        b = np.array([(c * g1).real, (c * g0).real])
        return b, np.array([1.0, -e.real]), np.array([-b[0]])
    b = 2.0 * np.real([c * g1, c * g0 - c * g1 * np.conj(e), -c * g0 * np.conj(e)])
    a = np.array([1.0, -2.0 * e.real, abs(e) ** 2])
    # transposed direct form II: y[0] = b0 v0 + zi0 = 0 and y[1] = 2 Re(c g0) v0 + b0 v1
    return b, a, np.array([-b[0], 2.0 * (c * g0).real - b[1]])


@dataclass(frozen=True, eq=False)
class SimulationResult:
    """Hub force history.

    Attributes
    ----------
    t, distance : ndarray
        Time (s) and distance travelled (m), as the road input.
    force : ndarray
        Vertical force on the hub (N), positive upward, relative to the static preload.
    road : RoadInput
        The input that produced it.
    """

    t: np.ndarray
    distance: np.ndarray
    force: np.ndarray
    road: RoadInput


def _run(sections: ModalSections, u: np.ndarray, dt: float) -> np.ndarray:
    """Output of the modal sections for inputs ``u`` (n_inputs, n_samples) at step ``dt``.

    Consecutive sections of one pole (a mode driven by many inputs, as in a common-pole tire)
    run as one: a section's output is real-linear in its gain :math:`c`, so
    :math:`\\sum_k F_{c_k}(u_k) = F_1(\\sum_k \\mathrm{Re}\\,c_k u_k) + F_i(\\sum_k \\mathrm{Im}\\,c_k u_k)`:
    two IIR passes per mode instead of one per input.
    """

    def run(part: list[list[Section]]) -> np.ndarray:
        out = np.zeros(u.shape[1])
        for group in part:
            if len(group) <= 2:
                for section in group:
                    b, a, zi = section_filter(section, dt)
                    v = u[section.source]
                    out += lfilter(b, a, v, zi=zi * v[0])[0]
                continue
            gains = np.array([section.gain for section in group])
            sources = [section.source for section in group]
            for unit, part_of in ((1.0, np.real), (1j, np.imag)):
                mix = part_of(gains)
                if unit == 1j and group[0].pole.imag == 0.0:
                    continue  # a real pole has real gains
                b, a, zi = section_filter(Section(group[0].pole, complex(unit), 0), dt)
                v = mix @ u[sources]
                out += lfilter(b, a, v, zi=zi * v[0])[0]
        return out

    groups: list[list[Section]] = []
    for section in sections.sections:
        if groups and groups[-1][0].pole == section.pole:
            groups[-1].append(section)
        else:
            groups.append([section])
    # lfilter releases the GIL: two parts of the sections, on two threads where the cores are free
    parts = [groups[k::PARTS] for k in range(PARTS)]
    exact = sum((block.output(u, dt)[0] for block in sections.blocks), np.zeros(u.shape[1]))
    return sections.direct @ u + sum(thread_map(run, parts)) + exact


def as_continuous_statespace(system) -> control.StateSpace:
    """A continuous-time python-control ``StateSpace`` from any python-control LTI model, or a clear error.

    Transfer functions are converted (``control.ss``); a discrete-time model (``dt`` set) is
    refused: the simulation discretises the continuous model itself, exactly for its own step.
    """
    if not isinstance(system, control.LTI):
        raise ValueError(
            f"system must be a python-control StateSpace or TransferFunction (or ModalSections), got {type(system).__name__}"
        )
    if control.isdtime(system, strict=True):
        raise ValueError(
            f"system has dt = {system.dt}: simulate needs a continuous-time model (dt = 0); pass the model "
            "before discretisation"
        )
    return system if isinstance(system, control.StateSpace) else control.ss(system)


def _check_inputs(u: np.ndarray, t: np.ndarray, n_inputs: int) -> float:
    if u.ndim != 2:
        raise ValueError(
            f"inputs must be 2-D, one row per model input ({n_inputs}) and one column per time sample; got {u.ndim}-D"
        )
    if u.shape[0] != n_inputs:
        raise ValueError(f"input has {u.shape[0]} rows; the model has {n_inputs} inputs")
    if u.shape[1] != t.size or t.size < 2:
        raise ValueError("inputs need one column per time sample, at least two samples")
    if not guards.all_finite(u):
        raise ValueError("input contains NaN or inf")
    return guards.uniform_step(t)


def simulate(system: control.StateSpace | ModalSections, road: RoadInput) -> SimulationResult:
    """Hub force of a (fixed-hub) state-space tire driven by tassello displacements.

    Parameters
    ----------
    system : control.StateSpace or ModalSections
        The tire, e.g. :func:`.statespace.assemble_fixed_hub`; one input per tassello, the hub
        force as output. Pass :func:`modal_sections` of it to reuse the decomposition.
    road : RoadInput
        Displacement histories (m), one row per input, uniform time step.

    Notes
    -----
    Zero initial state; the input varies linearly between samples (FOH), exactly as
    python-control's ``forced_response``. For a road flowing through the footprint,
    :func:`.aggregated.road_hub_force` gives the same force from the road itself, without forming
    the inputs (~30x faster and ~25x less memory at 2e6 samples; the book's "Performance" page).
    """
    if not isinstance(road, RoadInput):
        raise ValueError(f"road must be a RoadInput (t, u[input, sample]), got {type(road).__name__}")
    if not isinstance(system, ModalSections):
        system = as_continuous_statespace(system)
    n_inputs = system.n_inputs if isinstance(system, ModalSections) else system.ninputs
    u = np.asarray(road.u, dtype=float)
    dt = _check_inputs(u, np.asarray(road.t), n_inputs)  # before the model is decomposed
    sections = system if isinstance(system, ModalSections) else modal_sections(system)
    return SimulationResult(t=road.t, distance=road.distance, force=_run(sections, u, dt), road=road)


def _modal_states(pole: complex, drive: np.ndarray, dt: float) -> np.ndarray:
    """Exact FOH history of ``x' = p x + v`` from rest for the samples ``drive`` of ``v`` (complex or real)."""
    e, g0, g1 = foh_coefficients(pole, dt)
    if pole.imag == 0.0:
        e, g0, g1, drive = e.real, g0.real, g1.real, drive.real
    # x_k = e x_{k-1} + g0 v_{k-1} + g1 v_k with x_0 = 0: the transposed direct form started at -g1 v_0
    return lfilter([g1, g0], [1.0, -e], drive, zi=[-g1 * drive[0]])[0]


def response(system: control.StateSpace, t: np.ndarray, u: np.ndarray) -> np.ndarray:
    """All outputs (n_outputs, n_samples) of any stable LTI model for inputs ``u`` (FOH, zero state).

    The method of :func:`simulate` for a model with many inputs and outputs: each independent
    block of the state matrix is diagonalised once (or, ill-conditioned, stepped exactly:
    :class:`ExactBlock`), every mode (the upper member of a conjugate
    pair) is driven by its combination of the inputs and stepped once (exact FOH recursion),
    and the outputs are the modes' real parts weighted by the output matrix.
    """
    system = as_continuous_statespace(system)
    u = np.asarray(u, dtype=float)
    if u.ndim == 1 and system.ninputs == 1:
        u = u[None, :]
    t = np.asarray(t, dtype=float)
    dt = _check_inputs(u, t, system.ninputs)
    a, b, c, d = (np.asarray(m, dtype=float) for m in (system.A, system.B, system.C, system.D))
    out = d @ u
    n = a.shape[0]
    pattern = sp.csr_matrix(np.abs(a) > 0) + sp.identity(n, format="csr")
    n_blocks, labels = connected_components(pattern, directed=False)
    unstable = []
    for block in range(n_blocks):
        idx = np.nonzero(labels == block)[0]
        lam, vec = np.linalg.eig(a[np.ix_(idx, idx)])
        if not well_conditioned(a[np.ix_(idx, idx)]):
            unstable += list(lam[lam.real > 0])
            out += ExactBlock.balanced(a[np.ix_(idx, idx)], b[idx, :], c[:, idx]).output(u, dt)
            continue
        b_modal, c_modal = np.linalg.solve(vec, b[idx, :]), c[:, idx] @ vec
        scale = max(np.max(np.abs(lam)), 1.0)
        kept = np.nonzero(lam.imag >= -1e-12 * scale)[0]  # a conjugate pair's upper member carries both
        pair = np.abs(lam[kept].imag) > 1e-12 * scale
        poles = np.where(pair, lam[kept], lam[kept].real)
        unstable += list(poles[poles.real > 0])
        weights = c_modal[:, kept] * np.where(pair, 2.0, 1.0)
        for first in range(0, kept.size, MODES_AT_ONCE):  # bounded memory: a few modes' histories at a time
            part = slice(first, first + MODES_AT_ONCE)
            drives = b_modal[kept[part]] @ u
            states = np.array([_modal_states(complex(p), v, dt) for p, v in zip(poles[part], drives)])
            out += (weights[:, part] @ states).real
    if unstable:
        guards.warn(
            f"the model has {len(unstable)} unstable pole(s) (largest real part {max(p.real for p in unstable):.3g} "
            "1/s): its response grows without bound"
        )
    return out
