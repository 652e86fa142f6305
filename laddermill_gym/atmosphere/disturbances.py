"""Wind disturbances for the environments: each one is a speed factor and a direction offset as functions of
time, sampled per episode on the environment's modulation grid as a :class:`~laddermill_gym.atmosphere.field.WindField`
(:func:`sample_wind_field`) and handed to the simulator with ``set_wind`` (the kernels interpolate linearly between
samples).

Composition: speed factors multiply, direction offsets add. A parameter given as a pair ``(low, high)`` is
drawn uniformly from that interval at every reset with the environment's ``np_random``, so the same
classes serve fixed evaluation scenarios and randomised training.

The grid spacing (the env's ``wind_dt``, default 0.1 s) sets the resolution: a step becomes a ramp over one
grid interval, which is short against the wing's lateral dynamics (periods of about 20 s).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields

import numpy as np

from laddermill_gym.atmosphere.field import WindField

__all__ = ["Disturbance", "DirectionStep", "OneMinusCosineGust", "RandomPerturbation", "Schedule",
           "DISTURBANCE_TYPES", "disturbance_from_dict", "sample_modulation", "sample_wind_field"]


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


class Disturbance:
    """Base class: ``sample(t, rng)`` returns (speed factor (n,), direction offset (n,) [rad]) at times t [s]."""

    def sample(self, t: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError


@dataclass(frozen=True)
class DirectionStep(Disturbance):
    """A step of the wind direction by ``step`` [rad] at ``time`` [s] (Meijaard et al. 1999 use 0.01 rad).

    Either parameter may be a (low, high) range drawn per episode; ``random_sign`` flips the step's sign
    with probability 1/2.
    """

    step: float | tuple[float, float] = 0.01
    time: float | tuple[float, float] = 1.0
    random_sign: bool = False

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
    """Random, slowly varying wind for training: speed factor 1 + s(t) and direction offset d(t), each a
    stationary Ornstein-Uhlenbeck process (exponential autocorrelation with time constant
    ``correlation_time`` [s]) with standard deviations ``speed_std`` [-] and ``direction_std`` [rad], started
    in its stationary distribution. Sampled exactly on the uniform grid: z_i = a z_(i-1) + sqrt(1 - a^2) e_i,
    a = exp(-spacing / correlation_time), e_i standard normal.
    """

    speed_std: float = 0.05
    direction_std: float = 0.05
    correlation_time: float = 10.0

    def sample(self, t, rng):
        if not (self.correlation_time > 0 and self.speed_std >= 0 and self.direction_std >= 0):
            raise ValueError(f"RandomPerturbation: correlation_time = {self.correlation_time!r} s must be > 0 and "
                             f"the standard deviations ({self.speed_std!r}, {self.direction_std!r}) >= 0")
        from scipy.signal import lfilter  # imported here: scipy.signal costs about 0.5 s at package import

        n = t.size
        spacing = float(t[1] - t[0]) if n > 1 else 1.0
        a = math.exp(-spacing / self.correlation_time)  # the grid is uniform
        out = []
        for std in (self.speed_std, self.direction_std):
            z0 = rng.normal()
            e = rng.normal(size=n - 1) * math.sqrt(1.0 - a * a)
            rest = lfilter([1.0], [1.0, -a], e, zi=[a * z0])[0] if n > 1 else np.zeros(0)
            out.append(std * np.concatenate([[z0], rest]))
        return 1.0 + out[0], out[1]


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


def sample_wind_field(disturbances, t_end: float, spacing: float, rng: np.random.Generator) -> WindField:
    """The :class:`~laddermill_gym.atmosphere.field.WindField` of the composed ``disturbances`` from t = 0 on
    (:func:`sample_modulation`'s samples, no gust grid): what ``Simulator.set_wind`` and
    ``BatchSimulator.set_wind`` take."""
    speed, direction = sample_modulation(disturbances, t_end, spacing, rng)
    return WindField(0.0, spacing, speed, direction)


DISTURBANCE_TYPES: dict[str, type[Disturbance]] = {
    cls.__name__: cls for cls in (DirectionStep, OneMinusCosineGust, RandomPerturbation, Schedule)}


def disturbance_from_dict(spec: dict, where: str = "disturbances") -> Disturbance:
    """A disturbance from a config mapping ``{type: <class name>, <parameter>: value, ...}``; a parameter
    given as a two-element list is a (low, high) range drawn per episode. Raises ValueError naming ``where``,
    the field and the value."""
    if not isinstance(spec, dict) or "type" not in spec:
        raise ValueError(f"{where} = {spec!r}: must be a mapping with a 'type' (one of {sorted(DISTURBANCE_TYPES)})")
    kind = spec["type"]
    if kind not in DISTURBANCE_TYPES:
        raise ValueError(f"{where}.type = {kind!r}: must be one of {sorted(DISTURBANCE_TYPES)}")
    cls = DISTURBANCE_TYPES[kind]
    known = {f.name for f in fields(cls)}
    params = {}
    for key, value in spec.items():
        if key == "type":
            continue
        if key not in known:
            raise ValueError(f"{where}.{key} = {value!r}: unknown parameter of {kind} (known: {sorted(known)})")
        params[key] = tuple(value) if isinstance(value, list) else value
    try:
        dist = cls(**params)
        dist.sample(np.arange(3.0), np.random.default_rng(0))  # validate values and ranges now
    except (TypeError, ValueError) as err:
        raise ValueError(f"{where} ({kind}): {err}") from None
    return dist
