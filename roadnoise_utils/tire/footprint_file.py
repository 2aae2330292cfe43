"""A loaded tire's footprint as a CSV file: its contact nodes, their tasselli and FE weights.

The file a user's own FE tire brings beside its FRFs (``[tire] model = "frf-file"``), and what
:func:`write_footprint_csv` writes for any :class:`~.model.Footprint`. One row per contact node
of the tread, SI units, a header naming the columns:

===========  ==================================================================================
column       meaning
===========  ==================================================================================
tassello     the node's tassello, numbered from 1 (the paper's Fig. 2 numbers)
row, column  the tassello's row (from the leading edge, +x) and column (from -y), from 1
track        the road track the node runs on: nodes of one track share its lateral position
x_m, y_m     the node's position on the tread surface, tire frame (m): x forward, y lateral
dx_minus_m   distance to the previous tread point along x (m): the node's shape function
dx_plus_m    reaches it (a bilinear hat over ``[x - dx_minus, x + dx_plus]``)
width_m      lateral tributary width of the node (m)
weight       the node's FE weight in its tassello (-): a tassello's weights sum to 1
pressure_Pa  contact pressure at the node (Pa)
===========  ==================================================================================

A tassello's displacement is the weighted average of the road under its nodes' shape functions
(the paper's *Simulation of Wheel-Road Interaction*: "the weighting function consists of the
shape functions of the finite elements"), so these columns are all the road input needs.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from .. import guards
from ..repro.paths import atomic_output, record_read
from .tasselli import MAX_TASSELLO_SIZE, Tasselli, tasselli_from_nodes

#: The columns of a footprint file, in order.
COLUMNS = (
    "tassello",
    "row",
    "column",
    "track",
    "x_m",
    "y_m",
    "dx_minus_m",
    "dx_plus_m",
    "width_m",
    "weight",
    "pressure_Pa",
)
#: How far a tassello's weights may sum from 1 (round-off of the writer's 17 digits, and of the user's FE code).
WEIGHT_TOLERANCE = 1e-9
#: Largest footprint dimension a file may give (m): a tire's contact patch is well under this.
MAX_FOOTPRINT = 1.0


def write_footprint_csv(path: str | Path, tasselli: Tasselli, pressure: np.ndarray, overwrite: bool = False) -> Path:
    """Write a footprint's contact nodes (``tasselli``) and their ``pressure`` (Pa) as a footprint file.

    Every value is written with 17 significant digits, so :func:`read_footprint_csv` gives the
    same numbers back. Nothing is written half-way (a temporary file renamed into place).
    """
    t = tasselli
    pressure = np.asarray(pressure, float)
    if pressure.shape != t.node_x.shape:
        raise ValueError(f"pressure has shape {pressure.shape}: valid is ({t.node_x.size},), one value per node")
    _, track = np.unique(t.node_strip, return_inverse=True)
    table = pd.DataFrame(
        {
            "tassello": t.node_tassello + 1,
            "row": t.row[t.node_tassello] + 1,
            "column": t.column[t.node_tassello] + 1,
            "track": track + 1,
            "x_m": t.node_x,
            "y_m": t.node_y,
            "dx_minus_m": t.node_dx_minus,
            "dx_plus_m": t.node_dx_plus,
            "width_m": t.widths,
            "weight": t.node_weight,
            "pressure_Pa": pressure,
        }
    )
    with atomic_output(path, overwrite, "path") as tmp:
        table.to_csv(tmp, index=False, float_format="%.17g")
    return Path(path)


def read_footprint_csv(path: str | Path) -> tuple[Tasselli, np.ndarray]:
    """The tasselli and the contact pressure at each node (Pa) of a footprint file.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        A column missing or unknown, a value not a number or outside its range (named with its
        row), a tassello numbering with gaps, a tassello in two rows or columns, a track with
        two lateral positions, weights that do not sum to 1 in a tassello.
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"footprint file {str(path)!r} does not exist or is not a file")
    try:
        record_read(path)
        table = pd.read_csv(path)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path.name}: not a readable CSV file ({exc})") from None
    if list(table.columns) != list(COLUMNS):
        raise ValueError(f"{path.name}: columns {list(table.columns)}; a footprint file has exactly {list(COLUMNS)}")
    if len(table) == 0:
        raise ValueError(f"{path.name}: no contact node")
    values = {name: _column(table, name, path.name) for name in COLUMNS}
    integer = {name: _integers(values[name], name, path.name) for name in ("tassello", "row", "column", "track")}
    _check_ranges(values, path.name)
    n = int(integer["tassello"].max())
    node_tassello = integer["tassello"] - 1
    if set(np.unique(node_tassello)) != set(range(n)):
        missing = sorted(set(range(1, n + 1)) - set(integer["tassello"]))
        raise ValueError(f"{path.name}: tasselli {missing[:10]} hold no node; number them 1..{n} without gaps")
    row = _per_tassello(integer["row"] - 1, node_tassello, n, "row", path.name)
    column = _per_tassello(integer["column"] - 1, node_tassello, n, "column", path.name)
    track = integer["track"] - 1
    for k in np.unique(track):
        ys = values["y_m"][track == k]
        if np.ptp(ys) > 1e-9:
            raise ValueError(
                f"{path.name}: track {k + 1} has nodes at y = {ys.min():.6g} to {ys.max():.6g} m; a track is one lateral position"
            )
    sums = np.bincount(node_tassello, weights=values["weight"], minlength=n)
    bad = np.flatnonzero(np.abs(sums - 1.0) > WEIGHT_TOLERANCE)
    if bad.size:
        raise ValueError(
            f"{path.name}: the weights of tassello {bad[0] + 1} sum to {sums[bad[0]]:.12g}; each tassello's "
            f"weights must sum to 1 (within {WEIGHT_TOLERANCE:g})"
        )
    order = np.lexsort((values["x_m"], track))
    node_index = np.empty(track.size, int)
    for k in np.unique(track):  # position along x within the track
        nodes = order[track[order] == k]
        node_index[nodes] = np.arange(nodes.size)
    tasselli = tasselli_from_nodes(
        node_strip=track,
        node_index=node_index,
        node_x=values["x_m"],
        node_y=values["y_m"],
        node_dx_minus=values["dx_minus_m"],
        node_dx_plus=values["dx_plus_m"],
        strip_width=float(np.median(values["width_m"])),
        node_tassello=node_tassello,
        node_weight=values["weight"],
        row=row,
        column=column,
        node_width=values["width_m"],
    )
    largest = max(float(tasselli.length.max()), float(tasselli.width.max()))
    if largest > MAX_TASSELLO_SIZE + 1e-12:
        guards.warn(
            f"{path.name}: a tassello {largest * 1e3:.1f} mm long or wide; over {MAX_TASSELLO_SIZE * 1e3:.0f} mm the "
            "tasselli do not resolve road wavelengths down to 5 cm (paper abstract)"
        )
    return tasselli, values["pressure_Pa"]


def _column(table: pd.DataFrame, name: str, source: str) -> np.ndarray:
    values = pd.to_numeric(table[name], errors="coerce").to_numpy(float)
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        raise ValueError(
            f"{source}: column {name!r}, data row {bad[0] + 1}: {table[name].iloc[bad[0]]!r} is not a finite number"
        )
    return values


def _integers(values: np.ndarray, name: str, source: str) -> np.ndarray:
    bad = np.flatnonzero((values != np.round(values)) | (values < 1))
    if bad.size:
        raise ValueError(
            f"{source}: column {name!r}, data row {bad[0] + 1}: {values[bad[0]]:g}; valid values are integers >= 1"
        )
    return values.astype(int)


def _check_ranges(values: dict[str, np.ndarray], source: str) -> None:
    limits = {
        "x_m": (-MAX_FOOTPRINT, MAX_FOOTPRINT, "m"),
        "y_m": (-MAX_FOOTPRINT, MAX_FOOTPRINT, "m"),
        "dx_minus_m": (0.0, MAX_TASSELLO_SIZE, "m"),
        "dx_plus_m": (0.0, MAX_TASSELLO_SIZE, "m"),
        "width_m": (0.0, MAX_TASSELLO_SIZE, "m"),
        "weight": (0.0, 1.0, "-"),
        "pressure_Pa": (0.0, 1e8, "Pa"),
    }
    for name, (lo, hi, unit) in limits.items():
        v = values[name]
        positive = name in ("dx_minus_m", "dx_plus_m", "width_m")
        bad = np.flatnonzero((v <= lo if positive else v < lo) | (v > hi))
        if bad.size:
            bracket = "(" if positive else "["
            raise ValueError(
                f"{source}: column {name!r}, data row {bad[0] + 1}: {v[bad[0]]:g} {unit}; valid range is {bracket}{lo:g}, {hi:g}]"
            )


def _per_tassello(values: np.ndarray, node_tassello: np.ndarray, n: int, name: str, source: str) -> np.ndarray:
    out = np.full(n, -1)
    out[node_tassello] = values
    if np.any(out[node_tassello] != values):
        i = int(node_tassello[np.flatnonzero(out[node_tassello] != values)[0]])
        raise ValueError(f"{source}: tassello {i + 1} has nodes in two {name}s; a tassello is in one {name}")
    return out
