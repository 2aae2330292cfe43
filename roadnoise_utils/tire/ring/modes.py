"""Natural modes of the loaded tire with the hub fixed and the footprint tied to the road.

The rubber moduli are frozen at their storage values at a reference frequency (the paper's
FET70Hz: "the stiffness dependence on frequency ... has been frozen to the frequency of the
most relevant vertical mode (~70 Hz)"), giving the real eigenproblem
:math:`K_{ref}\\,\\phi = \\omega^2 M \\phi`, solved by shift-invert Lanczos (ARPACK).

Each mode is classified by its mirror symmetries (fore-aft, left-right), its dominant
circumferential wave number ``n`` and its lateral order ``m`` (sign changes across the
strips), and by its share of the static whole-footprint-to-hub FRF,

.. math:: c_r = -\\frac{(K_{hf}\\phi_r)(\\phi_r^T b_{tot})}{\\omega_r^2},\\qquad
          \\sum_r c_r \\to H_{tot}(0)\\ \\text{(all modes)},

with mass-normalised :math:`\\phi_r`. Only modes symmetric in both planes load the hub
vertically ("vertical modes").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
import scipy.sparse.linalg as spla

from ... import guards
from .loaded import LoadedTire, loaded_tire
from .mechanics import FETModel
from .mode_shapes import lateral_order, wave_numbers
from .static import StaticState
from .symmetry import mirror


@dataclass(frozen=True, eq=False)
class LoadedModes:
    """Modes of the loaded, fixed-hub tire.

    Attributes
    ----------
    freqs : ndarray (n_modes,)
        Undamped natural frequencies (Hz), ascending.
    shapes : ndarray (n_dof, n_modes)
        Mass-normalised shapes on all DOF (zero at the hub).
    reference_frequency : float
        Frequency at which the moduli are frozen (Hz).
    fore_aft, left_right : ndarray of int (n_modes,)
        +1 symmetric, -1 antisymmetric, 0 mixed, for the x and y mirrors.
    wave_number : ndarray of int
        Dominant circumferential wave number ``n``.
    lateral_order : ndarray of int
        Sign changes of the strip amplitudes across the width ``m``.
    hub_share : ndarray (n_modes,)
        Static contribution :math:`c_r` of each mode to :math:`H_{tot}(0)` (N/m).
    hub_gain : ndarray (n_modes,)
        :math:`K_{hf}\\phi_r` (N/m per unit modal coordinate).
    """

    freqs: np.ndarray
    shapes: np.ndarray
    reference_frequency: float
    fore_aft: np.ndarray
    left_right: np.ndarray
    wave_number: np.ndarray
    lateral_order: np.ndarray
    hub_share: np.ndarray
    hub_gain: np.ndarray

    @property
    def vertical(self) -> np.ndarray:
        """Mask of the modes symmetric in both planes (the only ones loading the hub vertically)."""
        return (self.fore_aft == 1) & (self.left_right == 1)

    def label(self, r: int) -> str:
        """Short description of mode ``r``, e.g. ``"n=1 m=0 vertical"``.

        The class names the mirror symmetries (fore-aft / left-right): symmetric in both is
        ``vertical``; antisymmetric fore-aft only is ``fore-aft``; antisymmetric left-right
        is ``lateral S`` or ``lateral A`` by its fore-aft symmetry.
        """
        return f"n={self.wave_number[r]} m={self.lateral_order[r]} {self.symmetry_class(r)}"

    def table(self, f_max: float = 300.0) -> pd.DataFrame:
        """Modes up to ``f_max`` (Hz): frequency, n, m, class and share of H_tot(0) (N/mm)."""
        keep = np.nonzero(self.freqs <= f_max)[0]
        return pd.DataFrame(
            {
                "frequency (Hz)": self.freqs[keep],
                "n": self.wave_number[keep],
                "m": self.lateral_order[keep],
                "class": [self.symmetry_class(r) for r in keep],
                "share of H_tot(0) (N/mm)": self.hub_share[keep] / 1e3,
            },
            index=pd.Index(keep + 1, name="mode"),
        )

    def symmetry_class(self, r: int) -> str:
        """``vertical``, ``fore-aft``, ``lateral S``, ``lateral A`` or ``mixed`` (see :meth:`label`)."""
        kind = {(1, 1): "vertical", (-1, 1): "fore-aft", (1, -1): "lateral S", (-1, -1): "lateral A"}
        return kind.get((int(self.fore_aft[r]), int(self.left_right[r])), "mixed")


def _symmetry_sign(mirror, shapes: np.ndarray, mass) -> np.ndarray:
    """Rayleigh quotient of the mirror: +1 symmetric, -1 antisymmetric, 0 if mixed."""
    q = np.einsum("ir,ir->r", shapes, mass @ (mirror @ shapes)) / np.einsum("ir,ir->r", shapes, mass @ shapes)
    return np.where(q > 0.9, 1, np.where(q < -0.9, -1, 0))


def _shape_signs(vecs: np.ndarray) -> np.ndarray:
    """+1 or -1 per shape (column) so that its projection on a fixed generic vector is positive.

    A symmetric tire has shapes whose largest entries come in equal mirrored pairs (an
    antisymmetric mode's of opposite sign): a sign fixed by the largest entry is then chosen
    by round-off and flips with the BLAS build. The projection on a seeded random vector is
    of the order of the shape's norm over sqrt(n_dof), far above round-off, for every shape.
    """
    probe = np.random.default_rng(20020101).standard_normal(vecs.shape[0])
    return np.where(probe @ vecs < 0.0, -1.0, 1.0)


def loaded_modes(
    fet: FETModel,
    static: StaticState,
    n_modes: int = 60,
    reference_frequency: float = 70.0,
    loaded: LoadedTire | None = None,
) -> LoadedModes:
    """The ``n_modes`` lowest modes of the loaded tire, moduli frozen at ``reference_frequency`` (Hz)."""
    n_modes = guards.integer("n_modes", n_modes, 1, 500)
    reference_frequency = guards.real("reference_frequency", reference_frequency, 0.0, unit="Hz")
    lt = loaded or loaded_tire(fet, static)
    omega_ref = 2 * np.pi * reference_frequency
    k = lt.stiffness(omega_ref, storage_only=True).tocsc()
    # a fixed ARPACK start vector and a sign convention make the shapes (and figures) repeatable
    start = np.ones(k.shape[0])
    vals, vecs = spla.eigsh(k, k=n_modes, M=lt.M.tocsc(), sigma=0.0, which="LM", v0=start)
    order = np.argsort(vals)
    vals, vecs = vals[order], vecs[:, order]
    vecs /= np.sqrt(np.einsum("ir,ir->r", vecs, lt.M @ vecs))
    vecs *= _shape_signs(vecs)
    omega2 = np.maximum(vals, 0.0)
    row = lt.hub_row(omega_ref, storage_only=True).real
    b_tot = fet.modulus_ratio("tread", omega_ref).real * np.asarray(lt.road_input.sum(axis=1)).ravel()
    gain = row @ vecs
    share = -gain * (b_tot @ vecs) / omega2
    shapes = np.zeros((fet.n_dof, n_modes))
    shapes[lt.free] = vecs
    mesh = fet.mesh
    return LoadedModes(
        freqs=np.sqrt(omega2) / (2 * np.pi),
        shapes=shapes,
        reference_frequency=float(reference_frequency),
        fore_aft=_symmetry_sign(mirror(mesh, True), vecs, lt.M),
        left_right=_symmetry_sign(mirror(mesh, False), vecs, lt.M),
        wave_number=wave_numbers(fet, shapes),
        lateral_order=lateral_order(fet, shapes),
        hub_share=share,
        hub_gain=gain,
    )
