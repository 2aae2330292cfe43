"""Road files: CSV profiles and height fields, read back exactly or refused with the reason."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru


def _write(path, header, s, z):
    rows = "\n".join(",".join(f"{v:.9g}" for v in (si, *zi)) for si, zi in zip(s, z.T))
    path.write_text("# a comment\n" + header + "\n" + rows + "\n")
    return path


def test_height_field_round_trip(tmp_path):
    s = np.arange(0.0, 1.0, 0.002)
    z = np.vstack([1e-3 * np.sin(2 * np.pi * s / 0.2 + k) for k in range(3)])
    road = ru.road.load_road_file(_write(tmp_path / "road.csv", "s,z@0.05,z@-0.05,z@0.00", s, z))
    assert np.array_equal(road.y, [-0.05, 0.0, 0.05])  # sorted by lateral position
    assert np.allclose(road.z, z[[1, 2, 0]], atol=1e-12) and np.allclose(road.s, s)
    profile = ru.road.load_road_file(_write(tmp_path / "profile.csv", "s,z", s, z[:1]))
    assert profile.z.shape == (1, s.size)


@pytest.mark.parametrize(
    ("header", "step", "bad", "message"),
    [
        ("x,z", 0.002, False, "header"),
        ("s,height", 0.002, False, "named"),
        ("s,z", 0.02, False, "too coarse"),
        ("s,z", 0.002, True, "NaN"),
    ],
)
def test_bad_road_files_are_refused(tmp_path, header, step, bad, message):
    s = np.arange(0.0, 0.5, step)
    z = np.zeros((1, s.size))
    if bad:
        z[0, 3] = np.nan
    with pytest.raises(ValueError, match=message):
        ru.road.load_road_file(_write(tmp_path / "bad.csv", header, s, z))
