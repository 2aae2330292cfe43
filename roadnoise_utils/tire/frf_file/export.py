"""Any tire model's load cases written as a tire from files: UFF 58 FRFs, footprint CSV, tire file.

What a user's FE code would give the collection, written from one of our models: the worked
example of the ``frf-file`` model, and a way to hand our tires to other NVH tools.
"""

from __future__ import annotations

from pathlib import Path

from ...repro.paths import atomic_output
from ...response.uff import write_uff58
from ..footprint_file import write_footprint_csv
from ..model import LoadCase, TireModel


def export_frf_files(
    model: TireModel,
    folder: str | Path,
    cases: list[LoadCase],
    stem: str,
    *,
    binary: bool = True,
    overwrite: bool = False,
) -> Path:
    """Write ``cases`` of ``model`` into ``folder`` as a tire from files; returns the tire file's path.

    Per case ``<stem>-<i>.uff`` (its fixed-hub FRFs on the model's default grid, through
    :func:`~roadnoise_utils.response.uff.write_uff58`; ``binary`` keeps them exactly, ASCII to 12
    digits) and ``<stem>-<i>.csv`` (:func:`~roadnoise_utils.tire.footprint_file.write_footprint_csv`),
    then ``<stem>.toml`` naming them with the load, the rim-side mass and each case's K_v.
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"folder = {str(folder)!r} does not exist or is not a folder")
    if not cases:
        raise ValueError("cases: give at least one LoadCase")
    lines = [
        "# Written by roadnoise_utils.tire.frf_file.export_frf_files",
        "[tire]",
        'model = "frf-file"',
        f"name = {_quoted(model.name + ' (from files)')}",
        "",
        "[operating]",
        f"vertical_load = {model.default_load!r}",
        "",
        "[hub]",
        f"rim_side_mass = {float(model.rim_side_mass())!r}",
    ]
    for k, case in enumerate(cases, start=1):
        footprint = model.load(case)
        frfs = model.fixed_hub_frfs(case)
        label = f"{model.name}, {case.describe()}"
        write_uff58(folder / f"{stem}-{k}.uff", frfs, binary=binary, overwrite=overwrite, label=label[:80])
        write_footprint_csv(folder / f"{stem}-{k}.csv", footprint.tasselli, footprint.node_pressure, overwrite)
        lines += ["", "[[load_case]]", f'road = "{case.road.kind}"']
        if case.drum_radius is not None:
            lines.append(f"drum_radius = {case.drum_radius!r}")
        lines += [
            f"load = {case.load!r}",
            f'frfs = "{stem}-{k}.uff"',
            f'footprint = "{stem}-{k}.csv"',
            f"vertical_stiffness = {float(footprint.vertical_stiffness)!r}",
            f"deflection = {float(footprint.deflection)!r}",
        ]
    path = folder / f"{stem}.toml"
    with atomic_output(path, overwrite, "stem") as tmp:
        tmp.write_text("\n".join(lines) + "\n")
    return path


def _quoted(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
