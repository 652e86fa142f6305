"""Training configurations of Stable-Baselines3 agents (``configs/agents/ppo_*.yaml``, ``sac_*.yaml``): read
strictly (unknown keys, wrong types and bad values raise :class:`~laddermill_gym.model.configio.ConfigError` naming the
file, the field and the value) into a frozen :class:`RLConfig`, and turned into environments."""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from laddermill_gym.atmosphere.disturbance_spec import disturbance_from_dict
from laddermill_gym.control.rl_env_kwargs import check_env_kwargs, env_family
from laddermill_gym.control.rl_phases import (
    CriticWarmup,
    Validation,
    check_disturbances,
    read_critic_warmup,
    read_init_from,
    read_validation,
)
from laddermill_gym.envs import ENV_IDS, env_arguments, episode_argument_error
from laddermill_gym.envs.rotorcraft.task import CraftTask
from laddermill_gym.envs.task import WingTask
from laddermill_gym.model.configio import ConfigError, Section, find_config, read_yaml

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
    "wing": ("scene", "action_mode", "groups", "control_dt", "physics_dt", "alpha_servo_tau", "scene_options"),
    "craft": ("craft", "collective", "control_dt", "physics_dt"),
    "mill": ("scene", "scene_options", "control_dt", "groups", "n_bands", "surfaces", "generator_torque", "drum",
             "cable_speed_command", "speed", "operating_point", "settle", "authority"),
    "pumping": ("config", "scene_options", "control_dt"),
    "pointmass": ("scene", "scene_options", "control_dt", "groups", "pitch_range_deg", "roll_range_deg"),
}


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
    init_from : None, or a controller spec (``lqr``, ``lqr:<config>``) the linear actor of a PPO policy starts at
    policy : ``MlpPolicy`` (SB3's), ``ResidualPolicy`` (control/residual_policy.py: the controller plus a residual,
        PPO) or ``ResidualSACPolicy`` (control/residual_sac.py: the same for SAC)
        (:mod:`laddermill_gym.control.warm_start`; the observation statistics are then held fixed)
    critic_warmup, validation : None, or the optional phases of :mod:`laddermill_gym.control.rl_phases`
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
    init_from: str | None = None
    policy: str = "MlpPolicy"
    critic_warmup: CriticWarmup | None = None
    validation: Validation | None = None

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
        return carried_settings(self.env_id, self.env_kwargs)


def carried_settings(env_id: str, env_kwargs: dict[str, Any]) -> dict[str, Any]:
    """The entries of ``env_kwargs`` that an evaluation of a policy trained on ``env_id`` takes over
    (:data:`CARRIED_KWARGS` of its family): what a run records for ``control.trained_settings`` to check."""
    keys = CARRIED_KWARGS[env_family(env_id)]
    return {k: v for k, v in env_kwargs.items() if k in keys}


def _algorithm_class(name: str):
    import stable_baselines3 as sb3

    return getattr(sb3, name)


_RATE = dict(positive=True, high=1.0)
#: Bounds of the numeric Stable-Baselines3 arguments a config may set (others pass to SB3 unchecked): keyword
#: arguments of :meth:`Section.number`, ``optional``: None allowed, ``auto``: SB3's "auto" / "auto_X" text allowed.
HYPERPARAMETERS: dict[str, dict] = {
    "learning_rate": dict(_RATE, why="the optimiser's step (SB3's default 3e-4)"),
    "gamma": dict(_RATE, why="a discount factor"),
    "gae_lambda": dict(nonneg=True, high=1.0, why="GAE's lambda"),
    "clip_range": dict(_RATE, why="PPO's ratio clip (SB3's default 0.2)"),
    "clip_range_vf": dict(_RATE, optional=True, why="PPO's value clip"),
    "target_kl": dict(positive=True, optional=True),
    "tau": dict(_RATE, why="the target networks' soft-update fraction"),
    "ent_coef": dict(nonneg=True, high=1.0, auto=True, why="the entropy weight (SB3's PPO default 0, SAC 'auto')"),
    "target_entropy": dict(auto=True),
    "vf_coef": dict(nonneg=True, high=10.0, why="the value loss weight (SB3's default 0.5)"),
    "max_grad_norm": dict(positive=True),
    "n_steps": dict(integer=True, positive=True, high=100_000, why="steps per copy per rollout"),
    "batch_size": dict(integer=True, positive=True),
    "n_epochs": dict(integer=True, positive=True, high=1000, why="passes over each rollout (SB3's default 10)"),
    "buffer_size": dict(integer=True, positive=True, high=10**8, why="transitions held in memory (SB3's default "
                                                                    "1e6)"),
    "learning_starts": dict(integer=True, nonneg=True),
    "train_freq": dict(integer=True, positive=True, high=10_000, why="env steps per copy between updates (SB3: 1)"),
    "gradient_steps": dict(integer=True, low=-1.0, high=10_000, why="per update; -1: as many as env steps"),
    "target_update_interval": dict(integer=True, positive=True),
    "sde_sample_freq": dict(integer=True, low=-1.0, why="-1: only at the start of a rollout"),
    "stats_window_size": dict(integer=True, positive=True),
    "normalize_advantage": "flag", "use_sde": "flag", "use_sde_at_warmup": "flag", "optimize_memory_usage": "flag",
}


#: SB3 algorithm arguments a config does not set: the trainer's own, the private ``_init_setup_model``, the
#: ``*_class`` arguments and ``action_noise`` (Python objects) are left out of what it may set as well
NOT_HYPERPARAMETERS = frozenset({"policy", "env", "seed", "policy_kwargs", "tensorboard_log", "verbose", "device",
                                 "action_noise"})
#: The arguments SB3's algorithms give their default buffer themselves (a ``*_buffer_kwargs`` entry may set the rest)
BUFFER_SET_BY_SB3 = frozenset({"self", "buffer_size", "observation_space", "action_space", "device", "n_envs",
                               "gamma", "gae_lambda", "optimize_memory_usage"})


def _buffer_kwargs(hp: Section, key: str, value) -> dict:
    """``replay_buffer_kwargs`` / ``rollout_buffer_kwargs``: a mapping (or None) of the default buffer's arguments
    that SB3 does not set itself (ReplayBuffer: ``handle_timeout_termination``, a flag; RolloutBuffer: none);
    ConfigError naming ``hyperparameters.KEY.NAME`` otherwise."""
    from stable_baselines3.common.buffers import ReplayBuffer, RolloutBuffer

    if value is None:
        return {}
    if not isinstance(value, dict):
        raise hp.error(key, value, "must be a mapping of keyword arguments")
    cls = ReplayBuffer if key == "replay_buffer_kwargs" else RolloutBuffer
    known = sorted(set(inspect.signature(cls).parameters) - BUFFER_SET_BY_SB3)
    sub = Section(value, hp.file, f"{hp.path}.{key}")
    for name in value:
        if name not in known:
            raise sub.error(name, value[name], f"not an argument of {cls.__name__} a config may set (known: {known}; "
                            "SB3 sets the others itself)")
        if isinstance(inspect.signature(cls).parameters[name].default, bool):
            sub.flag(name)
    return dict(value)


def _is_number(text: str) -> bool:
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def read_hyperparameters(s: Section, algo: str, n_envs: int | None, total: int | None) -> dict:
    """The ``hyperparameters`` mapping, each name an argument of the SB3 algorithm and each number of
    :data:`HYPERPARAMETERS` within its bounds; a PPO minibatch within a rollout, a SAC one within the buffer,
    ``learning_starts`` within ``total_timesteps`` (left out where ``n_envs`` / ``total`` is None: a trainer that
    sizes them itself, the shared per-wing policy's)."""
    raw = s.raw("hyperparameters", {}) or {}
    if not isinstance(raw, dict):
        raise s.error("hyperparameters", raw, "must be a mapping")
    hp = Section(raw, s.file, f"{s.path}.hyperparameters" if s.path else "hyperparameters")
    known = {k for k in inspect.signature(_algorithm_class(algo)).parameters
             if k not in NOT_HYPERPARAMETERS and not k.startswith("_") and not k.endswith("_class")}
    out = {}
    for key, value in raw.items():
        rule = HYPERPARAMETERS.get(key)
        if key.endswith("_class") or key == "action_noise":
            raise hp.error(key, value, "a Python object: set it in Python (stable_baselines3), not in a config")
        if key not in known:
            raise hp.error(key, value, f"not an argument of {algo} a config may set (known: {sorted(known)})")
        if key.endswith("_buffer_kwargs"):
            out[key] = _buffer_kwargs(hp, key, value)
        elif rule == "flag":
            out[key] = hp.flag(key)
        elif rule is None or (value is None and rule.get("optional")):
            out[key] = hp.raw(key)
        elif rule.get("auto") and isinstance(value, str):  # SAC's "auto"; ent_coef also "auto_<initial value>"
            head, sep, tail = value.partition("_")  # SB3 takes target_entropy "auto" or a number, and an initial
            initial = key == "ent_coef" and _is_number(tail) and float(tail) > 0  # ent_coef above 0 (it logs it)
            if algo != "SAC" or head != "auto" or (sep and not initial):
                raise hp.error(key, value, "'auto'" + (" (or 'auto_<number > 0>', its initial value)" if key ==
                                                       "ent_coef" else "") + " is SAC's only")
            out[key] = value
        else:
            out[key] = hp.number(key, **{k: v for k, v in rule.items() if k not in ("optional", "auto")})
    rollout = None if n_envs is None else out.get("n_steps", 2048) * n_envs
    limits = (("batch_size", rollout, "a rollout (n_steps x n_envs)") if algo == "PPO"
              else ("batch_size", out.get("buffer_size", 10**6), "the replay buffer (buffer_size)"),
              ("learning_starts", total, "total_timesteps"), ("train_freq", total, "total_timesteps"))
    for key, most, what in limits:
        if key in out and most is not None and out[key] > most:
            raise hp.error(key, out[key], f"must be at most {most} ({what})")
    if out.get("optimize_memory_usage") and (out.get("replay_buffer_kwargs") or {}).get(
            "handle_timeout_termination", True):  # SB3's ReplayBuffer refuses the two together
        raise hp.error("optimize_memory_usage", True, "needs replay_buffer_kwargs: {handle_timeout_termination: "
                       "false} (SB3's ReplayBuffer does not support both)")
    if out.get("gradient_steps") == 0:  # SB3 then skips every update
        raise hp.error("gradient_steps", 0, "must be -1 (as many as env steps) or at least 1: 0 would train nothing")
    if algo == "PPO" and out.get("batch_size", 64) < 2:  # SB3's PPO asserts it (its advantages are normalised)
        raise hp.error("batch_size", out["batch_size"], "must be at least 2 (PPO normalises a minibatch's advantages)")
    return out


#: policy_kwargs a config may set (SB3 names) and their checks; a Python class (activation_fn, ...) cannot be given
POLICY_NUMBERS: dict[str, dict] = {
    "log_std_init": dict(low=-20.0, high=2.0, why="the log of the initial action noise std (SB3's default 0)"),
    "n_critics": dict(integer=True, positive=True, high=10),
    "clip_mean": dict(positive=True),
    "residual_limit": dict(positive=True, high=2.0, why="a fraction of each control's half range: the bound of "
                           "ResidualPolicy's residual (2 spans the whole action range)"),
}


def _read_policy_kwargs(s: Section, algo: str, policy_name: str = "MlpPolicy") -> dict:
    """The ``policy_kwargs`` mapping: names of the SB3 policy's arguments, ``net_arch`` a list (or a mapping of
    lists) of layer sizes 1..4096, the numbers of :data:`POLICY_NUMBERS`, flags true or false."""
    raw = s.raw("policy_kwargs", {}) or {}
    if not isinstance(raw, dict):
        raise s.error("policy_kwargs", raw, "must be a mapping")
    pk = Section(raw, s.file, "policy_kwargs")
    if algo == "SAC":
        from stable_baselines3.sac.policies import SACPolicy as policy
    else:
        from stable_baselines3.common.policies import ActorCriticPolicy as policy
    known = set(inspect.signature(policy).parameters) - {"observation_space", "action_space", "lr_schedule"}
    if policy_name in ("ResidualPolicy", "ResidualSACPolicy"):
        known.add("residual_limit")  # control/residual_policy.py's and residual_sac.py's own argument
    if policy_name == "ResidualSACPolicy":
        known.add("residual_after_squash")  # control/residual_sac.py's flag: the LQR added after SAC's squash
        known.add("residual_base_clipped")  # and its flag: the LQR's action clipped before that
    for key, value in raw.items():
        if key not in known:
            raise pk.error(key, value, f"not an argument of {policy.__name__} (known: {sorted(known)})")
        if key == "net_arch":
            layers = value if isinstance(value, dict) else {"": value}
            parts = {"pi", "qf"} if algo == "SAC" else {"pi", "vf"}  # SB3 ignores any other (a typo: no critic)
            for part in layers:
                if part and part not in parts:
                    raise pk.error(f"net_arch.{part}", layers[part], f"not a part of {algo}'s networks "
                                   f"({', '.join(sorted(parts))})")
            if isinstance(value, dict) and algo == "SAC" and set(layers) != parts:
                raise pk.error("net_arch", value, "SAC's mapping needs both pi and qf")
            for part, sizes in layers.items():  # a part of a mapping may be [] (pi: []: a linear actor)
                if not (isinstance(sizes, list) and (sizes or part) and all(
                        isinstance(n, int) and not isinstance(n, bool) and 1 <= n <= 4096 for n in sizes)):
                    raise pk.error(f"net_arch{'.' + part if part else ''}", sizes,
                                   "must be a list of layer sizes, whole numbers 1..4096 (empty only as a part "
                                   "of a mapping, pi: [] for a linear actor)")
        elif key in POLICY_NUMBERS:
            pk.number(key, **POLICY_NUMBERS[key])
        elif key.endswith("_class") or key == "activation_fn":
            raise pk.error(key, value, "a Python class: set it in Python (stable_baselines3), not in a config")
        elif key in ("optimizer_kwargs", "features_extractor_kwargs"):  # passed to the default classes' __init__
            own = {"actor_lr_scale"} if policy_name == "ResidualSACPolicy" and key == "optimizer_kwargs" else set()
            _check_class_kwargs(pk, key, value, policy, own)  # residual_sac.py's own: the actor's slower rate
        elif key in ("residual_after_squash", "residual_base_clipped") or isinstance(
                inspect.signature(policy).parameters[key].default, bool):
            pk.flag(key)
    return dict(raw)


def _check_class_kwargs(pk: Section, key: str, value, policy, own: set[str] = frozenset()) -> None:
    """ConfigError naming ``policy_kwargs.KEY`` unless ``value`` is a mapping (or None) of arguments of the class it
    goes to: the policy's default optimizer (Adam) or features extractor (a typo failed in torch or SB3 on a
    traceback)."""
    if value is None:
        return
    if not isinstance(value, dict):
        raise pk.error(key, value, "must be a mapping of keyword arguments")
    cls = inspect.signature(policy).parameters[key.replace("_kwargs", "_class")].default
    known = (set(inspect.signature(cls).parameters) - {"self", "params", "observation_space"}) | set(own)
    for name in value:
        if name not in known:
            raise pk.error(f"{key}.{name}", value[name], f"not an argument of {cls.__name__} (known: "
                           f"{sorted(known)})")


def load_rl_config(path: str | Path) -> RLConfig:
    """Read and validate a training config (``path``: a file, or the bare name of a shipped one,
    ``ppo_tethered_wing``; needs the ``rl`` extra for the hyperparameter check)."""
    path = find_config("agents", path, "config")
    s = read_yaml(path)
    algo = s.text("algorithm", choices=ALGORITHMS)
    env_id = s.text("env", choices=tuple(ENV_IDS))
    n_envs = s.number("n_envs", integer=True, positive=True, high=4096,
                      why="copies of one batched kernel; the shipped configs use 4 to 32")
    env_kwargs = s.raw("env_kwargs", {}) or {}
    if not isinstance(env_kwargs, dict):
        raise s.error("env_kwargs", env_kwargs, "must be a mapping")
    known = env_kwargs_known(env_id)
    for key in env_kwargs:
        if key not in known:
            raise s.error(f"env_kwargs.{key}", env_kwargs[key],
                          f"unknown argument of {env_id} (known: {', '.join(known)})")
    check_env_kwargs(s, env_id, env_kwargs)
    disturbances = check_disturbances(s)
    cfg = dict(
        algorithm=algo, env_id=env_id, n_envs=n_envs, env_kwargs=dict(env_kwargs), disturbances=disturbances,
        normalize_observations=s.flag("normalize_observations", True),
        seed=s.number("seed", 0, integer=True, nonneg=True, high=2 ** 32 - 1, why="numpy's seed range"),
        total_timesteps=s.number("total_timesteps", integer=True, positive=True),
        time_limit_minutes=s.number("time_limit_minutes", positive=True),
        checkpoint_every=s.number("checkpoint_every", integer=True, positive=True),
    )
    ev = s.section("eval")
    cfg["eval_every"] = ev.number("every", integer=True, positive=True)
    cfg["eval_episodes"] = ev.number("episodes", integer=True, positive=True, high=1000,
                                     why="each evaluation runs them all")
    ev.done()
    hyper = read_hyperparameters(s, algo, n_envs, cfg["total_timesteps"])
    cfg["policy"] = s.text("policy", "MlpPolicy", choices=("MlpPolicy", "ResidualPolicy", "ResidualSACPolicy"))
    pk = _read_policy_kwargs(s, algo, cfg["policy"])
    if algo == "PPO" and pk.get("squash_output") and not hyper.get("use_sde"):  # SB3's ActorCriticPolicy asserts it
        raise s.error("policy_kwargs.squash_output", pk["squash_output"], "needs hyperparameters.use_sde: true "
                      "(SB3's PPO squashes only gSDE actions)")
    init_from = read_init_from(s, algo, pk, cfg["normalize_observations"], cfg["policy"])
    phases = dict(critic_warmup=read_critic_warmup(s, init_from, cfg["total_timesteps"]), validation=read_validation(s))
    if phases["critic_warmup"] is not None and algo == "SAC" and str(hyper.get("ent_coef", "auto")).startswith("auto"):
        raise s.error("critic_warmup", s.raw("critic_warmup"), "with SAC needs a fixed hyperparameters.ent_coef (got "
                      f"{hyper.get('ent_coef', 'auto')!r}): the learned one would drift while the actor is frozen")
    val = phases["validation"]
    if val is not None:  # its episodes fly the training's control period: a whole number of them (else at once)
        why = episode_argument_error(env_id, dict(cfg["env_kwargs"], episode_time=val.episode_time))
        if why:
            raise ConfigError(f"{s.file}: field 'validation.episode_time' = {val.episode_time!r}: {why}")
    s.done()
    return RLConfig(file=Path(path), hyperparameters=hyper, policy_kwargs=pk, init_from=init_from, **phases, **cfg)
