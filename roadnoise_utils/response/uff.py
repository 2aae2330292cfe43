"""The FRF sets in the universal file format (UFF 58), the format NVH tools exchange FRFs in.

:func:`write_uff58` writes every FRF of a loaded tire of any model (a :class:`roadnoise_utils.tire.model.FRFResult`) as UFF data sets 58 (function
at nodal DOF) through `pyuff <https://github.com/ladisk/pyuff>`_, after a units data set 164 (SI);
:func:`read_uff58` reads such a file back into an :class:`roadnoise_utils.tire.model.FRFResult`. Every set is a
frequency response function (function type 4) of the vertical hub force (response node
:data:`HUB_NODE`, direction +Z) per unit vertical displacement (reference direction +Z) of

======================  ===============================  =====================================
FRF                     reference node                   reference entity name
======================  ===============================  =====================================
``H_tot``               :data:`FOOTPRINT_NODE` (1000)    ``FOOTPRINT``
``G_H``                 :data:`HUB_NODE` (1)             ``HUB`` (driving point, footprint held)
``H[i]`` (tassello i)   :data:`TASSELLO_NODE` + i        ``T0001`` ... (1-based)
``H_points[p]``         :data:`POINT_NODE` + p           ``P000001`` ... (``points=True`` only)
======================  ===============================  =====================================

The ordinate is a reaction force (numerator, N) over a displacement (denominator, m), the abscissa
a frequency (Hz): N/m, SI, as inside the package. Frequencies on an even grid are stored as its
start and step (UFF "even spacing"); any other grid as the x-value of every point ("uneven").

Precision. ASCII files print values at 12 significant digits (pyuff's ``%20.11e``, the E20.12
double-precision field of the standard), so a value comes back within 5e-12 of itself per real
and imaginary part; the abscissa (start and step, or every x-value) is an E13.5 field, 6 digits:
a frequency that 6 digits do not hold comes back rounded (a :class:`.guards.RoadnoiseWarning`
says by how much; binary files keep it). Binary files (``binary=True``) store float64: values
and uneven frequencies come back exactly.

Two pyuff 2.5.8 behaviours are worked around here: its binary writer in ``mode="overwrite"``
truncates the file after the first set's text header, so every set is written with
``mode="add"`` into a new temporary file (then renamed over ``path``: nothing is ever half-written);
and its binary header records ``n`` x 8 bytes for ``n`` complex values (the data take 16 or 24 per
point, ladisk/pyuff#91), which other readers trust: the count is corrected in the header.
pyuff also turns NaN into 0 silently; :func:`write_uff58` refuses non-finite FRFs instead.
"""

from __future__ import annotations

import datetime
import re
from pathlib import Path

import numpy as np
import pyuff

from .. import guards
from ..repro.paths import atomic_output, record_read
from ..tire.model import FRFResult

#: Response node of every set: the hub (wheel centre); also the reference node of ``G_H``.
HUB_NODE = 1
#: Reference node of ``H_tot``: the whole footprint moving together.
FOOTPRINT_NODE = 1000
#: Reference node of tassello 0 (``H[0]``); tassello ``i`` is ``TASSELLO_NODE + i``.
TASSELLO_NODE = 1001
#: Reference node of contact point 0 (``H_points[0]``), written with ``points=True``.
POINT_NODE = 100001
#: Most tasselli a file can hold (their nodes stay below :data:`POINT_NODE`).
MAX_TASSELLI = POINT_NODE - TASSELLO_NODE
#: UFF direction code of a +Z translation (vertical, up).
VERTICAL = 3
#: UFF 58 function type of a frequency response function.
FRF_FUNCTION = 4
#: UFF 58 specific data types: abscissa, ordinate numerator, ordinate denominator.
FREQUENCY, REACTION_FORCE, EXCITATION_FORCE, DISPLACEMENT = 18, 9, 13, 8
#: The ASCII field pyuff writes abscissa values in (E13.5: 6 significant digits).
ABSCISSA_FIELD = "%13.5e"
#: Relative tolerance (of the largest frequency) within which a stored frequency grid counts as unchanged.
FREQUENCY_RTOL = 1e-9

_DATA_TYPES = {8: "displacement", 9: "reaction force", 11: "velocity", 12: "acceleration", 13: "excitation force"}


def write_uff58(
    path: str | Path,
    frfs: FRFResult,
    *,
    binary: bool = False,
    overwrite: bool = False,
    points: bool = False,
    label: str = "",
) -> Path:
    """Write every FRF of a loaded tire to a UFF file: a units set (164, SI), then one set 58 per FRF.

    Parameters
    ----------
    path : str or Path
        The file to write (``.uff`` or ``.unv`` by custom); its folder must exist.
    frfs : FRFResult
        Any tire model's FRFs (:meth:`roadnoise_utils.tire.model.TireModel.fixed_hub_frfs`, a
        :class:`.modal_reduction.ModalReduction`'s ``FRFResult``), in N/m.
    binary : bool
        Binary UFF 58 (float64, exact) instead of ASCII (12 significant digits); default ASCII.
    overwrite : bool
        Replace an existing ``path``; by default an existing file is refused.
    points : bool
        Also write every contact point's FRF (``H_points``: hundreds of sets); default off.
    label : str
        Text for ID line 2 of every set (the tire, the case); at most 80 characters are kept.

    Returns
    -------
    Path
        ``path``. The sets are ``H_tot``, ``G_H``, ``H[0]`` ... ``H[n-1]`` (and the points), nodes and
        directions as in the module's table.

    Raises
    ------
    TypeError
        ``frfs`` is not an ``FRFResult``.
    ValueError
        Frequencies not increasing, fewer than 2, negative or non-finite; arrays whose lengths do
        not match ``freqs``; a non-finite FRF (naming the array and the tassello or point).
    FileExistsError
        ``path`` exists and ``overwrite`` is false.
    """
    if not isinstance(frfs, FRFResult):
        raise TypeError(f"frfs must be an FRFResult (TireModel.fixed_hub_frfs), got {type(frfs).__name__}")
    for name, value in (("binary", binary), ("overwrite", overwrite), ("points", points)):
        guards.flag(name, value)
    freqs, rows = _checked_rows(frfs, points)
    spacing, stored = _abscissa(freqs, binary)
    if not binary and spacing == 0:
        change = float(np.max(np.abs(stored - freqs)))
        if change > FREQUENCY_RTOL * max(float(freqs[-1]), 1.0):
            guards.warn(
                f"frfs.freqs: an ASCII UFF 58 file keeps 6 significant digits of each frequency (E13.5), so "
                f"these come back moved by up to {change:.3g} Hz; binary=True keeps them exactly"
            )
    when = datetime.datetime.now().strftime("%d-%b-%y %H:%M:%S")
    common = {
        "binary": int(bool(binary)),
        "id2": _id_line(label),
        "id3": when,
        "id4": _id_line(frfs.method),
        "id5": "roadnoise: RM model of Belluzzo et al. 2002, fixed hub, SI",
        "func_type": FRF_FUNCTION,
        "rsp_ent_name": "HUB",
        "rsp_node": HUB_NODE,
        "rsp_dir": VERTICAL,
        "ref_dir": VERTICAL,
        "abscissa_spacing": spacing,
        "abscissa_spec_data_type": FREQUENCY,
        "abscissa_axis_lab": "Frequency",
        "abscissa_axis_units_lab": "Hz",
        "ordinate_spec_data_type": REACTION_FORCE,
        "ordinate_force_unit_exp": 1,
        "ordinate_axis_lab": "Hub force Fz",
        "ordinate_axis_units_lab": "N",
        "orddenom_spec_data_type": DISPLACEMENT,
        "orddenom_len_unit_exp": 1,
        "orddenom_axis_lab": "Displacement z",
        "orddenom_axis_units_lab": "m",
        "z_axis_spec_data_type": 0,
        "x": freqs,
    }
    units = {
        "type": 164,
        "units_code": 1,
        "units_description": "SI: m, N, s",
        "temp_mode": 2,
        "length": 1.0,
        "force": 1.0,
        "temp": 1.0,
        "temp_offset": 273.15,
    }
    sets = [units]
    for k, (description, name, node, values) in enumerate(rows):
        sets.append(
            {
                **common,
                "type": 58,
                "id1": description,
                "func_id": k + 1,
                "ref_ent_name": name,
                "ref_node": node,
                "data": values,
            }
        )
    with atomic_output(path, overwrite, "path") as tmp:
        pyuff.UFF(str(tmp)).write_sets(sets, mode="add")  # "overwrite" loses the first binary set
        if binary:
            _correct_byte_counts(tmp, freqs.size, spacing)
    return Path(path)


def read_uff58(path: str | Path) -> FRFResult:
    """Read the FRF sets of a UFF file written by :func:`write_uff58` (or laid out as it writes them).

    Parameters
    ----------
    path : str or Path
        An ASCII or binary UFF file holding the sets 58 of the module's table, and optionally a
        units set 164: its factors convert the FRFs to N/m (without one, SI is assumed).

    Returns
    -------
    FRFResult
        ``freqs`` (Hz), ``H`` per tassello, ``H_tot``, ``G_H`` and ``H_points`` (N/m; an empty
        ``(0, n_freq)`` array when the file has no point sets; ``G_H`` is ``None`` when the file
        has no hub set: data without a hub transfer). ``method`` names the file and
        the writer's method line. A cross-section tire's ``FootprintFRF`` comes back as this
        equivalent: its per-tassello, whole-footprint and hub FRFs (``transfer`` and ``free_rim``
        are not written).

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        Not a readable UFF file; a set that is not a hub-force per displacement FRF (function
        type, nodes, directions, data types); sets on different frequencies; ``H_tot`` or
        a tassello missing, or a set twice.
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"path = {str(path)!r} does not exist or is not a file")
    try:
        record_read(path)
        found = pyuff.UFF(str(path)).read_sets()
    except Exception as exc:  # pyuff raises bare Exceptions
        raise ValueError(f"{path.name}: not a readable UFF file ({exc})") from None
    found = [found] if isinstance(found, dict) else list(found)
    factor = _units_factor(found, path.name)
    frfs: dict[int, np.ndarray] = {}
    freqs = None
    method = ""
    for k, dset in enumerate(s for s in found if s.get("type") == 58):
        where = f"{path.name}, set 58 number {k + 1} (reference node {dset.get('ref_node')})"
        _check_set(dset, where)
        node = int(dset["ref_node"])
        if node in frfs:
            raise ValueError(f"{where}: a second set for the same reference node")
        x = np.asarray(dset["x"], float)
        if freqs is None:
            freqs, method = x, str(dset.get("id4", "")).strip()
        elif x.shape != freqs.shape or not np.array_equal(x, freqs):
            raise ValueError(f"{where}: its frequencies differ from the first set's; every FRF needs the same ones")
        try:
            values = np.asarray(dset["data"], complex)
        except (TypeError, ValueError):
            raise ValueError(f"{where}: its values are not numbers") from None
        if values.shape != freqs.shape:
            raise ValueError(f"{where}: {values.size} values for {freqs.size} frequencies (a set cut short?)")
        if not np.all(np.isfinite(values)):
            raise ValueError(f"{where}: NaN or infinite values")
        frfs[node] = values * factor
    if freqs is None:
        raise ValueError(f"{path.name}: no UFF 58 data set")
    missing = [] if FOOTPRINT_NODE in frfs else ["H_tot"]
    tasselli = sorted(n for n in frfs if TASSELLO_NODE <= n < POINT_NODE)
    if not tasselli:
        missing.append(f"the tasselli (reference nodes {TASSELLO_NODE}, {TASSELLO_NODE + 1}, ...)")
    if missing:
        raise ValueError(f"{path.name}: no set for {', '.join(missing)}")
    _check_numbering(tasselli, TASSELLO_NODE, "tassello", path.name)
    point_nodes = sorted(n for n in frfs if n >= POINT_NODE)
    _check_numbering(point_nodes, POINT_NODE, "contact point", path.name)
    unknown = sorted(set(frfs) - {HUB_NODE, FOOTPRINT_NODE, *tasselli, *point_nodes})
    if unknown:
        raise ValueError(
            f"{path.name}: reference nodes {unknown} are not roadnoise nodes (hub {HUB_NODE}, footprint "
            f"{FOOTPRINT_NODE}, tasselli from {TASSELLO_NODE}, contact points from {POINT_NODE})"
        )
    h_points = np.array([frfs[n] for n in point_nodes]) if point_nodes else np.empty((0, freqs.size), complex)
    return FRFResult(
        freqs=freqs,
        H=np.array([frfs[n] for n in tasselli]),
        H_tot=frfs[FOOTPRINT_NODE],
        G_H=frfs.get(HUB_NODE),
        H_points=h_points,
        method=f"read from UFF 58 file {path.name}" + (f" ({method})" if method and method != "NONE" else ""),
    )


def _checked_rows(result: FRFResult, points: bool) -> tuple[np.ndarray, list[tuple[str, str, int, np.ndarray]]]:
    """The frequencies and every set to write (description, entity name, reference node, values), checked."""
    freqs = np.asarray(result.freqs, dtype=float)
    if freqs.ndim != 1 or freqs.size < 2:
        raise ValueError(
            f"frfs.freqs has shape {freqs.shape}: a UFF 58 FRF needs a 1-D array of at least 2 frequencies"
        )
    if not np.all(np.isfinite(freqs)) or freqs[0] < 0 or np.any(np.diff(freqs) <= 0):
        raise ValueError("frfs.freqs must be finite, >= 0 Hz and strictly increasing")
    n = freqs.size
    H = np.asarray(result.H)
    if H.ndim != 2 or H.shape[1] != n or not 1 <= H.shape[0] <= MAX_TASSELLI:
        raise ValueError(
            f"frfs.H has shape {H.shape}: valid is (n_tasselli, {n}) for {n} frequencies, 1 <= n_tasselli <= {MAX_TASSELLI}"
        )
    rows = {}
    for name, values in (("H_tot", result.H_tot), ("G_H", result.G_H)):
        if values is None and name == "G_H":
            continue  # data without a hub transfer
        values = np.asarray(values)
        if values.shape != (n,):
            raise ValueError(f"frfs.{name} has shape {values.shape}: valid is ({n},), one value per frequency")
        _finite(values, f"frfs.{name}")
        rows[name] = values
    out = [("H_tot: hub force Fz per road displacement, whole footprint", "FOOTPRINT", FOOTPRINT_NODE, rows["H_tot"])]
    if "G_H" in rows:
        out.append(("G_H: hub force Fz per hub displacement, footprint held", "HUB", HUB_NODE, rows["G_H"]))
    for i, values in enumerate(H):
        _finite(values, f"frfs.H (tassello {i})")
        out.append(
            (f"H_i: hub force Fz per road displacement, tassello {i + 1}", f"T{i + 1:04d}", TASSELLO_NODE + i, values)
        )
    if points:
        P = np.asarray(result.H_points)
        if P.ndim != 2 or P.shape[1] != n:
            raise ValueError(f"frfs.H_points has shape {P.shape}: valid is (n_points, {n}) with points=True")
        guards.check_memory(24.0 * P.size, f"{P.shape[0]} contact-point sets", "points")
        for p, values in enumerate(P):
            _finite(values, f"frfs.H_points (contact point {p})")
            out.append(
                (
                    f"H_point: hub force Fz per road displacement, contact point {p + 1}",
                    f"P{p + 1:06d}",
                    POINT_NODE + p,
                    values,
                )
            )
    return freqs, [(d, e, node, np.asarray(v, complex)) for d, e, node, v in out]


def _finite(values: np.ndarray, name: str) -> None:
    if not np.all(np.isfinite(values)):
        bad = np.flatnonzero(~np.isfinite(values))
        raise ValueError(
            f"{name} is NaN or inf at {bad.size} frequencies (first at index {bad[0]}): a UFF file needs finite FRFs"
        )


def _abscissa(freqs: np.ndarray, binary: bool) -> tuple[int, np.ndarray]:
    """UFF abscissa spacing (1 even, 0 uneven) and the frequencies a reader will get back."""
    tol = FREQUENCY_RTOL * max(float(freqs[-1]), 1.0)
    start, step = (float(ABSCISSA_FIELD % v) for v in (freqs[0], freqs[1] - freqs[0]))
    grid = start + step * np.arange(freqs.size)
    if np.max(np.abs(grid - freqs)) <= tol:
        return 1, grid
    return 0, freqs.copy() if binary else np.array([float(ABSCISSA_FIELD % f) for f in freqs])


def _id_line(text: str) -> str:
    """An ID line: one line of at most 80 characters, ``NONE`` when empty (the standard's rule)."""
    text = " ".join(str(text).split())[:80]
    return text or "NONE"


def _correct_byte_counts(path: Path, n_freq: int, spacing: int) -> None:
    """Set the byte count of every binary set 58 header to the bytes its data take (pyuff writes n x 8)."""
    data = path.read_bytes()
    per_point = 8 * (2 if spacing else 3)  # complex float64, with the x-value when uneven
    head = re.compile(rb"\n    58b([ \d]{6})([ \d]{6})([ \d]{12})([ \d]{12})")
    fixed = head.sub(lambda m: m.group(0)[:-12] + b"%12i" % (per_point * n_freq), data)
    path.write_bytes(fixed)


def _units_factor(sets: list[dict], name: str) -> float:
    """The factor from the file's FRF units to N/m (UFF 164: SI value = file value / unit factor)."""
    units = [s for s in sets if s.get("type") == 164]
    factors = {float(s["length"]) / float(s["force"]) for s in units}
    if len(factors) > 1:
        raise ValueError(f"{name}: {len(units)} units sets (164) that disagree; a file has one unit system")
    return factors.pop() if factors else 1.0


def _check_set(dset: dict, where: str) -> None:
    """Refuse a set 58 that is not a hub-force-per-displacement FRF in roadnoise's layout."""
    if int(dset.get("func_type", -1)) != FRF_FUNCTION:
        raise ValueError(f"{where}: function type {dset.get('func_type')}, expected {FRF_FUNCTION} (an FRF)")
    if int(dset.get("rsp_node", -1)) != HUB_NODE or int(dset.get("rsp_dir", 0)) != VERTICAL:
        raise ValueError(
            f"{where}: response node {dset.get('rsp_node')} direction {dset.get('rsp_dir')}, expected the hub "
            f"(node {HUB_NODE}) in +Z ({VERTICAL})"
        )
    if int(dset.get("ref_dir", 0)) != VERTICAL:
        raise ValueError(f"{where}: reference direction {dset.get('ref_dir')}, expected +Z ({VERTICAL})")
    numerator, denominator = int(dset.get("ordinate_spec_data_type", 0)), int(dset.get("orddenom_spec_data_type", 0))
    if numerator not in (REACTION_FORCE, EXCITATION_FORCE) or denominator != DISPLACEMENT:
        raise ValueError(
            f"{where}: ordinate {_DATA_TYPES.get(numerator, f'type {numerator}')} per "
            f"{_DATA_TYPES.get(denominator, f'type {denominator}')}, expected force per displacement (N/m)"
        )
    if int(dset.get("abscissa_spec_data_type", FREQUENCY)) not in (FREQUENCY, 0):
        raise ValueError(
            f"{where}: abscissa type {dset.get('abscissa_spec_data_type')}, expected frequency ({FREQUENCY})"
        )


def _check_numbering(nodes: list[int], first: int, what: str, name: str) -> None:
    if nodes and nodes != list(range(first, first + len(nodes))):
        gaps = sorted(set(range(first, nodes[-1] + 1)) - set(nodes))
        raise ValueError(f"{name}: no set for {what} node(s) {gaps[:5]} (they are numbered from {first} without gaps)")
