"""The config of a shared per-wing policy's training (``laddermill train configs/agents/ppo_mill_v1.yaml``):
read strictly, every error naming the file, the field and the value. See :mod:`.shared_train` for what each part
does."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_dict
from laddermill_gym.control.rl_config import check_env_kwargs, read_hyperparameters
from laddermill_gym.envs import env_arguments
from laddermill_gym.model.configio import find_config, read_yaml
from laddermill_gym.multiagent.agents import AGENT_KINDS

__all__ = ["SharedTrainConfig", "load_shared_config", "is_shared_config"]

#: The marker key of a shared per-wing policy's training config.
MARKER = "shared_policy"


@dataclass(frozen=True)
class SharedTrainConfig:
    """One shared-policy training run (units in the field comments of configs/agents/ppo_mill_v1.yaml)."""

    file: Path
    algorithm: str
    env_id: str
    k: int
    n_basis: int
    env_kwargs: dict[str, Any]
    disturbances: list[dict[str, Any]]
    seed: int
    time_limit_minutes: float
    bc_iterations: int
    bc_copies: int
    bc_steps: int
    bc_ridge: float
    bc_action_noise: float
    ppo_copies: int
    ppo_timesteps: int
    ppo_minutes: float
    log_std_init: float
    value_net: tuple[int, ...]
    eval_episodes: int
    eval_time: float
    eval_every: int
    hyperparameters: dict[str, Any] = field(default_factory=dict)
    teacher_config: Path | None = None  # the teacher's LQR config (None: the env's default design)

    def train_env_kwargs(self) -> dict[str, Any]:
        """The env arguments of training: overrides plus the disturbances drawn per episode."""
        kw = dict(self.env_kwargs)
        if self.disturbances:
            kw["disturbances"] = [disturbance_from_dict(d, f"{self.file}: disturbances[{i}]")
                                  for i, d in enumerate(self.disturbances)]
        return kw


def is_shared_config(path: str | Path) -> bool:
    """Whether the training config ``path`` (a file or a shipped name) is a shared per-wing policy's."""
    s = read_yaml(find_config("agents", path, "config"))
    return bool(s.raw(MARKER, False))


def load_shared_config(path: str | Path) -> SharedTrainConfig:
    """Read and check a shared-policy training config (``path``: a file or a shipped config's name)."""
    path = find_config("agents", path, "config")
    s = read_yaml(path)
    if s.raw(MARKER) is not True:
        raise s.error(MARKER, s.raw(MARKER), "must be true in a shared per-wing policy's config")
    algo = s.text("algorithm", choices=("PPO",))
    # the point-mass chain's kites have a per-agent interface but no LQR teacher or lateral columns here
    env_id = s.text("env", choices=tuple(e for e, kind in AGENT_KINDS.items() if kind != "kite"))
    env_kwargs = s.raw("env_kwargs", {}) or {}
    if not isinstance(env_kwargs, dict):
        raise s.error("env_kwargs", env_kwargs, "must be a mapping")
    known = env_arguments(env_id)
    for key in env_kwargs:
        if key not in known or key in ("disturbances", "groups"):
            raise s.error(f"env_kwargs.{key}", env_kwargs[key], f"not an argument a per-wing training may set "
                          f"(known: {', '.join(a for a in known if a not in ('disturbances', 'groups'))})")
    check_env_kwargs(s, env_id, env_kwargs)  # values, as laddermill train's configs (episode_time -5 passed)
    dist = s.raw("disturbances", []) or []
    if not isinstance(dist, list):
        raise s.error("disturbances", dist, "must be a list of mappings")
    for i, d in enumerate(dist):
        try:
            disturbance_from_dict(d, f"{path}: disturbances[{i}]")
        except ValueError as err:  # a traceback on the command line before
            raise s.error(f"disturbances[{i}]", d, str(err)) from None
    teacher = s.raw("teacher", None)
    if teacher is not None and not isinstance(teacher, str):
        raise s.error("teacher", teacher, "must be an LQR config's file or shipped name (configs/agents)")
    cfg: dict[str, Any] = dict(
        teacher_config=None if teacher is None else find_config("agents", teacher, f"{path}: teacher"),
        algorithm=algo, env_id=env_id, env_kwargs=dict(env_kwargs), disturbances=list(dist),
        k=s.number("k", integer=True, nonneg=True, high=10, why="neighbours seen on each side"),
        n_basis=s.number("n_basis", integer=True, positive=True, high=1000, why="hat functions of the position"),
        seed=s.number("seed", 0, integer=True, nonneg=True, high=2 ** 31 - 1, why="numpy's seed range"),
        time_limit_minutes=s.number("time_limit_minutes", positive=True, high=120.0,
                                    why="issue 31: at most 2 hours on this machine"))
    bc = s.section("imitation")
    cfg.update(bc_iterations=bc.number("iterations", integer=True, positive=True, high=100),
               bc_copies=bc.number("n_copies", integer=True, positive=True, high=256),
               bc_steps=bc.number("steps", integer=True, positive=True, high=100000),
               bc_ridge=bc.number("ridge", nonneg=True),
               bc_action_noise=bc.number("action_noise", 0.0, nonneg=True, high=1.0,
                                         why="std of the flown actions' noise, in normalised action units"))
    bc.done()
    ppo = s.section("ppo")
    cfg.update(ppo_copies=ppo.number("n_copies", integer=True, positive=True, high=256),
               ppo_timesteps=ppo.number("total_timesteps", integer=True, nonneg=True),
               ppo_minutes=ppo.number("time_limit_minutes", nonneg=True),
               log_std_init=ppo.number("log_std_init", high=1.0))
    vf = ppo.raw("value_net", [64, 64])
    if not isinstance(vf, list) or not all(isinstance(v, int) and not isinstance(v, bool) and 0 < v <= 1024
                                           for v in vf):
        raise ppo.error("value_net", vf, "must be a list of hidden layer widths (integers 1-1024)")
    cfg["value_net"] = tuple(vf)
    # names and values as laddermill train's configs check them (a learning rate of -1 or a text batch size
    # passed and failed in SB3 once the mill was built); the rollout's size is the trainer's (agents x copies)
    cfg["hyperparameters"] = read_hyperparameters(ppo, "PPO", None, None)
    ppo.done()
    ev = s.section("eval")
    cfg.update(eval_episodes=ev.number("episodes", integer=True, positive=True, high=64),
               eval_time=ev.number("episode_time", positive=True),
               eval_every=ev.number("every", integer=True, positive=True))
    ev.done()
    s.done()
    return SharedTrainConfig(file=Path(path), **cfg)
