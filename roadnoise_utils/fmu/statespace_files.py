"""The fixed- and moving-hub state spaces as a MATLAB ``.mat`` file, for Simulink's State-Space block.

``A_F, B_F, C_F, D_F`` is the fixed-hub tire of Eq. 3-4 (inputs: the tasselli's displacements,
m; output: the hub force F_F, N); ``A_M, B_M, C_M, D_M`` the moving-hub tire of Eq. 7 (inputs
``[u_1 .. u_n, u_H]``, m; output F_M, N). With them: ``tassello_x``, ``tassello_y`` (m), where
each tassello sits in the footprint (its inputs' order), and ``description``. In Simulink, a
State-Space block takes ``A_M``, ``B_M``, ``C_M``, ``D_M`` as they are (``load tire.mat``);
the road enters as the tassello displacements the user's road model computes.

A Modelica model (``Modelica.Blocks.Continuous.StateSpace``) would need the matrices written out
as literals: ~10^6 numbers for a ~1000-state tire, a 10 MB text file no tool opens gladly. The
FMU (:mod:`.export`) is the way into Modelica tools.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import scipy.io

from ..rm.fitting import FitSet
from ..rm.moving_hub import assemble_moving_hub
from ..rm.realisation import assemble_fixed_hub
from ..tire.model import Footprint

MATRICES = ("A", "B", "C", "D")


def write_statespace_mat(path: str | Path, fits: FitSet, hub: FitSet, static: Footprint, name: str = "RM tire") -> Path:
    """Write the fixed- and moving-hub state spaces of ``fits`` and ``hub`` on ``static`` to ``path`` (``.mat``)."""
    path = Path(path)
    if path.suffix != ".mat":
        raise ValueError(f"path = {str(path)!r} must end in .mat")
    if not path.parent.is_dir():
        raise ValueError(f"path = {str(path)!r}: its folder {str(path.parent)!r} does not exist")
    if not isinstance(static, Footprint):
        raise TypeError(f"static must be a Footprint (the loaded tire), got {type(static).__name__}")
    if len(fits) != static.tasselli.n:
        raise ValueError(f"fits has {len(fits)} tasselli; the footprint has {static.tasselli.n}")
    fixed, moving = assemble_fixed_hub(fits), assemble_moving_hub(fits, hub)
    content = {f"{m}_F": np.asarray(getattr(fixed, m), float) for m in MATRICES}
    content |= {f"{m}_M": np.asarray(getattr(moving, m), float) for m in MATRICES}
    content["tassello_x"] = np.asarray(static.tasselli.centre_x, float)
    content["tassello_y"] = np.asarray(static.tasselli.centre_y, float)
    content["description"] = (
        f"{name}: fixed-hub (A_F..D_F, inputs tassello displacements in m, output F_F in N) and moving-hub "
        "(A_M..D_M, inputs [tassello displacements; hub displacement] in m, output F_M in N) state spaces, "
        "Belluzzo et al. 2002, Eq. 3-4 and 7"
    )
    staged = path.with_name(path.name + ".partial")
    with open(staged, "wb") as file:  # written whole or not at all
        scipy.io.savemat(file, content, do_compression=True)
    staged.replace(path)
    return path


def read_statespace_mat(path: str | Path) -> dict[str, np.ndarray]:
    """The matrices of a file of :func:`write_statespace_mat` (``A_F`` .. ``D_M``, ``tassello_x``, ``tassello_y``)."""
    data = scipy.io.loadmat(Path(path))
    expected = [f"{m}_{k}" for k in "FM" for m in MATRICES] + ["tassello_x", "tassello_y"]
    missing = [key for key in expected if key not in data]
    if missing:
        raise ValueError(f"{path}: not a roadnoise state-space file (missing {missing})")
    out = {key: np.asarray(data[key], float) for key in expected}
    out["tassello_x"], out["tassello_y"] = out["tassello_x"].ravel(), out["tassello_y"].ravel()
    return out
