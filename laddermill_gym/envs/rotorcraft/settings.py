"""Settings of :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv`: reward weights, termination limits and
the random start perturbations (frozen dataclasses that validate their fields, naming field and value)."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from laddermill_gym.envs.task_settings import (
    FailureLimits,
    ShapedRewardConfig,
    check_nonnegative_fields,
    check_reference_power,
)


@dataclass(frozen=True)
class RotorcraftRewardConfig(ShapedRewardConfig):
    """Reward per control period: r = w_P P / P_ref - w_y S(y) - w_w S(rates) - w_u S(effort), S(x) = 1 - exp(-x).

    P [W] is the craft's net electrical power (:meth:`CraftSimulator.electrical_power`, Roberts' 95 %
    efficiency), P_ref its value at the trim in the undisturbed wind, so the power term is 1 at the trim.

    * S(y): x = (dy / lateral_scale)^2, dy the lateral CG offset [m]; lateral_scale [m] defaults to 5 % of the
      rear tether length;
    * S(rates): x = (p^2 + r^2) / rate_scale^2, body roll and yaw rates [rad/s];
    * S(effort): x = mean of (a - a_trim)^2 over the two normalised action entries.

    ``failure_penalty`` [-] is subtracted once, in the step that ends an episode by a physical failure.
    ``reference_power_W`` [W]: a fixed P_ref instead of the operating point's, so returns compare across winds.
    """

    rate_scale: float = 0.2  # the other shared fields and their defaults: ShapedRewardConfig's
    effort_weight: float = 0.1
    failure_penalty: float = 0.0
    reference_power_W: float | None = None

    def __post_init__(self):
        super().__post_init__()
        check_reference_power(self)


@dataclass(frozen=True)
class RotorcraftTerminationConfig(FailureLimits):
    """When an episode ends as a physical failure (``terminated``).

    min_altitude [m]: CG altitude below which the craft has hit the ground; default half its span (hub
    spacing + rotor diameter), where a craft rolled to 90 deg touches the ground with a rotor tip.
    breaking_factor [-]: a tether fails when an element's tension exceeds this times its breaking load.
    max_abs_roll_deg [deg], pitch_range_deg [deg], max_abs_yaw_deg [deg]: attitude far from the operating
    range of the quasi-steady rotor model (the trim pitch of the default craft is about 25 deg).
    blade_stall [bool]: end the episode when a retreating blade tip's incidence passes the craft's
    ``blade_incidence_limit`` (Roberts: 13 deg, configs/rotors/). The rotor model's lift is linear in the
    incidence, without stall, so past the limit it overstates thrust and power, and a policy is paid for leaving
    the model's validity (docs/rotorcraft.md). False (Rotorcraft-v0): not checked; True: Rotorcraft-v1's default.
    """

    max_abs_roll_deg: float = 60.0
    pitch_range_deg: tuple[float, float] = (-20.0, 80.0)
    max_abs_yaw_deg: float = 90.0
    blade_stall: bool = False

    def __post_init__(self):
        self.check_range("pitch_range_deg")
        for name in ("breaking_factor", "max_abs_roll_deg", "max_abs_yaw_deg"):
            v = getattr(self, name)
            if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
                raise ValueError(f"termination.{name} = {v!r}: must be a finite number > 0")
        if not isinstance(self.blade_stall, bool):
            raise ValueError(f"termination.blade_stall = {self.blade_stall!r}: must be true or false")
        super().__post_init__()


@dataclass(frozen=True)
class InitialNoise:
    """Random start: standard deviations of perturbations added to the trim at every reset, drawn from the
    env's ``np_random``: lateral_velocity [m/s] (global y), roll_rate [rad/s] (body p), yaw_rate [rad/s]
    (body r). Velocities only, so the tethers start at their trim stretch. All 0 (the default): the trim."""

    lateral_velocity: float = 0.0
    roll_rate: float = 0.0
    yaw_rate: float = 0.0

    def __post_init__(self):
        check_nonnegative_fields(self, "initial_noise")
