"""Training configurations of Stable-Baselines3 agents (``configs/agents/ppo_*.yaml``, ``sac_*.yaml``): read
strictly (unknown keys, wrong types and bad values raise :class:`~laddermill_gym.model.configio.ConfigError` naming the
file, the field and the value) into a frozen :class:`RLConfig`, and turned into environments."""

from __future__ import annotations

import inspect
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_dict
from laddermill_gym.envs import ENV_IDS, env_arguments, task_class
from laddermill_gym.envs.rotorcraft.task import CraftTask
from laddermill_gym.envs.task import WingTask
from laddermill_gym.model.configio import ConfigError, read_yaml

ALGORITHMS: tuple[str, ...] = ("PPO", "SAC")
#: WingTask arguments a config may override under ``env_kwargs`` (disturbances have their own section)
ENV_KWARGS: tuple[str, ...] = tuple(p for p in inspect.signature(WingTask).parameters
                                    if p not in ("n_copies", "disturbances", "parallel"))
#: RotorcraftEnv (CraftTask) arguments a config for ``laddermill_gym/Rotorcraft-v0`` may override under ``env_kwargs``
CRAFT_ENV_KWARGS: tuple[str, ...] = tuple(p for p in inspect.signature(CraftTask).parameters
                                          if p not in ("n_copies", "disturbances", "parallel"))
#: Arguments the evaluation env takes over from training (the policy's spaces and the model must match);
#: the rest (wind, disturbances, episode length, reward, termination) is the registered scenario's
CARRIED_KWARGS: dict[str, tuple[str, ...]] = {
    "wing": ("action_mode", "groups", "control_dt", "physics_dt", "alpha_servo_tau", "scene_options"),
    "craft": ("craft", "collective", "control_dt", "physics_dt"),
    "mill": ("scene", "scene_options", "control_dt", "groups", "n_bands", "surfaces", "generator_torque", "drum",
             "cable_speed_command", "speed", "operating_point", "settle"),
    "pumping": ("config", "scene_options", "control_dt"),
    "pointmass": ("scene", "scene_options", "control_dt", "groups", "pitch_range_deg", "roll_range_deg"),
}


def env_family(env_id: str) -> str:
    """'craft' (Rotorcraft-v0), 'mill' (the moving-cable LadderMill-v0), 'pumping' (PumpingKite-v0), 'pointmass'
    (PointMassChain-v0) or 'wing' (the fixed-cable wing scenes)."""
    if "craft" in ENV_IDS[env_id]:
        return "craft"
    name = task_class(env_id).__name__
    return {"MillTask": "mill", "PumpingTask": "pumping", "PointMassTask": "pointmass"}.get(name, "wing")


def env_kwargs_known(env_id: str) -> tuple[str, ...]:
    """The ``env_kwargs`` keys a config for the registered environment ``env_id`` may set."""
    family = env_family(env_id)
    if family in ("mill", "pumping", "pointmass"):
        return tuple(a for a in env_arguments(env_id) if a != "disturbances")
    return CRAFT_ENV_KWARGS if family == "craft" else ENV_KWARGS


@dataclass(frozen=True)
class RLConfig:
    """One training run.

    Attributes
    ----------
    file : Path
    algorithm : "PPO" or "SAC"
    env_id : registered environment id (:data:`laddermill_gym.envs.ENV_IDS`)
    n_envs : copies stepped together by the environment's batched kernel (:func:`laddermill_gym.envs.sb3.sb3_vec_env`
        over :class:`~laddermill_gym.envs.task.WingTask` or :class:`~laddermill_gym.envs.rotorcraft.task.CraftTask`)
    env_kwargs : overrides of the registered env arguments for training (episode_time [s], reward, ...):
        WingTask's arguments (:data:`ENV_KWARGS`) or, for Rotorcraft-v0, RotorcraftEnv's (:data:`CRAFT_ENV_KWARGS`)
    disturbances : list of disturbance mappings for training (``type`` plus parameters; ranges drawn per episode)
    normalize_observations : running mean / variance normalisation of observations (SB3 ``VecNormalize``)
    seed : int
    total_timesteps : env steps (all copies together)
    time_limit_minutes : wall-clock limit [min]; training stops at whichever limit comes first
    checkpoint_every, eval_every : env steps between checkpoints / evaluations
    eval_episodes : episodes of the registered evaluation scenario per evaluation (seeds 0 .. n - 1)
    hyperparameters : keyword arguments of the SB3 algorithm
    policy_kwargs : SB3 ``policy_kwargs`` (e.g. net_arch, log_std_init)
    """

    file: Path
    algorithm: str
    env_id: str
    n_envs: int
    env_kwargs: dict[str, Any]
    disturbances: list[dict[str, Any]]
    normalize_observations: bool
    seed: int
    total_timesteps: int
    time_limit_minutes: float
    checkpoint_every: int
    eval_every: int
    eval_episodes: int
    hyperparameters: dict[str, Any] = field(default_factory=dict)
    policy_kwargs: dict[str, Any] = field(default_factory=dict)

    @property
    def is_craft(self) -> bool:
        """Whether the environment is the rotorcraft (Rotorcraft-v0) rather than a wing scene."""
        return "craft" in ENV_IDS[self.env_id]

    def train_env_kwargs(self) -> dict[str, Any]:
        """WingTask (or RotorcraftEnv) arguments of the training environment: registered defaults, overrides,
        disturbances."""
        kw = dict(ENV_IDS[self.env_id])
        kw.update(self.env_kwargs)
        if self.disturbances:
            kw["disturbances"] = [disturbance_from_dict(d, f"{self.file}: disturbances[{i}]")
                                  for i, d in enumerate(self.disturbances)]
        return kw

    def eval_env_kwargs(self) -> dict[str, Any]:
        """The registered scenario (its own disturbance, episode length, reward and termination), with the
        training's control settings (:data:`CARRIED_KWARGS`: action mode, groups, control period, model; for the
        craft its config, trim collective, control period and physics step) so the policy's spaces match."""
        kw = dict(ENV_IDS[self.env_id])
        kw.update(self.carried_env_kwargs())
        return kw

    def carried_env_kwargs(self) -> dict[str, Any]:
        """The training's overrides of the arguments the evaluation takes over (:data:`CARRIED_KWARGS`)."""
        keys = CARRIED_KWARGS[env_family(self.env_id)]
        return {k: v for k, v in self.env_kwargs.items() if k in keys}


def _algorithm_class(name: str):
    import stable_baselines3 as sb3

    return getattr(sb3, name)


def load_rl_config(path: str | Path) -> RLConfig:
    """Read and validate a training config (needs the ``rl`` extra for the hyperparameter check)."""
    s = read_yaml(path)
    algo = s.text("algorithm", choices=ALGORITHMS)
    env_id = s.text("env", choices=tuple(ENV_IDS))
    n_envs = s.number("n_envs", integer=True, positive=True)
    env_kwargs = s.raw("env_kwargs", {}) or {}
    if not isinstance(env_kwargs, dict):
        raise s.error("env_kwargs", env_kwargs, "must be a mapping")
    known = env_kwargs_known(env_id)
    for key in env_kwargs:
        if key not in known:
            raise s.error(f"env_kwargs.{key}", env_kwargs[key],
                          f"unknown argument of {env_id} (known: {', '.join(known)})")
    disturbances = s.raw("disturbances", []) or []
    if not isinstance(disturbances, list):
        raise s.error("disturbances", disturbances, "must be a list of mappings with a 'type'")
    for i, d in enumerate(disturbances):
        try:
            disturbance_from_dict(d, f"disturbances[{i}]")
        except ValueError as err:
            raise ConfigError(f"{path}: {err}") from None
    cfg = dict(
        algorithm=algo, env_id=env_id, n_envs=n_envs, env_kwargs=dict(env_kwargs), disturbances=list(disturbances),
        normalize_observations=s.flag("normalize_observations", True),
        seed=s.number("seed", 0, integer=True, nonneg=True),
        total_timesteps=s.number("total_timesteps", integer=True, positive=True),
        time_limit_minutes=s.number("time_limit_minutes", positive=True),
        checkpoint_every=s.number("checkpoint_every", integer=True, positive=True),
    )
    ev = s.section("eval")
    cfg["eval_every"] = ev.number("every", integer=True, positive=True)
    cfg["eval_episodes"] = ev.number("episodes", integer=True, positive=True)
    ev.done()
    hyper = s.raw("hyperparameters", {}) or {}
    pk = s.raw("policy_kwargs", {}) or {}
    for key, value in (("hyperparameters", hyper), ("policy_kwargs", pk)):
        if not isinstance(value, dict):
            raise s.error(key, value, "must be a mapping")
    s.done()
    known = set(inspect.signature(_algorithm_class(algo)).parameters) - {"policy", "env", "seed", "policy_kwargs",
                                                                         "tensorboard_log", "verbose", "device"}
    for key, value in hyper.items():
        if key not in known:
            raise ConfigError(f"{path}: field 'hyperparameters.{key}' = {value!r}: not an argument of {algo} "
                              f"(known: {sorted(known)})")
    return RLConfig(file=Path(path), hyperparameters=dict(hyper), policy_kwargs=dict(pk), **cfg)
