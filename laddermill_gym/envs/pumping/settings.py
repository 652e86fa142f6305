"""Settings of ``laddermill_gym/PumpingKite-v0``: the reward (frozen dataclass that validates its fields, naming field
and value) and the failure codes. Terminations use the wing envs' :class:`~laddermill_gym.envs.task.TerminationConfig`,
the random start the rotorcraft's :class:`~laddermill_gym.envs.rotorcraft.settings.InitialNoise`."""

from __future__ import annotations

from dataclasses import dataclass

from laddermill_gym.envs.rotorcraft.settings import InitialNoise
from laddermill_gym.envs.task_settings import ShapedRewardConfig, TerminationConfig

__all__ = ["PumpingRewardConfig", "InitialNoise", "TerminationConfig", "PUMPING_FAILURES"]

#: Termination causes (code -> name), the wing envs' codes; 0: still flying.
#: 5, the winch's reel-in end stop (``kernels/winch.py``: the first element under 5 % of its start length), is a
#: physical end, told apart from a numerical one (it was reported as 1 until 2026-12-07)
PUMPING_FAILURES: dict[int, str] = {0: "", 1: "integration failed (non-finite state, speed or rate limit, singular "
                                    "mass)", 2: "ground contact", 3: "cable over its breaking load",
                                    4: "aerodynamic range exceeded",
                                    5: "tether fully reeled in (below 5 % of its start length)"}


@dataclass(frozen=True)
class PumpingRewardConfig(ShapedRewardConfig):
    """Reward per control period of length dt: r = w_P E_el / (P_ref dt) - w_y S(dy) - w_w S(rates)
    - failure_penalty [terminated], S(x) = 1 - exp(-x) (bounded below).

    E_el [J] is the electrical energy of the period: eta dE while the winch generates (dE > 0, the mechanical
    energy at the drum), dE / eta while it reels in (dE < 0) (Lansdorp et al. 2008 eq. 13), so the power terms of
    an episode sum to its net electrical energy over P_ref dt. ``reference_power`` P_ref [W] scales it (default
    1 kW, the order of the scripted cycle's mean on the default scene; docs/pumping.md).

    * S(dy): x = (dy / lateral_scale)^2, dy the lateral CG offset [m] from the wind plane; lateral_scale [m]
      defaults to 5 % of the tether's start length;
    * S(rates): x = (p^2 + r^2) / rate_scale^2, body roll and yaw rates [rad/s].

    ``failure_penalty`` [-] is subtracted once, in the step that ends an episode by a physical failure. Its default,
    1e5, is 5 MJ at P_ref dt = 50 J: more than the wing left without lateral control makes before it hits the ground
    (it diverges into crosswind flight and makes 1.8 MJ in 138 s, docs/pumping.md), about ten times the LQR-assisted
    cycle's 400 s; but less than controlled crosswind flight makes in 400 s (PPO's 11.7 MJ), so a crosswind flight
    that crashes late still ends with a positive return (PumpingKite-v1's penalty is 100 MJ).
    """

    lateral_weight: float = 0.1  # the other shared fields and their defaults: ShapedRewardConfig's
    reference_power: float = 1000.0
    failure_penalty: float = 1.0e5

    def __post_init__(self):
        super().__post_init__()
        if not self.reference_power > 0:
            raise ValueError(f"reward.reference_power = {self.reference_power!r}: must be > 0 W")
