"""The env arguments of a training config (``env_kwargs``), checked without building the env: each value against the
task's default's type and the bounds here, the settings mappings through the task's own dataclasses, the scene's
options against ``load_scene``, the physics step and the episode against the control period; and the env's family
(which arguments a run carries to its evaluation). Split from :mod:`laddermill_gym.control.rl_config`, which reads
the rest of a config and re-exports these."""

from __future__ import annotations

import inspect

from laddermill_gym.envs import ENV_IDS, episode_argument_error, registered_arguments, task_class
from laddermill_gym.envs.task_base import whole_multiple
from laddermill_gym.model.configio import ConfigError, Section, find_config

__all__ = ["ENV_KWARG_BOUNDS", "SETTINGS_BOUNDS", "check_env_kwargs", "env_family"]


def env_family(env_id: str) -> str:
    """'craft' (Rotorcraft-v0), 'mill' (the moving-cable LadderMill-v0), 'pumping' (PumpingKite-v0), 'pointmass'
    (PointMassChain-v0) or 'wing' (the fixed-cable wing scenes)."""
    if "craft" in ENV_IDS[env_id]:
        return "craft"
    name = task_class(env_id).__name__
    return {"MillTask": "mill", "PumpingTask": "pumping", "PointMassTask": "pointmass"}.get(name, "wing")


#: Upper bounds of the env arguments a config sets, beyond the envs' own checks (finite, > 0): (bound, why).
ENV_KWARG_BOUNDS: dict[str, tuple[float, str]] = {
    "episode_time": (86400.0, "s: a day of flight per episode"),
    "control_dt": (10.0, "s: a control period longer than the wings' fastest motion"),
    "physics_dt": (1.0, "s: as a scene's integrator.dt"),
    "wind_dt": (60.0, "s: the sampling of the disturbances' time histories"),
    "settle_time": (3600.0, "s: an hour of settling per episode"),
    "n_bands": (50.0, "bands per leg: the mill's 101 wings make 50 per leg"),
}
#: Upper bounds of the fields of the settings mappings (``initial_noise``: standard deviations): (bound, why).
SETTINGS_BOUNDS: dict[str, tuple[float, str]] = {
    "power_weight": (100.0, "a power term up to 100 times the other terms' weights"),
    "lateral_velocity": (150.0, "m/s: the fastest wind (ladder/bounds.py)"),
    "roll_rate": (100.0, "rad/s: the scenes' exploding-state guard max_rate"),
    "yaw_rate": (100.0, "rad/s: the scenes' exploding-state guard max_rate"),
    "pitch_rate": (100.0, "rad/s: the scenes' exploding-state guard max_rate"),
}
#: The settings dataclasses of env arguments given as mappings, by argument: (module of the task, class name).
_SETTINGS = {"reward": "reward_class", "termination": "termination_class", "initial_noise": "noise_class",
             "settle": "SettleConfig", "drum": "DrumConfig", "speed": "SpeedCommandConfig"}


def check_env_kwargs(s: Section, env_id: str, kwargs: dict) -> None:
    """ConfigError naming ``env_kwargs.NAME`` (and its value) for an argument the task would refuse or one beyond
    :data:`ENV_KWARG_BOUNDS`: its type against the task's default (flag, number, text), its settings mapping
    (``reward``, ``termination``, ...) through the task's own dataclass, and the named choices and files; checked
    without building the environment."""
    import sys

    from laddermill_gym.envs.actions import ACTION_MODES, GROUPINGS
    from laddermill_gym.envs.laddermill.actions import SLOT_GROUPINGS
    from laddermill_gym.envs.task_settings import RewardConfig, TerminationConfig, config_from

    task = task_class(env_id)
    params = inspect.signature(task).parameters
    ek = Section(kwargs, s.file, "env_kwargs")
    choices = {"action_mode": ACTION_MODES, "groups": SLOT_GROUPINGS if env_family(env_id) == "mill" else GROUPINGS}
    files = {"scene": "scenes", "craft": "rotorcraft", "config": "pumping"}
    for key, value in kwargs.items():
        default = params[key].default if key in params else None
        if key in _SETTINGS and (isinstance(value, dict) or value is None):
            name = _SETTINGS[key]
            cls = getattr(task, name, None) if name.endswith("_class") else getattr(sys.modules[task.__module__],
                                                                                    name, None)
            cls = cls or {"reward": RewardConfig, "termination": TerminationConfig}.get(key)
            try:
                if cls is not None:
                    config_from(value, cls, f"env_kwargs.{key}")
            except (TypeError, ValueError) as err:
                raise ConfigError(f"{s.file}: field 'env_kwargs.{key}' = {value!r}: {err}") from None
            sub = Section(value or {}, s.file, f"env_kwargs.{key}")
            for name in set(sub.data) & set(SETTINGS_BOUNDS):
                sub.number(name, nonneg=True, high=SETTINGS_BOUNDS[name][0], why=SETTINGS_BOUNDS[name][1])
        elif isinstance(default, bool):
            ek.flag(key)
        elif isinstance(default, (int, float)) or key in ENV_KWARG_BOUNDS:
            if value is not None or default is not None:
                high, why = ENV_KWARG_BOUNDS.get(key, (None, ""))
                ek.number(key, integer=isinstance(default, int), positive=bool(default) or key in ENV_KWARG_BOUNDS,
                          nonneg=True, high=high, why=why)
        elif key in files and value is not None:
            find_config(files[key], ek.text(key), f"{s.file}: field 'env_kwargs.{key}'")
        elif key in choices and not isinstance(value, list):
            ek.text(key, choices=choices[key])
    _check_scene_options(s, kwargs)
    if "physics_dt" in kwargs and kwargs["physics_dt"] is not None:  # a control period of whole physics steps
        control_dt = float(registered_arguments(env_id, kwargs).get("control_dt",
                                                                    params["control_dt"].default))
        try:
            whole_multiple(control_dt, float(kwargs["physics_dt"]), control_dt)
        except ValueError as err:
            raise ConfigError(f"{s.file}: field 'env_kwargs.physics_dt' = {kwargs['physics_dt']!r}: {err}") from None
    if "episode_time" in kwargs or "control_dt" in kwargs:  # an episode is a whole number of control periods
        why = episode_argument_error(env_id, kwargs)
        if why:
            key = "episode_time" if "episode_time" in kwargs else "control_dt"
            raise ConfigError(f"{s.file}: field 'env_kwargs.{key}' = {kwargs[key]!r}: {why}")


def _check_scene_options(s: Section, kwargs: dict) -> None:
    """ConfigError naming ``env_kwargs.scene_options`` unless it is a mapping (or None) of ``load_scene``'s
    keyword arguments (a typo failed in ``load_scene`` on a traceback)."""
    value = kwargs.get("scene_options")
    if value is None:
        return
    if not isinstance(value, dict):
        raise s.error("env_kwargs.scene_options", value, "must be a mapping of load_scene's keyword arguments")
    from laddermill_gym.ladder.scene import load_scene

    known = set(inspect.signature(load_scene).parameters) - {"name_or_path"}
    for name in value:
        if name not in known:
            raise s.error(f"env_kwargs.scene_options.{name}", value[name], f"not an argument of load_scene (known: "
                          f"{sorted(known)})")
        if name == "fidelity":  # the env passes its own (envs/task_env.check_scene_options)
            from laddermill_gym.envs.task_env import FIDELITY_IS_THE_ENVS

            raise s.error("env_kwargs.scene_options.fidelity", value[name], FIDELITY_IS_THE_ENVS)
