"""Road file formats: measured (or any) roads as CSV profiles and height fields."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..repro.paths import record_read
from .textures import MAX_HEIGHT, MIN_WAVELENGTH, RoadProfile, check_lateral_positions


def load_road_file(path: str | Path) -> RoadProfile:
    """A measured (or any) road from a CSV file: a 2D profile or a height field.

    Format: a header line, then one row per road coordinate (m, increasing, uniform step).
    ``s,z`` is a 2D profile; ``s,z@-0.05,z@0.00,z@0.05`` a height field, one column per
    lateral position ``y`` (m) given after ``@``. Heights in metres. Lines starting with ``#``
    are comments. Each belt strip uses the track nearest to its centre line.
    """
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"road file {str(path)!r} does not exist or is not a file")
    try:
        record_read(path)
        with open(path, encoding="utf-8-sig") as fh:  # tolerates the byte-order mark spreadsheets write
            lines = [line for line in fh if line.strip() and not line.startswith("#")]
    except UnicodeDecodeError:
        raise ValueError(f"{path.name}: not a text file; a road file is CSV text (header s,z or s,z@<y>,...)") from None
    if not lines:
        raise ValueError(f"{path.name}: no data; a road file has a header line 's,z' (or 's,z@<y>,...') and rows")
    header = lines[0].strip().split(",")
    if header[0].strip() != "s" or len(header) < 2:
        raise ValueError(f"{path.name}: the header must be 's,z' or 's,z@<y>,z@<y>,...', got {','.join(header)!r}")
    try:
        y = np.array([0.0 if h.strip() == "z" else float(h.strip().split("@")[1]) for h in header[1:]])
    except (IndexError, ValueError) as exc:
        raise ValueError(f"{path.name}: height columns must be named 'z' or 'z@<y in m>'") from exc
    if len(lines) < 4:
        raise ValueError(f"{path.name}: {len(lines) - 1} data rows; a road needs at least 3 rows (a uniform step)")
    try:
        data = np.loadtxt(lines[1:], delimiter=",", ndmin=2)
    except ValueError as exc:
        raise ValueError(f"{path.name}: every row must be numbers separated by commas ({exc})") from None
    if data.shape[1] != len(header):
        raise ValueError(f"{path.name}: {data.shape[1]} columns but {len(header)} names in the header")
    s, z = data[:, 0], data[:, 1:].T
    check_road_grid(s, y, z, path.name)
    if np.unique(y).size != y.size:
        raise ValueError(f"{path.name}: two height columns at one lateral position: {header[1:]}")
    order = np.argsort(y)
    return RoadProfile(s=s, y=y[order], z=z[order], spectrum=None, seed=None, periodic=False)


def check_road_grid(s: np.ndarray, y: np.ndarray, z: np.ndarray, source: str) -> None:
    """Refuse a road the RM input cannot use: NaN or inf, a non-uniform or too coarse step, heights or
    lateral positions out of range (errors name ``source``, the file).

    Parameters
    ----------
    s : ndarray (n,)
        Road coordinate (m): increasing with a uniform step of at most a quarter of the
        shortest wavelength the tasselli resolve (5 cm, paper abstract): 12.5 mm.
    y : ndarray (n_tracks,)
        Lateral position of each track (m), within +/- 1 m.
    z : ndarray (n_tracks, n)
        Heights (m), within +/- 0.25 m.
    """
    if not (np.all(np.isfinite(s)) and np.all(np.isfinite(y)) and np.all(np.isfinite(z))):
        raise ValueError(f"{source}: the road contains NaN or inf")
    step = np.diff(s)
    if s.size < 3 or np.any(step <= 0) or not np.allclose(step, step[0], rtol=1e-6):
        raise ValueError(f"{source}: s must increase with a uniform step")
    if step[0] > MIN_WAVELENGTH / 4 * (1 + 1e-9):
        raise ValueError(
            f"{source}: step {step[0] * 1e3:.1f} mm is too coarse: valid range is <= "
            f"{MIN_WAVELENGTH / 4 * 1e3:.1f} mm (4 samples per 5 cm)"
        )
    if np.max(np.abs(z)) > MAX_HEIGHT:
        raise ValueError(
            f"{source}: heights up to {np.max(np.abs(z)):g} m: valid range is [-{MAX_HEIGHT:g}, {MAX_HEIGHT:g}] m "
            "(heights are in metres, not millimetres)"
        )
    try:
        check_lateral_positions(y)
    except ValueError as exc:
        raise ValueError(f"{source}: {exc}") from None
