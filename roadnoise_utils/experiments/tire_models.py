"""The tire models side by side: what each one can do, and any of them handed over as files.

Every stage of the RM chain asks the tire through :class:`~roadnoise_utils.tire.model.TireModel`;
these helpers serve the chapter that runs the paper's figures on every model: the table of the
optional capabilities, the tire written as the files a user's FE code would give (UFF 58 FRFs,
a footprint CSV, a tire file) and read back as a third model, and the cleat test's row influences.
"""

from __future__ import annotations

import os
import re
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from ..repro import stages
from ..repro.cache import cache_key, stage_fingerprint
from ..repro.paths import cache_dir
from ..repro.stages import Tire
from ..tire.frf_file.export import export_frf_files
from ..tire.model import CAPABILITIES, tire_model
from ..tire.surface import MAX_DRUM_RADIUS
from .cleat import row_influence

#: Folder (under the stage cache) where :func:`tire_as_files` writes a model's files.
FILES_FOLDER = "tire-files"


def capability_table(tires: dict[str, Tire]) -> pd.DataFrame:
    """One row per optional capability (:data:`~roadnoise_utils.tire.model.CAPABILITIES`), one column per tire.

    ``tires`` maps a label to a tire file name or path; a cell is ``"yes"`` where the tire's model
    has the capability and ``"not applicable"`` where a stage needing it refuses the tire.
    """
    models = {label: tire_model(tire) for label, tire in tires.items()}
    rows = {
        capability: {label: "yes" if model.has(capability) else "not applicable" for label, model in models.items()}
        for capability in CAPABILITIES
    }
    table = pd.DataFrame.from_dict(rows, orient="index")
    table.index.name = "capability"
    return table


def tire_as_files(tire: Tire, roads: tuple[str, ...] = ("flat",), drum_radius: float | None = None) -> Path:
    """Write ``tire``'s load cases on ``roads`` as a tire from files and return its tire file's path.

    Parameters
    ----------
    tire : str, Path, spec or TireModel
        Any tire of any model.
    roads : tuple of {"flat", "drum"}
        The load cases to write, one per road, at the tire file's load.
    drum_radius : float, optional
        Drum radius (m, in (0.3, 20]); required when ``roads`` holds ``"drum"``.

    Returns
    -------
    Path
        The tire file (``[tire] model = "frf-file"``) naming the UFF 58 and footprint CSV files.

    The files (:func:`~roadnoise_utils.tire.frf_file.export.export_frf_files`, binary UFF 58:
    exact) go to ``<stage cache>/tire-files/<tire name>-<key>/``, the key a digest of the tire's
    every value, the load cases and the code that computes and writes them (two variants of one
    tire never share a folder, nor does a tire after a change of that code). They are written
    once, into a temporary folder renamed into place when complete; later calls return them as
    they are (a UFF 58 header holds the time it was written, so writing again would change the
    files' contents, on which the stage cache keys the file tire's stages).
    """
    if isinstance(roads, str) or not roads or not set(roads) <= {"flat", "drum"} or len(set(roads)) < len(roads):
        raise ValueError(f"roads = {roads!r}: give a tuple of distinct roads out of ('flat', 'drum')")
    if "drum" in roads and drum_radius is None:
        raise ValueError(
            f"drum_radius: give the drum's radius for the 'drum' load case (m, valid range (0.3, {MAX_DRUM_RADIUS:g}])"
        )
    drum_radius = drum_radius if "drum" in roads else None
    model = tire_model(tire)
    cases = [model.case(road, drum_radius=drum_radius if road == "drum" else None) for road in roads]
    code = stage_fingerprint(tire_as_files, (*model.code_runs(), export_frf_files))
    key = cache_key(
        "tire_as_files", {"tire": model.fingerprint(), "roads": list(roads), "drum_radius": drum_radius}, code
    )
    folder = cache_dir() / FILES_FOLDER / f"{re.sub(r'[^A-Za-z0-9]+', '_', model.name).strip('_')}-{key[:12]}"
    if not (folder / "tire.toml").is_file():
        folder.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryDirectory(dir=folder.parent, prefix=f".{folder.name}-") as partial:
            export_frf_files(model, partial, cases, "tire")
            try:
                os.rename(partial, folder)  # atomic; another process's complete set may have won
            except OSError:
                if not (folder / "tire.toml").is_file():
                    raise
            Path(partial).mkdir(exist_ok=True)  # for the context manager's clean-up
    return folder / "tire.toml"


def drum_rows(tire: Tire, drum_radius: float) -> tuple[pd.DataFrame, float]:
    """The static influence H_i(0) of each tassello row on the drum, and the tire's K_v there (N/m).

    The rows from :func:`~roadnoise_utils.experiments.cleat.row_influence` on the drum footprint;
    the cleat's force while it crosses a row is about that row's H(0) times the cleat's mean
    height over it (notebook 04). Needs the drum FRFs at 0 Hz (a tire from files may start above).
    """
    static = stages.solve_static(tire, "drum", drum_radius=drum_radius)
    frfs = stages.frf_visco(tire, road="drum", drum_radius=drum_radius)
    if frfs.freqs[0] != 0.0:
        raise ValueError(f"tire: its drum FRFs start at {frfs.freqs[0]:g} Hz; the row influences need H_i at 0 Hz")
    h0 = frfs.H[:, 0].real
    return row_influence(static, h0), float(np.sum(h0))


def applicable(tire: Tire, capability: str) -> bool:
    """Whether ``tire``'s model has ``capability``; if not, print ``not applicable: <capability> (...)``.

    For a chapter's section that needs an optional capability: ``if applicable(tire, "..."):``
    runs it on a model that has it and says why it is skipped on one that has not.
    """
    model = tire_model(tire)
    if model.has(capability):
        return True
    print(f"{model.name}: not applicable: {capability} ({CAPABILITIES[capability]})")
    return False
