"""The wing task's settings: the reward and termination dataclasses, their checks, and ``config_from`` (a settings
dataclass from None, an instance or a dict of its fields), with the bases every family's reward and termination
settings extend (:class:`ShapedRewardConfig`, :class:`FailureLimits`). Plain Python; re-exported by
``envs/task.py``."""

from __future__ import annotations

import dataclasses
import math
import numbers
from dataclasses import dataclass

__all__ = ["RewardConfig", "TerminationConfig", "ShapedRewardConfig", "FailureLimits", "check_nonnegative_fields",
           "config_from"]


def check_nonnegative_fields(obj, section: str, optional: tuple[str, ...] = ()) -> None:
    """Raise ValueError naming ``section.field`` and the value unless every dataclass field of ``obj`` is a
    finite number >= 0 (fields named in ``optional`` may also be None)."""
    for f in dataclasses.fields(obj):
        v = getattr(obj, f.name)
        if v is None and f.name in optional:
            continue
        if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v >= 0):
            raise ValueError(f"{section}.{f.name} = {v!r}: must be a finite number >= 0")


def check_reference_power(cfg) -> None:
    """``reward.reference_power_W`` is None (the operating point's power) or a fixed power > 0 [W]."""
    v = cfg.reference_power_W
    if v is not None and not v > 0:
        raise ValueError(f"reward.reference_power_W = {v!r}: must be > 0 W (or None: the operating point's power)")


@dataclass(frozen=True)
class ShapedRewardConfig:
    """The weights and scales of the reward terms every family shares: r = w_P P / P_ref - w_y S(lateral)
    - w_w S(rates) - ..., S(x) = 1 - exp(-x) (``envs.task_base.TaskCore.shaped_reward``). ``power_weight`` w_P,
    ``lateral_weight`` w_y, ``rate_weight`` w_w [-]; ``lateral_scale`` [m] (None: the family's default) and
    ``rate_scale`` [rad/s] of the lateral offset and the rates. A family's config extends it (its defaults, its
    own terms) and documents the reward; the checks here name the field and the value."""

    power_weight: float = 1.0
    lateral_weight: float = 1.0
    lateral_scale: float | None = None
    rate_weight: float = 0.1
    rate_scale: float = 0.5

    def __post_init__(self):
        check_nonnegative_fields(self, "reward", optional=("lateral_scale", "reference_power_W"))
        if self.rate_scale <= 0:
            raise ValueError(f"reward.rate_scale = {self.rate_scale!r}: must be > 0 rad/s")
        if self.lateral_scale is not None and self.lateral_scale <= 0:
            raise ValueError(f"reward.lateral_scale = {self.lateral_scale!r}: must be > 0 m")


@dataclass(frozen=True)
class FailureLimits:
    """The termination limits every family shares: ``min_altitude`` [m] (None: the family's default) and
    ``breaking_factor`` [-] (a cable or tether element fails above this times its breaking load; each family
    checks it). A family's config extends it with its attitude or aerodynamic ranges (:meth:`check_range`) and
    documents them."""

    min_altitude: float | None = None
    breaking_factor: float = 1.0

    def __post_init__(self):
        if self.min_altitude is not None and (isinstance(self.min_altitude, bool) or not (
                isinstance(self.min_altitude, numbers.Real) and math.isfinite(self.min_altitude))):
            raise ValueError(f"termination.min_altitude = {self.min_altitude!r}: must be a finite number [m]")
        v = self.breaking_factor
        if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
            raise ValueError(f"termination.breaking_factor = {v!r}: must be a finite number > 0")

    def check_range(self, name: str) -> None:
        """ValueError naming ``termination.name`` unless that field is a finite (low, high) pair with low < high."""
        pair = getattr(self, name)
        try:
            lo, hi = pair
            ok = math.isfinite(lo) and math.isfinite(hi) and lo < hi
        except (TypeError, ValueError):  # not a pair of numbers: ("-30",), 5, ("a", "b")
            ok = False
        if not ok:
            raise ValueError(f"termination.{name} = {pair!r}: need a pair (low, high) of finite numbers, low < high")


@dataclass(frozen=True)
class RewardConfig(ShapedRewardConfig):
    """Reward per control period: r = w_P P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort).

    P is the power a ground generator would take in with the cable reeled out at ``v_reel``:
    P = T_ground v_reel (Lansdorp et al. 2008: P = T dL/dt) for a single tether, and
    P = (T_start - T_end) v_reel for a chain between two ground points (the net pull on an endless cable
    through a generator at the start point). v_reel = ``reel_speed_fraction`` x the scene's wind speed v0;
    1/3 is Loyd's (1980) optimum for crosswind-free pulling. P_ref is P at the trim in the undisturbed
    wind, so the power term is 1 at the nominal operating point.

    Penalties saturate, S(x) = 1 - exp(-x), so a step's reward is at least w_P P/P_ref - (w_y + w_w + w_u):
    bounded below, unlike quadratic penalties, which grow without limit and can make ending an episode early
    pay. The lateral weight is 1: a first
    PPO run with 0.3 learned to park the wing 80 m to the side, where it pulls 1.8 times the trim power, and
    paid the saturated penalty; with w_y = 1 a sideways station costs more than it gains, so the reward asks
    for what the task says (power while laterally stable, laddermill_gym/docs/lateral_stability.md).

    * S(dy): x = mean over wings of (dy / lateral_scale)^2, dy the lateral CG offset [m];
      lateral_scale [m] defaults to 5 % of the cable piece length;
    * S(rates): x = mean over wings of (p^2 + r^2) / rate_scale^2 [rad/s];
    * S(effort): x = mean of (a - a_nominal)^2 over the normalised action entries.

    ``failure_penalty`` [-] is subtracted once, in the step that ends an episode by a physical failure
    (``terminated``); default 0, so a return is the plain sum of the terms above. Training configs set it to
    make a crash cost more than the power a risky manoeuvre gains before it (``reward_failure`` in ``info``).

    ``reference_power_W`` [W]: a fixed P_ref instead of the trim's, so that returns compare across wind speeds
    and scenes (the power term is then P / reference_power_W).
    """

    effort_weight: float = 0.1
    reel_speed_fraction: float = 1.0 / 3.0
    failure_penalty: float = 0.0
    reference_power_W: float | None = None

    def __post_init__(self):
        super().__post_init__()
        check_reference_power(self)
        if self.reel_speed_fraction <= 0:
            raise ValueError(f"reward.reel_speed_fraction = {self.reel_speed_fraction!r}: must be > 0")


@dataclass(frozen=True)
class TerminationConfig(FailureLimits):
    """When an episode ends as a physical failure (``terminated``).

    min_altitude [m]: a wing CG below it counts as ground contact; default half the wing span (a wing rolled
    to 90 deg at that height touches the ground with a tip). A wing CG or cable node reaching the scene's
    ``integrator.ground_height`` within a control period (``ground_contact: stop``) is a ground contact too.
    breaking_factor [-]: the cable fails when an element's tension exceeds this times its breaking load.
    alpha_range_deg [deg], max_abs_beta_deg [deg]: the quasi-steady aerodynamic model is left "by far"
    (deep stall or reversed flow; the attached-flow range of the default wing is about -10 to 15 deg).
    """

    alpha_range_deg: tuple[float, float] = (-30.0, 60.0)
    max_abs_beta_deg: float = 60.0

    def __post_init__(self):
        super().__post_init__()  # min_altitude and breaking_factor, named
        self.check_range("alpha_range_deg")
        v = self.max_abs_beta_deg
        if isinstance(v, bool) or not (isinstance(v, numbers.Real) and v > 0):
            raise ValueError(f"termination.max_abs_beta_deg = {v!r}: must be a number > 0")


def config_from(value, cls, name: str):
    """An instance of the settings dataclass ``cls`` from ``value``: None (the defaults), an instance, or a dict of
    its fields. Raises ValueError naming ``name`` and the unknown keys or the value."""
    if value is None:
        return cls()
    if type(value) is cls:
        return value
    if isinstance(value, cls):  # a family's extension (another env's reward): its extra fields would be ignored
        raise ValueError(f"{name} = {value!r}: a {type(value).__name__}, not this env's {cls.__name__} (its extra "
                         f"fields would be ignored); pass a {cls.__name__} or a dict of its fields")
    if isinstance(value, dict):
        known = {f.name for f in dataclasses.fields(cls)}
        bad = sorted(set(value) - known)
        if bad:
            raise ValueError(f"{name}: unknown key(s) {bad}; known: {sorted(known)}")
        return cls(**value)
    raise ValueError(f"{name} = {value!r}: must be a dict or a {cls.__name__}")
