"""Wind disturbances for the environments: each one is a speed factor and a direction offset as functions of
time, sampled per episode on the environment's modulation grid as a :class:`~laddermill_gym.atmosphere.field.WindField`
(:func:`sample_wind_field`) and handed to the simulator with ``set_wind`` (the kernels interpolate linearly between
samples).

Composition: speed factors multiply, direction offsets add. A parameter given as a pair ``(low, high)`` is
drawn uniformly from that interval at every reset with the environment's ``np_random``, so the same
classes serve fixed evaluation scenarios and randomised training.

The grid spacing (the env's ``wind_dt``, default 0.1 s) sets the resolution: a step becomes a ramp over one
grid interval, which is short against the wing's lateral dynamics (periods of about 20 s).

Spatial disturbances (turbulence, ``atmosphere/turbulence.py``; the IEC extreme wind shear,
``atmosphere/iec_gusts.py``) also give a frozen gust grid (:meth:`Disturbance.gust_grid`); the grids of a
composition are summed on one grid (:func:`~laddermill_gym.atmosphere.field.sum_grids`). Every disturbance
can be written as plain data and read back (``atmosphere/disturbance_spec.py``, which imports this module).
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from laddermill_gym.atmosphere.field import GridGeometry, WindField, sum_grids, union_geometry

__all__ = ["Disturbance", "DirectionStep", "OneMinusCosineGust", "RandomPerturbation", "Schedule",
           "DISTURBANCE_TYPES", "grid_geometry", "sample_modulation", "sample_wind_field"]


def _draw(value, rng: np.random.Generator, name: str) -> float:
    """A fixed number, or a uniform draw from a (low, high) pair."""
    if isinstance(value, (tuple, list)):
        if len(value) != 2 or not (math.isfinite(value[0]) and math.isfinite(value[1])) or value[0] > value[1]:
            raise ValueError(f"{name} = {value!r}: a range must be a finite pair (low, high) with low <= high")
        return float(rng.uniform(value[0], value[1]))
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} = {value!r}: must be finite")
    return v


def _check_range(value, name: str, low: float | None = None, strict: bool = False, why: str = "") -> None:
    """ValueError naming ``name`` unless ``value`` is a finite number or a finite (low, high) pair with low <= high
    whose every value is >= ``low`` (> with ``strict``): checked when the disturbance is made, not at the reset that
    first draws a value past it."""
    if isinstance(value, (tuple, list)):
        if len(value) != 2 or not all(isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(v)
                                      for v in value) or value[0] > value[1]:
            raise ValueError(f"{name} = {value!r}: a range must be a finite pair (low, high) with low <= high")
        least = value[0]
    elif isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise ValueError(f"{name} = {value!r}: must be a finite number or a (low, high) pair")
    else:
        least = value
    if low is not None and (least < low or (strict and least == low)):
        raise ValueError(f"{name} = {value!r}: every value must be {'>' if strict else '>='} {low:g}"
                         + (f" ({why})" if why else ""))


class Disturbance:
    """Base class: ``sample(t, rng)`` returns (speed factor (n,), direction offset (n,) [rad]) at times t [s];
    a spatial disturbance also returns a frozen gust grid (``gust_grid``) whose nodes ``grid_geometry`` tells
    without drawing (None for a purely temporal one)."""

    def sample(self, t: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError

    def grid_geometry(self, t_end: float) -> GridGeometry | None:
        """The nodes of the grid that :meth:`gust_grid` returns for an episode of t_end [s]; None for none."""
        return None

    def gust_grid(self, t_end: float, rng: np.random.Generator):
        """A :class:`~laddermill_gym.atmosphere.field.GustGrid` drawn with ``rng`` for an episode of t_end [s],
        or None (the default: no spatial part, no draws)."""
        return None


@dataclass(frozen=True)
class DirectionStep(Disturbance):
    """A step of the wind direction by ``step`` [rad] at ``time`` [s] (Meijaard et al. 1999 use 0.01 rad).

    Either parameter may be a (low, high) range drawn per episode; ``random_sign`` flips the step's sign
    with probability 1/2.
    """

    step: float | tuple[float, float] = 0.01
    time: float | tuple[float, float] = 1.0
    random_sign: bool = False

    def __post_init__(self):
        _check_range(self.step, "DirectionStep.step")
        _check_range(self.time, "DirectionStep.time")
        if not isinstance(self.random_sign, bool):
            raise ValueError(f"DirectionStep.random_sign = {self.random_sign!r}: must be true or false")

    def sample(self, t, rng):
        step = _draw(self.step, rng, "DirectionStep.step")
        t0 = _draw(self.time, rng, "DirectionStep.time")
        if self.random_sign and rng.random() < 0.5:
            step = -step
        return np.ones_like(t), np.where(t >= t0, step, 0.0)


@dataclass(frozen=True)
class OneMinusCosineGust(Disturbance):
    """A discrete 1-cosine gust: speed factor 1 + (A/2)(1 - cos(2 pi (t - t0)/T)) for t0 <= t <= t0 + T, and
    the same shape in direction with amplitude ``direction_amplitude`` [rad]. The shape of the discrete gust
    of the airworthiness codes (CS-25.341, FAR 25.341).

    Parameters: ``amplitude`` A [-] (relative speed increase at the peak), ``duration`` T [s], ``time`` t0 [s].
    """

    amplitude: float | tuple[float, float] = 0.3
    duration: float | tuple[float, float] = 10.0
    time: float | tuple[float, float] = 5.0
    direction_amplitude: float | tuple[float, float] = 0.0

    def __post_init__(self):
        _check_range(self.amplitude, "OneMinusCosineGust.amplitude", low=-1.0,
                     why="the speed factor at the peak, 1 + amplitude, would be negative")
        _check_range(self.duration, "OneMinusCosineGust.duration", low=0.0, strict=True, why="[s]")
        _check_range(self.time, "OneMinusCosineGust.time")
        _check_range(self.direction_amplitude, "OneMinusCosineGust.direction_amplitude")

    def sample(self, t, rng):
        a = _draw(self.amplitude, rng, "OneMinusCosineGust.amplitude")
        T = _draw(self.duration, rng, "OneMinusCosineGust.duration")
        t0 = _draw(self.time, rng, "OneMinusCosineGust.time")
        ad = _draw(self.direction_amplitude, rng, "OneMinusCosineGust.direction_amplitude")
        if T <= 0:
            raise ValueError(f"OneMinusCosineGust.duration = {T!r} s: must be > 0")
        inside = (t >= t0) & (t <= t0 + T)
        shape = np.where(inside, 0.5 * (1.0 - np.cos(2.0 * math.pi * (t - t0) / T)), 0.0)
        return 1.0 + a * shape, ad * shape


@dataclass(frozen=True)
class RandomPerturbation(Disturbance):
    """Random, slowly varying wind for training: a speed factor s(t) and a direction offset d(t) driven by
    stationary Ornstein-Uhlenbeck processes z(t) (zero mean, unit variance, exponential autocorrelation with
    time constant ``correlation_time`` [s]) started in their stationary distribution and sampled exactly on the
    uniform grid: z_i = a z_(i-1) + sqrt(1 - a^2) e_i, a = exp(-spacing / correlation_time), e_i standard normal.

    d(t) = ``direction_std`` z_d(t) [rad]. The speed factor is log-normal, s(t) = exp(q z_s(t) - q^2 / 2) with
    q = sqrt(ln(1 + speed_std^2)): mean 1 and standard deviation ``speed_std`` [-] exactly, and never negative
    for any parameter (a Gaussian factor 1 + speed_std z went negative in 1 % of 600 s episodes at 0.25 and
    93 % at 0.5). For small ``speed_std`` it is 1 + speed_std z to first order, with the same autocorrelation to
    O(speed_std^2).
    """

    speed_std: float = 0.05
    direction_std: float = 0.05
    correlation_time: float = 10.0

    def __post_init__(self):
        for name in ("speed_std", "direction_std", "correlation_time"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, numbers.Real) or not math.isfinite(v) or v < 0 or (
                    name == "correlation_time" and v == 0):
                raise ValueError(f"RandomPerturbation.{name} = {v!r}: must be a finite number "
                                 f"{'> 0 s' if name == 'correlation_time' else '>= 0'}")

    def sample(self, t, rng):
        from scipy.signal import lfilter  # imported here: scipy.signal costs about 0.5 s at package import

        n = t.size
        spacing = float(t[1] - t[0]) if n > 1 else 1.0
        a = math.exp(-spacing / self.correlation_time)  # the grid is uniform
        out = []
        for _ in range(2):
            z0 = rng.normal()
            e = rng.normal(size=n - 1) * math.sqrt(1.0 - a * a)
            rest = lfilter([1.0], [1.0, -a], e, zi=[a * z0])[0] if n > 1 else np.zeros(0)
            out.append(np.concatenate([[z0], rest]))
        q = math.sqrt(math.log1p(self.speed_std ** 2))
        return np.exp(q * out[0] - 0.5 * q * q), self.direction_std * out[1]


@dataclass(frozen=True)
class Schedule(Disturbance):
    """A user time series: ``times`` [s] (increasing), ``speed`` factors [-] and ``direction`` offsets [rad],
    linearly interpolated and held constant outside."""

    times: tuple[float, ...] = field(default=(0.0,))
    speed: tuple[float, ...] = field(default=(1.0,))
    direction: tuple[float, ...] = field(default=(0.0,))

    def __post_init__(self):
        t = np.asarray(self.times, float)
        s, d = np.asarray(self.speed, float), np.asarray(self.direction, float)
        if t.ndim != 1 or t.size < 1 or s.shape != t.shape or d.shape != t.shape:
            raise ValueError(f"Schedule: times, speed and direction need the same 1-D length, got "
                             f"{t.shape}, {s.shape}, {d.shape}")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(s)) and np.all(np.isfinite(d))):
            raise ValueError("Schedule: times, speed and direction must be finite")
        if np.any(np.diff(t) <= 0):
            raise ValueError(f"Schedule.times = {self.times!r}: must be strictly increasing")
        if np.any(s < 0):
            raise ValueError(f"Schedule.speed = {self.speed!r}: speed factors must be >= 0")

    def sample(self, t, rng):
        return (np.interp(t, self.times, self.speed), np.interp(t, self.times, self.direction))


def sample_modulation(disturbances, t_end: float, spacing: float,
                      rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Speed factor and direction offset samples at t = 0, spacing, ..., >= t_end [s] of the composed
    ``disturbances`` (speed factors multiplied, direction offsets added); shape (n,) each, n = ceil(t_end /
    spacing) + 1. Raises ValueError if the composed speed factor goes negative."""
    n = int(math.ceil(t_end / spacing - 1e-9)) + 1
    t = spacing * np.arange(n)
    speed, direction = np.ones(n), np.zeros(n)
    for dist in disturbances:
        s, d = dist.sample(t, rng)
        speed *= s
        direction += d
    if np.any(speed < 0):
        raise ValueError(f"disturbances give a negative wind speed factor (min {speed.min():.3g})")
    return speed, direction


def grid_geometry(disturbances, t_end: float) -> GridGeometry | None:
    """The nodes of the one gust grid that :func:`sample_wind_field` gives for ``disturbances`` over an episode
    of t_end [s] (None when none is spatial): what a ``BatchSimulator`` must hold (``n_grid`` = its
    ``floats``). Raises ValueError naming the first two spatial disturbances that cannot share a grid (another
    advection speed, heading or fade-in: one grid moves and fades as a whole)."""
    geoms = [d.grid_geometry(t_end) for d in disturbances]
    spatial = [i for i, g in enumerate(geoms) if g is not None]
    for i in spatial[1:]:
        a, b = geoms[spatial[0]], geoms[i]
        if math.isclose(a.advection, b.advection) and math.isclose(a.heading, b.heading) and a.fade_in == b.fade_in:
            continue
        raise ValueError(f"{_grid_name(disturbances, spatial[0], a)} and {_grid_name(disturbances, i, b)} cannot share "
                         "one gust grid, which is advected, turned and faded in as a whole: give them the same "
                         "wind_speed and heading, and the same fade_in (0 where one has no fade_in field)")
    return union_geometry(geoms)


def _grid_name(disturbances, i: int, g: GridGeometry) -> str:
    d = disturbances[i]
    fade = f"fade_in {g.fade_in:g} s" if hasattr(d, "fade_in") else "no fade-in"
    return (f"disturbances[{i}] ({type(d).__name__}: advected at {g.advection:g} m/s, heading {g.heading:g} rad, "
            f"{fade})")


def sample_wind_field(disturbances, t_end: float, spacing: float, rng: np.random.Generator) -> WindField:
    """The :class:`~laddermill_gym.atmosphere.field.WindField` of the composed ``disturbances`` from t = 0 on:
    :func:`sample_modulation`'s samples, then the disturbances' gust grids in their order (each drawing from
    ``rng``) summed on the grid of :func:`grid_geometry` (none without spatial disturbances: no grid, no cost).
    What ``Simulator.set_wind`` and ``BatchSimulator.set_wind`` take."""
    speed, direction = sample_modulation(disturbances, t_end, spacing, rng)
    geom = grid_geometry(disturbances, t_end)
    grid = None
    if geom is not None:
        grid = sum_grids([d.gust_grid(t_end, rng) for d in disturbances], geom)
    return WindField(0.0, spacing, speed, direction, grid)


DISTURBANCE_TYPES: dict[str, type[Disturbance]] = {
    cls.__name__: cls for cls in (DirectionStep, OneMinusCosineGust, RandomPerturbation, Schedule)}
