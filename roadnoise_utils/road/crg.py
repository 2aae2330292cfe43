"""OpenCRG road files (ASAM OpenCRG ``.crg``) in and out of the road module, the modifiers explicit.

An OpenCRG file holds a road as a grid of heights along a reference line: cross sections ``u``
(m, uniform step) by long sections ``v`` (m, positive to the left), relative to the reference
line, whose elevation, slope and banking the header gives. It is read and written through
`pycrg <https://github.com/ExpectedArgument/pycrg>`_, the bindings of the ASAM OpenCRG C library
(the reference loader simulators use), in all four data formats (binary ``KRBI``/``KDBI``, text
``LRFI``/``LDFI``).

**Modifiers.** A file's ``$ROAD_CRG_MODS`` block tells a loader to scale, fill or move the road.
A file *without* that block gets the C loader's *default* modifiers: the start of the reference
line is moved to ``x = y = z = 0`` — the whole road shifted by minus its height at the start of
the reference line (``u`` first, ``v = 0``). For a tire that is a false static load
(``K_v`` x shift: a road starting 14 mm up, shifted 14 mm down, unloads a 200 N/mm tire by
2.8 kN). :func:`load_crg` therefore never applies those defaults unless asked:
``modifiers="file"`` (default) applies the file's own block if it has one and nothing otherwise,
``"none"`` the data as stored, ``"opencrg"`` what the C loader does (the file's block or its
defaults: what a simulator built on it sees). A road whose median height is more than
:data:`STATIC_OFFSET_WARNING` from zero gets a :class:`.guards.RoadnoiseWarning`: the RM chain is
linearised about the tire loaded on ``z = 0``.

**Precision.** The C library keeps the heights in single precision, whatever the file's format:
a height comes back within ``2**-24`` of itself (relative, 6e-8); ``LRFI`` files print 10
characters per value (within 5e-8 m below 0.1 m). :func:`save_crg` writes ``KDBI`` by default
with an empty modifier block, so any OpenCRG reader keeps the road where it is.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Iterator
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pycrg

from .. import guards
from ..repro.paths import atomic_output, record_read
from .files import check_road_grid
from .textures import MAX_HEIGHT, MAX_LATERAL, RoadProfile

#: Serialises the message callback where pycrg has no thread-local capture.
_MESSAGES_LOCK = threading.Lock()
#: The choices of :func:`load_crg`'s ``modifiers``.
MODIFIER_CHOICES = ("file", "none", "opencrg", "path")
#: OpenCRG data formats :func:`save_crg` writes.
CRG_FORMATS = ("KDBI", "KRBI", "LDFI", "LRFI")
#: A road whose median height is further from zero than this (m) gets a warning (a static load).
STATIC_OFFSET_WARNING = 2e-3
#: Half the width of the two identical long sections a 2-D profile is written as (m): a CRG grid needs two.
PROFILE_HALF_WIDTH = 0.15


def crg_modifiers(path: str | Path) -> dict[str, float | str] | None:
    """The ``$ROAD_CRG_MODS`` block of an OpenCRG file: ``None`` without one, ``{}`` for an empty one."""
    return _header(_existing(path)).modifiers


def load_crg(path: str | Path, *, modifiers: str = "file", track: float = 0.0, half_width: float = 0.25) -> RoadProfile:
    """A road from an OpenCRG file: the long sections near one wheel track as a height field.

    Parameters
    ----------
    path : str or Path
        The ``.crg`` file (any of the four formats).
    modifiers : {"file", "none", "opencrg", "path"}
        ``"file"`` (default): the file's ``$ROAD_CRG_MODS`` block if it has one, nothing otherwise;
        ``"none"``: the data as stored, even if the file has a block; ``"opencrg"``: as the C loader
        does, the file's block or, without one, OpenCRG's defaults (the start of the reference
        line moved to ``z = 0``: a shift by minus the road's height there); ``"path"``: the
        heights relative to the reference line, the wheel's path (its elevation, slope and
        banking removed, :func:`_relative_to_path`): a surveyed road at its geographic elevation
        read as the roughness the tire rolls over.
    track : float
        Lateral position ``v`` of the wheel's centre line on the road (m, positive to the left, as
        in OpenCRG); default the reference line.
    half_width : float
        Long sections within this distance of ``track`` are kept (m), in (0, 1]; default 0.25 m
        (a tire is narrower than 0.35 m). At least one must fall inside.

    Returns
    -------
    RoadProfile
        ``s`` the file's ``u`` (m), ``y = v - track`` of each kept long section (m, increasing),
        ``z[track, s]`` the absolute heights ``grid + reference-line elevation + banking * v`` (m),
        after the chosen modifiers; not periodic (:meth:`RoadProfile.height` refuses points
        beyond the file). Curvature of the reference line is not used: the wheel follows ``u``.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        An unknown ``modifiers``; a file OpenCRG cannot load, fails OpenCRG's consistency check or
        whose modifiers are invalid; a header line OpenCRG cannot parse, or a header that disagrees
        with the data (:func:`check_consistency`: its reference line or long sections imply another
        number of sections than the data holds, a zero increment, a data channel short);
        ``track`` outside the road or no long section within ``half_width``; NaN heights in the
        kept long sections; a step over 12.5 mm; heights beyond 0.25 m (a reference line at its
        geographic elevation, say).
    """
    path = _existing(path)
    if modifiers not in MODIFIER_CHOICES:
        raise ValueError(f"modifiers = {modifiers!r}: valid values are {', '.join(map(repr, MODIFIER_CHOICES))}")
    half_width = guards.real("half_width", half_width, 0.0, MAX_LATERAL, lo_open=True, unit="m")
    track = guards.real("track", track, unit="m")
    with _opencrg_messages() as messages:
        header = _header(path)
        has_block = header.modifiers is not None
        apply = modifiers == "opencrg" or (modifiers == "file" and has_block)
        try:
            record_read(path)
            with pycrg.DataSet.open(path, apply_modifiers=False, check=True) as dataset:
                stored = dataset.grid()
                if apply:
                    dataset.modifiers_apply()
                grid = dataset.grid()
            if modifiers == "path":
                grid = _relative_to_path(path)
        except (pycrg.OpenCRGError, ValueError) as exc:
            raise ValueError(f"{path.name}: OpenCRG cannot load it ({exc})") from None
    check_consistency(path.name, header, messages, np.asarray(stored.u).size, np.asarray(stored.v).size)
    v = np.asarray(grid.v, float)
    if not v.min() <= track <= v.max():
        raise ValueError(f"track = {track:g} m: valid range is the road's width, [{v.min():g}, {v.max():g}] m")
    keep = np.flatnonzero(np.abs(v - track) <= half_width * (1 + 1e-9))
    if keep.size == 0:
        raise ValueError(
            f"half_width = {half_width:g} m: no long section of {path.name} within it of track = {track:g} m "
            f"(nearest at {v[np.argmin(np.abs(v - track))]:g} m): widen it"
        )
    z = np.asarray(grid.elevation, float)[:, keep].T
    y = v[keep] - track
    nan_columns = ~np.all(np.isfinite(z), axis=1)
    if np.any(nan_columns):
        raise ValueError(
            f"{path.name}: NaN heights in the long sections at v = {np.round(v[keep][nan_columns], 4).tolist()} m "
            "(the road's border has no data there): narrow half_width or move track, or give the file a "
            "$ROAD_CRG_MODS block with a GRID_NAN_MODE (applied with modifiers='file')"
        )
    s = np.asarray(grid.u, float)
    if modifiers != "path" and np.nanmax(np.abs(z)) > MAX_HEIGHT:
        raise ValueError(
            f"{path.name}: heights up to {np.nanmax(np.abs(z)):.4g} m with modifiers = {modifiers!r}: a road at its "
            "geographic elevation? modifiers='path' reads it relative to its reference line (the wheel's path)"
        )
    check_road_grid(s, y, z, path.name)
    median = float(np.median(z))
    if abs(median) > STATIC_OFFSET_WARNING:
        guards.warn(
            f"{path.name}: the road's median height is {median * 1e3:.2f} mm, not 0: the RM chain is linearised "
            f"about the tire loaded on z = 0, so that offset is a static load (modifiers = {modifiers!r}"
            + (
                ", the file has no $ROAD_CRG_MODS block: OpenCRG's defaults moved the road's start to z = 0)"
                if apply and not has_block
                else ")"
            )
        )
    return RoadProfile(s=s, y=y, z=z, spectrum=None, seed=None, periodic=False)


def save_crg(path: str | Path, road: RoadProfile, *, fmt: str = "KDBI", overwrite: bool = False) -> Path:
    """Write a road as an OpenCRG file (a straight reference line along ``s``), modifiers block empty.

    Parameters
    ----------
    path : str or Path
        The file to write; its folder must exist.
    road : RoadProfile
        A generated (:func:`.textures.generate_field`) or loaded road: ``s`` becomes ``u``, ``y``
        becomes ``v`` (m); a 2-D profile (one track) is written as two identical long sections at
        ``v = +/-`` :data:`PROFILE_HALF_WIDTH`.
    fmt : {"KDBI", "KRBI", "LDFI", "LRFI"}
        OpenCRG data format: binary double (default) or single, text double or single.
    overwrite : bool
        Replace an existing ``path``; by default an existing file is refused.

    Returns
    -------
    Path
        ``path``, written atomically (a temporary file renamed over it). The empty
        ``$ROAD_CRG_MODS`` block keeps OpenCRG readers from moving the road; the comment block
        names the texture and seed of a generated road.
    """
    if not isinstance(road, RoadProfile):
        raise TypeError(f"road must be a RoadProfile, got {type(road).__name__}")
    if fmt not in CRG_FORMATS:
        raise ValueError(f"fmt = {fmt!r}: valid values are {', '.join(map(repr, CRG_FORMATS))}")
    s, y, z = np.asarray(road.s, float), np.asarray(road.y, float), np.asarray(road.z, float)
    if z.ndim != 2 or z.shape != (y.size, s.size):
        raise ValueError(f"road.z has shape {z.shape}: valid is (n_tracks, n) = ({y.size}, {s.size})")
    check_road_grid(s, y, z, "road")
    if y.size > 1 and np.any(np.diff(y) <= 0):
        raise ValueError("road.y must increase (one long section per lateral position)")
    if y.size == 1:
        y, z = np.array([-PROFILE_HALF_WIDTH, PROFILE_HALF_WIDTH]) + y[0], np.vstack([z, z])
    comment = ["written by roadnoise (the RM model of Belluzzo et al. 2002)"]
    if road.spectrum is not None:
        comment.append(f"texture {road.spectrum.name}, seed {road.seed} (random-phase method)")
    with atomic_output(path, overwrite, "path") as tmp:
        try:
            pycrg.write(tmp, z.T, road.step, y, u0=float(s[0]), fmt=fmt, comment=comment, mods={})
        except ValueError as exc:
            raise ValueError(f"road: OpenCRG refuses it ({exc})") from None
    return Path(path)


@contextlib.contextmanager
def _opencrg_messages() -> Iterator[list[str]]:
    """The OpenCRG library's messages emitted on this thread while the block runs, collected and not
    printed. pycrg's thread-local capture sees every message, whatever limit a file's ``warn_msgs``
    option or an earlier file set, and leaves a user's own message callback alone; without it (an
    older pycrg), the public callback under a lock, the limit lifted."""
    messages: list[str] = []
    capture = getattr(getattr(pycrg, "_messages", None), "capture", None)
    if capture is not None:
        with capture(exclusive=True) as got:
            try:
                yield messages
            finally:
                messages.extend(" ".join(str(text).split()) for _, text in got)
        return
    with _MESSAGES_LOCK:  # pragma: no cover - older pycrg
        pycrg.set_max_warn_messages(-1)
        pycrg.set_message_callback(lambda level, text: messages.append(" ".join(str(text).split())))
        try:
            yield messages
        finally:
            pycrg.set_message_callback(None)


def check_consistency(name: str, header: pycrg.CrgHeader, messages: list[str], n_u: int, n_v: int) -> None:
    """Refuse an OpenCRG file whose header and data disagree, as the format defines them.

    OpenCRG's own loader skips a header line it cannot parse (a misspelt or non-numeric
    modifier) with a message, and reads as many cross sections and long sections as the data
    holds; here each is an error naming the file and what was expected. ``n_u``, ``n_v``: the
    cross and long sections of the data as stored (before modifiers).
    """
    ignored = [m for m in messages if "ignoring line" in m]
    if ignored:
        raise ValueError(f"{name}: a header line OpenCRG cannot parse ({ignored[0]}); fix or remove it")
    road = header.road or {}
    if not road:
        raise ValueError(f"{name}: no $ROAD_CRG block (the reference line and the long sections' positions)")
    for key in ("reference_line_increment", "long_section_v_increment"):
        if key in road and not (isinstance(road[key], (int, float)) and road[key] > 0):
            raise ValueError(f"{name}: $ROAD_CRG {key} = {road[key]}: valid range is > 0 m")
    _check_count(
        name,
        road,
        ("reference_line_start_u", "reference_line_end_u", "reference_line_increment"),
        n_u,
        "cross sections (u)",
    )
    _check_count(
        name,
        road,
        ("long_section_v_right", "long_section_v_left", "long_section_v_increment"),
        n_v,
        "long sections (v)",
    )
    data_channels = sum(1 for channel in header.channels if channel.kind == "D")
    if data_channels and data_channels != n_v:
        raise ValueError(
            f"{name}: {data_channels} data channels (D:) in $KD_DEFINITION, {n_v} long sections in the data"
        )


def _check_count(name: str, road: dict, keys: tuple[str, str, str], found: int, what: str) -> None:
    """The number of sections a header's start, end and increment imply against the data's."""
    if not set(keys) <= set(road):
        return
    values = [road[k] for k in keys]
    if not all(isinstance(v, (int, float)) and np.isfinite(v) for v in values):
        raise ValueError(
            f"{name}: $ROAD_CRG {', '.join(f'{k} = {v}' for k, v in zip(keys, values))}: each must be a finite number (m)"
        )
    start, end, step = (float(v) for v in values)
    implied = (end - start) / step + 1.0
    if abs(implied - round(implied)) > 1e-6 * max(implied, 1.0) or round(implied) != found:
        raise ValueError(
            f"{name}: the header's {keys[0]} .. {keys[1]} = {start:g} .. {end:g} m every {step:g} m make "
            f"{implied:.6g} {what}; the data has {found} (a line missing or cut short, or a wrong header)"
        )


def _relative_to_path(path: Path) -> SimpleNamespace:
    """The stored grid relative to its reference surface: the reference line's elevation (its slope
    integrated) and banking removed, the roughness kept.

    OpenCRG's own modifier ``scale_z`` scales the grid's values and leaves the reference surface:
    the grid evaluated with ``scale_z = 1`` minus the grid with ``scale_z = 0`` is the roughness
    alone (to the single precision the library stores it in), whatever the road's geographic
    elevation, slope or banking. The file's own modifier block is not applied (both evaluations
    replace it by that one modifier): a grid scaling or NaN mode in it is for the other choices.
    """
    record_read(path)
    elevations = []
    for scale in (1.0, 0.0):
        with pycrg.DataSet.open(path, apply_modifiers=False) as dataset:
            dataset.modifier_remove_all()
            dataset.modifier_set_double(pycrg.MOD_SCALE_Z, scale)
            dataset.modifiers_apply()
            grid = dataset.grid()
            elevations.append(np.asarray(grid.elevation, float))
    return SimpleNamespace(
        u=np.asarray(grid.u, float), v=np.asarray(grid.v, float), elevation=elevations[0] - elevations[1]
    )


def _existing(path: str | Path) -> Path:
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"path = {str(path)!r} does not exist or is not a file")
    return path


def _header(path: Path) -> pycrg.CrgHeader:
    try:
        return pycrg.read_header(path)
    except (pycrg.OpenCRGError, ValueError, UnicodeDecodeError) as exc:
        raise ValueError(f"{path.name}: not an OpenCRG file ({exc})") from None
