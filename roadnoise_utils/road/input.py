"""Road inputs: the road flowing through the footprint, one displacement history per tassello.

Paper, *Simulation of Wheel-Road Interaction*: "The time histories of the displacements due
to road irregularity can be obtained by flowing a spatial distribution of road unevenness
through the contact patch. The displacement pertaining to each tassello is then defined as a
weighted average of all the physical displacements of the points inside the area of the
tassello, where the weighting function consists of the shape functions of the finite elements."

For a road that is uniform across the width (a cleat, a 2D profile), the weighted average of
tassello ``i`` is a correlation of the profile :math:`z(x)` with a fixed kernel,

.. math:: u_i(d) = \\int k_i(x)\\, z(x + d)\\, dx, \\qquad
          k_i(x) = \\sum_{n \\in i} w_n \\frac{N_n(x)}{\\int N_n\\,dx},

where ``d`` is the distance the wheel has travelled over the road and :math:`N_n` the
bilinear shape function (hat) of contact point ``n`` (:mod:`roadnoise_utils.tire.tasselli`,
:mod:`.kernels`). The kernel is evaluated on a fine grid and the correlation done for all
tasselli at once.

Distance convention: a footprint point at ``x`` sees road coordinate ``s = x + d`` after the
wheel has travelled ``d``, so road features move towards -x (backwards) as ``d`` grows; a
feature starting at ``s = 0`` (its leading edge, met first) is under the axle at ``d = 0``.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass

import numpy as np

from .. import guards
from ..tire.model import Footprint
from .kernels import strip_kernels
from .textures import MAX_HEIGHT, RoadProfile, RoadSpectrum, as_spectrum, generate_field, generate_profile

#: Simulation band of the RM model (Hz), paper abstract: "0-250 Hz".
BAND = 250.0
#: Time samples per period of the band's top frequency, at least (FOH inputs, decay fits).
SAMPLES_PER_PERIOD = 20
#: Largest road step per time sample (m): about half the 5.7-6 mm spacing of the tread points,
#: so each tassello input varies smoothly between samples (the road itself is averaged on a grid
#: ``oversample`` times finer).
MAX_ROAD_STEP = 3.5e-3
#: Fastest rolling speed accepted (m/s, 360 km/h): more is a unit slip (km/h times 3.6).
MAX_SPEED = 100.0
#: Road grid of slow runs (m): finer steps are interpolated linearly from this grid.
ROAD_GRID = 1.0e-4


@dataclass(frozen=True, eq=False)
class RoadInput:
    """Displacement histories of the tasselli.

    Attributes
    ----------
    t : ndarray (n_samples,)
        Time (s), uniform, starting at 0.
    distance : ndarray (n_samples,)
        Distance travelled (m), ``speed * t`` plus the start offset.
    u : ndarray (n_tasselli, n_samples)
        Vertical displacement of each tassello (m), positive up.
    speed : float
        Rolling speed (m/s).
    description : str
        What the road is.
    """

    t: np.ndarray
    distance: np.ndarray
    u: np.ndarray
    speed: float
    description: str

    def __post_init__(self):
        """Shapes, types and the speed checked when the input is made (no pass over the samples:
        :func:`roadnoise_utils.rm.simulate` checks the values are finite, in chunks)."""
        guards.real("speed", self.speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s")
        for name in ("t", "distance", "u"):
            if np.iscomplexobj(getattr(self, name)):  # np.asarray(..., float) would drop the imaginary part
                raise ValueError(f"{name} must be real numbers, got complex values")
            try:
                object.__setattr__(self, name, np.asarray(getattr(self, name), float))
            except (TypeError, ValueError):
                raise ValueError(f"{name} must be real numbers (a rectangular array)") from None
        if self.t.ndim != 1 or self.distance.shape != self.t.shape:
            raise ValueError(f"t {self.t.shape} and distance {self.distance.shape} must be 1-D, of one length")
        if self.u.ndim != 2 or self.u.shape[1] != self.t.size:
            raise ValueError(f"u must be (n_tasselli, n_samples) = (., {self.t.size}), got shape {self.u.shape}")

    @property
    def dt(self) -> float:
        """Time step (s)."""
        return float(self.t[1] - self.t[0])

    @property
    def sample_rate(self) -> float:
        """Samples per second (Hz)."""
        return 1.0 / self.dt

    def excerpt(self, start: int, stop: int) -> RoadInput:
        """Samples ``start`` to ``stop`` (clipped to the record), the time restarting at 0."""
        part = slice(start, min(stop, self.t.size))
        return RoadInput(
            t=self.t[part] - self.t[start],
            distance=self.distance[part],
            u=self.u[:, part],
            speed=self.speed,
            description=f"{self.description}, samples {start}-{part.stop}",
        )

    def padded(self, n_samples: int) -> RoadInput:
        """The record extended with zero displacement to ``n_samples`` samples (the road beyond is flat)."""
        extra = max(0, n_samples - self.t.size)
        t = self.dt * np.arange(self.t.size + extra)
        return RoadInput(
            t=t,
            distance=self.distance[0] + self.speed * t,
            u=np.pad(self.u, ((0, 0), (0, extra))),
            speed=self.speed,
            description=f"{self.description}, zero-padded to {t.size} samples",
        )


#: Samples of a road record beyond which a run is announced with its size (1000 s at 10 kHz: a
#: hundred times the road test's record); larger inputs still meet the memory guard.
LONG_RECORD = 10_000_000


def sample_rate_for(speed: float, band: float = BAND) -> float:
    """Sample rate (Hz): at least ``SAMPLES_PER_PERIOD`` per period of ``band`` and a road
    step of at most :data:`MAX_ROAD_STEP`, rounded up to a whole multiple of 100 Hz (5 kHz up
    to 63 km/h, 10 kHz at 120 km/h)."""
    fs = max(SAMPLES_PER_PERIOD * band, speed / MAX_ROAD_STEP)
    return float(np.ceil(fs / 100.0) * 100.0)


def check_sampling(speed: float, sample_rate: float, band: float = BAND) -> None:
    """Refuse speeds and sample rates that cannot represent the band, naming the valid range."""
    speed = guards.real("speed", speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s (km/h / 3.6)")
    sample_rate = guards.real("sample_rate", sample_rate, 0.0, lo_open=True, unit="Hz")
    needed = SAMPLES_PER_PERIOD * band
    if sample_rate < needed:
        raise ValueError(
            f"sample_rate = {sample_rate:g} Hz is too coarse for the {band:g} Hz band: valid range is "
            f">= {needed:g} Hz ({SAMPLES_PER_PERIOD} samples per period)"
        )
    step = speed / sample_rate
    if step > MAX_ROAD_STEP:
        raise ValueError(
            f"road step speed/sample_rate = {step * 1e3:.2f} mm: valid range is <= {MAX_ROAD_STEP * 1e3:.1f} mm "
            f"(raise sample_rate to >= {speed / MAX_ROAD_STEP:g} Hz at {speed:g} m/s)"
        )


def _correlate(z: np.ndarray, kernels: np.ndarray, stride: int, n_out: int, step: float) -> np.ndarray:
    """``step * sum_j k[r, j] z[j + stride * m]`` for every kernel row r and output m (BLAS matmul)."""
    windows = np.lib.stride_tricks.sliding_window_view(z, kernels.shape[1])[::stride][:n_out]
    return step * (kernels @ windows.T)


@dataclass(frozen=True, eq=False)
class RoadGrid:
    """Where a road flowing through the footprint is sampled (:func:`road_grid`): the time samples,
    the road grid (``grid`` m per point, ``n_grid`` points) and its ``oversample`` times finer
    correlation grid (``step`` m) whose road coordinates ``s`` every track is evaluated at, and the
    tasselli's kernels per strip (:func:`.kernels.strip_kernels`)."""

    t: np.ndarray
    distance: np.ndarray
    speed: float
    grid: float
    n_grid: int
    step: float
    oversample: int
    s_start: float
    n_fine: int
    parts: list
    lateral: bool
    profile: object
    strip_y: np.ndarray

    @property
    def s(self) -> np.ndarray:
        """Road coordinates of the fine grid (m), ``n_fine`` of them from ``s_start`` every ``step``."""
        return self.s_start + self.step * np.arange(self.n_fine)

    @property
    def on_time_steps(self) -> bool:
        """Whether the road grid is the time step's (else the inputs are interpolated to the samples)."""
        return self.grid == self.speed * (self.t[1] - self.t[0])

    def tracks(self):
        """Yields ``(parts, heights)``: each track's heights on ``s`` (m) with the strip parts
        ``[(strip, rows, kernels)]`` that see it (one track for a 2-D road, one per strip for a 3-D one)."""
        for parts, heights in self.track_heights():
            yield parts, heights(0, self.n_fine)

    def track_heights(self):
        """Yields ``(parts, heights)`` as :meth:`tracks`, ``heights(lo, hi)`` the track's heights (m) at the fine
        grid's points ``lo .. hi - 1`` (zero outside the grid), evaluated and checked on demand: a long road in pieces."""
        if not self.lateral:
            yield self.parts, self._heights_of(self.profile)
            return
        for part in self.parts:
            strip = part[0]
            yield [part], self._heights_of(lambda ss, y=self.strip_y[strip]: self.profile(ss, y))

    def _heights_of(self, profile):
        def heights(lo: int, hi: int) -> np.ndarray:
            out = np.zeros(hi - lo)
            a, b = max(lo, 0), min(hi, self.n_fine)
            if b > a:
                out[a - lo : b - lo] = _heights(profile, self.s_start + self.step * np.arange(a, b))
            return out

        return heights


def road_grid(
    static: Footprint,
    profile,
    speed: float,
    distance: tuple[float, float],
    sample_rate: float | None = None,
    oversample: int = 4,
    check_memory=None,
) -> RoadGrid:
    """The sampling of :func:`profile_input` (same arguments), every argument checked before any work.

    ``check_memory(n_samples, n_grid, step, dt)`` refuses what its user would allocate, before
    anything is (default: :func:`profile_input`'s inputs).
    """
    _check_static(static)
    speed = guards.real("speed", speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s (km/h / 3.6)")
    fs = sample_rate_for(speed) if sample_rate is None else sample_rate
    check_sampling(speed, fs)
    fs = float(fs)
    d0, d1 = guards.interval("distance", distance)
    oversample = guards.integer("oversample", oversample, 1, 64)
    if not callable(profile):
        hint = " (of a RoadProfile, pass its .height)" if isinstance(profile, RoadProfile) else ""
        shown = type(profile).__name__ if isinstance(profile, (RoadProfile, np.ndarray)) else repr(profile)[:80]
        raise ValueError(
            f"profile = {shown} must be a function of the road coordinate: profile(s) or profile(s, y){hint}"
        )
    dt = 1.0 / fs
    n = int(np.floor((d1 - d0) / (speed * dt))) + 1
    # road grid: one time step of road, but no finer than ROAD_GRID (slow runs are interpolated)
    grid = max(speed * dt, min(ROAD_GRID, d1 - d0))
    n_grid = int(np.ceil((d1 - d0) / grid)) + 1
    step = grid / oversample
    if check_memory is None:
        _check_input_memory(static.tasselli, n, n_grid, step, oversample)
    else:
        check_memory(n, n_grid, step, dt)
    if n > LONG_RECORD:
        guards.warn(
            f"speed = {speed:g} m/s over distance {d0:g} .. {d1:g} m at {fs:g} Hz is {n:.3g} samples "
            f"({n * dt:.4g} s of record), beyond the usual <= {LONG_RECORD:.0e}: expect minutes "
            "(a slow speed or a long road); shorten the distance or raise the speed if that is not meant",
            4,
        )
    t = dt * np.arange(n)
    parts, x0 = strip_kernels(static.tasselli, step)
    n_x = parts[0][2].shape[1]
    return RoadGrid(
        t=t,
        distance=d0 + speed * t,
        speed=float(speed),
        grid=grid,
        n_grid=n_grid,
        step=step,
        oversample=oversample,
        s_start=float(x0 + d0),
        n_fine=n_x + (n_grid - 1) * oversample,
        parts=parts,
        lateral=_takes_lateral(profile),
        profile=profile,
        strip_y=strip_centres(static),
    )


def profile_input(
    static: Footprint,
    profile,
    speed: float,
    distance: tuple[float, float],
    sample_rate: float | None = None,
    oversample: int = 4,
    description: str = "road profile",
) -> RoadInput:
    """Tassello displacements for a road flowing through the footprint.

    Parameters
    ----------
    static : Footprint
        The loaded tire (its tasselli and their shape-function weights).
    profile : callable
        Road height (m). ``profile(s)`` for a road uniform across the width (2D), or
        ``profile(s, y)`` for a laterally varying road (3D): road coordinate ``s`` (m, array)
        and lateral position ``y`` (m, scalar). The footprint point at ``x`` sees road
        coordinate ``x + d`` after the wheel has travelled ``d``; a 3D road is sampled along
        the centre line of each belt strip.
    speed : float
        Rolling speed (m/s), > 0.
    distance : (float, float)
        Travel range (m) to simulate.
    sample_rate : float, optional
        Samples per second; default :func:`sample_rate_for`.
    oversample : int
        The correlation is done on a road grid ``oversample`` times finer than one time step
        (or than :data:`ROAD_GRID` when a time step covers less road; the result is then
        interpolated linearly to the time samples).
    """
    where = road_grid(static, profile, speed, distance, sample_rate, oversample)
    n, n_grid, step = where.t.size, where.n_grid, where.step
    on_grid = np.zeros((static.tasselli.n, n_grid))
    for parts, z in where.tracks():
        # a 2-D road: one track under every strip, one correlation of every strip's kernels
        stacked = _correlate(z, np.vstack([k for _, _, k in parts]), where.oversample, n_grid, step)
        first = 0
        for _, rows, _ in parts:
            on_grid[rows] += stacked[first : first + rows.size]
            first += rows.size
    if where.on_time_steps:
        u = on_grid[:, :n]
    else:
        position = (where.distance - where.distance[0]) / where.grid
        left = np.minimum(np.floor(position).astype(int), n_grid - 2)
        frac = position - left
        u = on_grid[:, left] * (1 - frac) + on_grid[:, left + 1] * frac
    return RoadInput(t=where.t, distance=where.distance, u=u, speed=where.speed, description=description)


def _check_input_memory(tasselli, n: int, n_grid: int, step: float, oversample: int) -> None:
    """Refuse inputs whose arrays would exceed the memory limit (the speed or the travel is the usual cause)."""
    x_lo = np.min(tasselli.node_x - tasselli.node_dx_minus)
    x_hi = np.max(tasselli.node_x + tasselli.node_dx_plus)
    n_kernel = (x_hi - x_lo) / step + 4
    n_fine = n_kernel + (n_grid - 1) * oversample
    # the inputs and the grid results, the road on the fine grid, one strip's correlation windows
    n_bytes = 8.0 * (tasselli.n * (n + 2 * n_grid) + 2 * n_fine + n_grid * n_kernel)
    guards.check_memory(n_bytes, f"the tassello inputs ({n} samples x {tasselli.n} tasselli)", "speed and distance")


def _heights(profile, s: np.ndarray) -> np.ndarray:
    z = np.asarray(profile(s))
    if np.iscomplexobj(z):
        raise ValueError("the road profile returned complex heights: heights are real numbers (m)")
    z = np.asarray(z, dtype=float)  # no copy of a float array
    if z.shape != s.shape:
        raise ValueError("the road profile must return finite heights, one per road coordinate")
    if not guards.all_finite(z):  # in chunks: no temporary as large as the road
        raise ValueError("the road profile must return finite heights, one per road coordinate")
    highest = max(-float(z.min(initial=0.0)), float(z.max(initial=0.0)))
    if highest > MAX_HEIGHT:
        raise ValueError(
            f"road heights up to {highest:g} m: valid range is [-{MAX_HEIGHT:g}, {MAX_HEIGHT:g}] m "
            "(heights are in metres, not millimetres)"
        )
    return z


def _takes_lateral(profile) -> bool:
    """Whether ``profile`` is a 3D road ``profile(s, y)``.

    It is when it takes two required positional arguments, or when its second positional
    argument is named ``y`` (``lambda s, y=0.0: ...`` is a 3D road with a default track).
    """
    try:
        params = list(inspect.signature(profile).parameters.values())
    except (TypeError, ValueError):
        return False
    positional = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    required = [p for p in positional if p.default is inspect.Parameter.empty]
    return len(required) >= 2 or (len(positional) >= 2 and positional[1].name == "y")


def _check_static(static) -> None:
    if not isinstance(static, Footprint):
        raise TypeError(
            f"static must be the loaded tire of ru.stages.solve_static(tire) (a Footprint, of any tire model), "
            f"got {type(static).__name__}"
        )


def strip_centres(static: Footprint) -> np.ndarray:
    """Lateral position of every belt strip (m), indexed by strip number."""
    t = static.tasselli
    centres = np.full(int(t.node_strip.max()) + 1, np.nan)
    centres[t.node_strip] = t.node_y
    return centres


#: Road generated beyond the travel (m): the footprint's leading edge runs ahead of the axle.
ROAD_MARGIN = 5.0


def contact_tracks(static: Footprint) -> np.ndarray:
    """Lateral positions (m) of the belt strips in contact: where a 3D road needs its tracks."""
    centres = strip_centres(static)
    return np.unique(centres[np.isfinite(centres)])


#: Road grid of a generated texture (m): at most a fifth of its shortest wavelength (2 cm).
TEXTURE_STEP = 0.004


def texture_road(spectrum: RoadSpectrum, length: float, seed: int, tracks: np.ndarray | None = None) -> RoadProfile:
    """The generated road of a texture run: 3D with one coherent track per lateral position in
    ``tracks`` (m; :func:`.textures.generate_field`), or 2D, uniform across the width (``None``).

    ``length`` (m) of road on the :data:`TEXTURE_STEP` grid; ``seed`` of the random phases.
    """
    if tracks is None:
        return generate_profile(spectrum, length, TEXTURE_STEP, seed=seed)
    return generate_field(spectrum, length, TEXTURE_STEP, tracks, seed=seed)


def texture_length(spectrum: RoadSpectrum, travel: float) -> float:
    """Road (m) a run of ``travel`` m needs: the travel, the footprint's margin, and every wavelength of the spectrum."""
    return max(travel + ROAD_MARGIN, spectrum.max_wavelength)


def texture_input(
    static: Footprint,
    spectrum: RoadSpectrum,
    speed: float,
    duration: float,
    seed: int,
    lateral: bool = True,
    sample_rate: float | None = None,
    road: RoadProfile | None = None,
) -> RoadInput:
    """Tassello displacements for ``duration`` s on a generated road of PSD ``spectrum``.

    Parameters
    ----------
    static : Footprint
        The loaded tire.
    spectrum : RoadSpectrum
        The road's displacement PSD (:mod:`.textures`).
    speed : float
        Rolling speed (m/s), > 0.
    duration : float
        Simulated time (s), > 0.
    seed : int
        Seed of the random phases: the same seed gives the same road.
    lateral : bool
        ``True``: a laterally varying 3D road, one coherent track per belt strip in contact
        (:func:`.textures.generate_field`); ``False``: a 2D road uniform across the width.
    sample_rate : float, optional
        Samples per second; default :func:`sample_rate_for`.
    road : RoadProfile, optional
        The road :func:`texture_road` generates for these arguments, when already made (e.g.
        from the stage cache); it must be that road (its tracks, length and seed are checked).
    """
    _check_static(static)
    spectrum = as_spectrum(spectrum)
    if not isinstance(lateral, (bool, np.bool_)):
        raise ValueError(f"lateral = {lateral!r} must be True (a 3D road) or False (uniform across the width)")
    duration = guards.real("duration", duration, 0.0, lo_open=True, unit="s")
    speed = guards.real("speed", speed, 0.0, MAX_SPEED, lo_open=True, unit="m/s (km/h / 3.6)")
    seed = guards.seed(seed)
    fs = sample_rate_for(speed) if sample_rate is None else sample_rate
    check_sampling(speed, fs)
    n = int(duration * float(fs)) + 1
    _check_input_memory(static.tasselli, n, n, speed / float(fs), 1)  # before the road is generated
    travel = duration * speed
    length = texture_length(spectrum, travel)
    tracks = contact_tracks(static) if lateral else None
    if road is None:
        road = texture_road(spectrum, length, seed, tracks)
    elif (
        road.seed != seed
        or road.s.size * road.step < length
        or not np.isclose(road.step, TEXTURE_STEP)
        or not np.array_equal(road.y, np.zeros(1) if tracks is None else tracks)
    ):
        raise ValueError("road is not the road texture_road generates for these arguments (seed, length, tracks)")
    description = f"{spectrum.name} ({'3D' if lateral else '2D'}, seed {seed})"
    return profile_input(
        static,
        road.as_3d() if lateral else road.as_2d(),
        speed,
        (0.0, travel),
        sample_rate=sample_rate,
        oversample=1,
        description=description,
    )
