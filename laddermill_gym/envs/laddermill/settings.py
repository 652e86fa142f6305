"""Settings of ``laddermill_gym/LadderMill-v0``: the reward weights and the generator drum (frozen dataclasses that
validate their fields, naming field and value). Terminations use the wing envs'
:class:`~laddermill_gym.envs.task.TerminationConfig`, the random start the rotorcraft's
:class:`~laddermill_gym.envs.rotorcraft.settings.InitialNoise` (applied to every wing)."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from laddermill_gym.envs.rotorcraft.settings import InitialNoise, RotorcraftRewardConfig
from laddermill_gym.envs.task import TerminationConfig

__all__ = ["MillRewardConfig", "DrumConfig", "InitialNoise", "TerminationConfig", "MILL_FAILURES"]

#: Termination causes (code -> name), the wing envs' codes; 0: still flying.
MILL_FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state, speed or rate limit, singular mass)",
                                 2: "ground contact", 3: "cable over its breaking load",
                                 4: "aerodynamic range exceeded"}


@dataclass(frozen=True)
class MillRewardConfig(RotorcraftRewardConfig):
    """Reward per control period: r = w_P P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty.

    P [W] is the simulated generator's electrical power at the end of the control period: the station's
    efficiency times the mechanical power (T_first - T_last) V_c with a prescribed cable speed, (Q / r) V_c with a
    drum, and that power over the efficiency while it is negative (motoring; ``sim.generator_power()``); P_ref [W]
    is the mean electrical power of the operating point's period
    (:class:`~laddermill_gym.envs.laddermill.operating_point.OperatingPoint`), so the power term averages about 1
    over a period of the undisturbed operating point. S(x) = 1 - exp(-x) saturates (bounded below):

    * S(dy): x = mean over slots of (dy / lateral_scale)^2, dy the lateral CG offset [m] from the (in-plane)
      reference orbit; lateral_scale [m] defaults to 5 % of the piece length;
    * S(rates): x = mean over slots of (p^2 + r^2) / rate_scale^2, body roll and yaw rates [rad/s];
    * S(effort): x = mean of a^2 over the normalised action entries (a = 0 holds the operating point).

    ``failure_penalty`` [-] is subtracted once, in the step that ends an episode by a physical failure.
    """

    rate_scale: float = 0.5  # [rad/s] the fields, their checks and the other defaults are the rotorcraft's


@dataclass(frozen=True)
class DrumConfig:
    """The generator drum used when the generator torque is an action (``generator_torque=True``;
    ``model/station.py``: (J / r^2) dV_c/dt = T_first - T_last - Q / r).

    radius [m], inertia [kg m^2] (drum and generator rotor): J / r^2 = 1000 kg by default, a fifth of the wings'
    mass of the default mill; torque_half_range [N m]: the torque per unit normalised action (default: the
    operating point's torque r P_ref / (efficiency V_c), P_ref the operating point's power, whatever the reward's
    reference_power_W), so a = -1 gives (about) no torque and a = +1 twice the
    operating point's.

    Time scale: the cable's speed answers a torque step dQ within (J / r^2) / (dQ / r) per m/s. At the defaults on
    LadderMill-v1 a = +1 (dQ = 76 kN m) reverses the 2 m/s cable within one 50 ms control period (V_c = -0.97 m/s
    after 0.05 s, a backward transfer after 0.10 s; a review of 2026-12-07): the torque's full range is as hard to
    learn as the surfaces' full authority was. A larger ``inertia`` or a smaller ``torque_half_range`` slows it.
    """

    radius: float = 1.0
    inertia: float = 1000.0
    torque_half_range: float | None = None

    def __post_init__(self):
        for name in ("radius", "inertia", "torque_half_range"):
            v = getattr(self, name)
            if v is None and name == "torque_half_range":
                continue
            if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
                raise ValueError(f"drum.{name} = {v!r}: must be a finite number > 0")


@dataclass(frozen=True)
class SpeedCommandConfig:
    """The generator's speed controller when the cable speed is an action (``cable_speed_command=True``; station
    mode 'commanded', ``model/station.py``: dV_c/dt = (V_cmd - V_c) / time_constant).

    half_range [m/s]: commanded speed per unit normalised action (default: the operating point's V_c, so a in
    [-1, 1] spans 0..2 V_c); time_constant [s]: the controller's (chosen: 1 s, fast against the mill's 35 s period
    and slower than the 50 ms control period, so a command is a smooth change of speed).
    """

    half_range: float | None = None
    time_constant: float = 1.0

    def __post_init__(self):
        for name in ("half_range", "time_constant"):
            v = getattr(self, name)
            if v is None and name == "half_range":
                continue
            if isinstance(v, bool) or not (isinstance(v, numbers.Real) and math.isfinite(v) and v > 0):
                raise ValueError(f"speed.{name} = {v!r}: must be a finite number > 0")
