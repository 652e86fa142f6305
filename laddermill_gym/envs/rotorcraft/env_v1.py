"""``laddermill_gym/Rotorcraft-v1``: Rotorcraft-v0 whose episode also ends when a retreating blade tip passes the
rotor's blade-incidence limit. The same craft, trim, task, observations, actions and rewards as ``Rotorcraft-v0``
(:class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`); what differs is registered with the id
(``envs.ENV_IDS``): ``termination={"blade_stall": True}``. These classes carry the id's own page (docstring) and
version history, and apply the id's registered defaults when built directly (``registered_id``)."""

from __future__ import annotations

import warnings

from laddermill_gym.envs.rotorcraft.env import RotorcraftEnv, RotorcraftVectorEnv
from laddermill_gym.warning_site import user_stacklevel

__all__ = ["RotorcraftV1Env", "RotorcraftV1VectorEnv", "warn_without_blade_limit"]


class RotorcraftV1Env(RotorcraftEnv):
    """Roberts' tethered twin-rotor craft, its episode ended where the rotor model leaves its validity.

    ## Description

    Rotorcraft-v0's craft and task (Roberts' flying model at 10 m/s, the 0.01 rad wind-direction step at t = 1 s),
    with one more physical limit: a control period that ends with a retreating blade tip past the rotor's
    blade-incidence limit (Roberts sec. 4: 13 deg; ``configs/rotors/roberts_rotor.yaml``) ends the episode. The rotor
    model's lift is linear in the incidence, without stall, so past the limit it overstates the thrust and the power:
    on v0 the LQR with its collective at the 15 deg limit nearly doubles its return. On v0's gust scenarios (gusts-v5)
    every episode the LQR loses on v1 ends on this limit (docs/rotorcraft.md). The LQR with the blade-tip guard
    (``make_controller("lqr_guard", "laddermill_gym/Rotorcraft-v1")``: control/craft_tip_guard.py) lowers the
    collective in gusts before a tip reaches the limit.

    ## Action Space

    Rotorcraft-v0's: Box [-1, 1]^2 float32, collective and differential collective over their half ranges.

    ## Observation Space

    Rotorcraft-v0's: Box (19,) float32.

    ## Rewards

    Rotorcraft-v0's: r = P / P_ref - w_y S(dy) - w_w S(rates) - w_u S(effort) - failure_penalty [terminated], P the
    craft's net electrical power; every term is in ``info``, with ``max_tip_incidence_rad``.

    ## Starting State

    Rotorcraft-v0's trim. A ``wind_speed`` whose trim at the given (or the config's) collective puts a tip past the
    limit is refused, naming the blade-limited collective to pass instead.

    ## Episode End

    Rotorcraft-v0's, and ``terminated`` with ``info["failure_name"]`` "blade incidence past its limit" (the tip's
    incidence in ``info["failure_reason"]``); ``truncated`` at ``episode_time`` (120 s).

    ## Arguments

    Rotorcraft-v0's (:class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftEnv`); registered: craft
    ``roberts_flying_model``, control_dt 0.05 s, episode_time 120 s, termination ``{"blade_stall": True}``.
    ``termination={"blade_stall": False}`` makes it Rotorcraft-v0, with a warning (so does a
    ``RotorcraftTerminationConfig`` that leaves ``blade_stall`` at its False); ``termination=None`` is v1's.

    ## Version History

    * v1: the blade-incidence limit ends an episode; craft, spaces and rewards as v0.
    * v0: initial version (``laddermill_gym/Rotorcraft-v0``, unchanged).
    """

    registered_id = "laddermill_gym/Rotorcraft-v1"

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        warn_without_blade_limit(self.task)


class RotorcraftV1VectorEnv(RotorcraftVectorEnv):
    """``num_envs`` copies of :class:`RotorcraftV1Env` in one batch (Rotorcraft-v0's
    :class:`~laddermill_gym.envs.rotorcraft.env.RotorcraftVectorEnv` with Rotorcraft-v1's registered defaults)."""

    registered_id = "laddermill_gym/Rotorcraft-v1"

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        warn_without_blade_limit(self.task)


def warn_without_blade_limit(task) -> None:
    """A UserWarning when the task's termination does not end episodes at the blade-incidence limit, Rotorcraft-v1's
    one difference from Rotorcraft-v0 (a termination config built without ``blade_stall=True`` turns it off)."""
    if not task.termination_config.blade_stall:
        warnings.warn("Rotorcraft-v1 with termination.blade_stall off: the blade-incidence limit, v1's one difference "
                      "from Rotorcraft-v0, does not end episodes", UserWarning, stacklevel=user_stacklevel())
