"""The control settings a trained policy was trained with, checked against the env it is asked to fly.

A policy's observation and action sizes can match an env whose actions mean other things: ``ppo_tethered_wing`` on
TetheredWing-v0 with ``action_mode="alpha"`` (angle-of-attack commands instead of tail deflections) or with
``control_dt=0.1`` (twice its period) has the same spaces. :func:`check_trained_settings` compares the settings the
harness carries over from a run (``rl_config.CARRIED_KWARGS`` of the env's family: action mode and groups, control
period, scene and its options ...) as the training had them (its registered defaults and its own arguments) with the
env's, and raises ValueError naming the file, each setting and both values. The physics step (``physics_step``,
``physics_dt``) is not the policy's: TetheredWing-v0's policy flies v1 (``envs.same_task``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from laddermill_gym.envs import ENV_IDS, registered_arguments, same_task, task_class

__all__ = ["training_settings", "settings_of", "check_trained_settings", "carried_to"]

#: settings the check leaves out: the physics step is the env's (TetheredWing-v0's policies fly v1), and so are
#: the integrator's entries of ``scene_options`` (``load_scene``'s ``method`` and ``dt``: v0 registers its W method
#: there)
PHYSICS_KEYS = ("physics_step", "physics_dt")
PHYSICS_SCENE_OPTIONS = ("method", "dt")


def carried_to(trained_env: str, env_id: str | None, carried: dict[str, Any]) -> dict[str, Any]:
    """A run's carried settings ``carried`` (trained on ``trained_env``) for flying its policy on ``env_id``: without
    the physics step (:data:`PHYSICS_KEYS`, the integrator's ``scene_options``) where ``env_id`` is another id of the
    same task, which steps its own physics (a v0 config's ``physics_dt: 0.05`` made TetheredWing-v1 step RK4 at
    50 ms, neither id's step; review of 2026-12-08)."""
    if env_id is None or env_id == trained_env:
        return dict(carried)
    out = {k: v for k, v in carried.items() if k not in PHYSICS_KEYS}
    if isinstance(out.get("scene_options"), dict):
        out["scene_options"] = _policy_part("scene_options", out["scene_options"])
    return out


def _policy_part(key: str, value):
    """``value`` of setting ``key`` without its physics-step entries (a tuple as the list a YAML file gives)."""
    if key == "scene_options" and isinstance(value, dict):
        return {k: v for k, v in value.items() if k not in PHYSICS_SCENE_OPTIONS}
    return list(value) if isinstance(value, tuple) else value


def settings_of(env_id: str, env_kwargs: dict[str, Any], keys: list[str]) -> dict[str, Any]:
    """The settings ``keys`` of ``env_id`` with ``env_kwargs``: the registered arguments merged as
    ``gymnasium.make`` merges them, else the task class's own default (``action_mode`` 'tail' of a wing id registers
    none), else None."""
    import inspect

    args = registered_arguments(env_id, env_kwargs)
    params = inspect.signature(task_class(env_id)).parameters
    defaults = {k: p.default for k, p in params.items() if p.default is not inspect.Parameter.empty}
    return {k: _policy_part(k, args[k] if k in args else defaults.get(k)) for k in keys}


def training_settings(path: str | Path) -> tuple[Path, str, dict[str, Any]] | None:
    """(file that says so, env id, env arguments) the policy at ``path`` (a run folder or a model file in one) was
    trained with: a shared policy's ``shared_policy.yaml``, an rl-zoo3 run's arguments, a ``laddermill train`` run's
    ``config.yaml``; None when its folder records none (a bare model file)."""
    from laddermill_gym.control.sb3_policy import read_run_config, run_folder
    from laddermill_gym.control.shared_controller import SHARED_POLICY_FILE, read_shared_meta
    from laddermill_gym.control.zoo_run import find_zoo_run, read_zoo_run

    path = Path(path)
    if find_zoo_run(path) is not None:
        run = read_zoo_run(path)
        return run.folder, run.env_id, dict(run.env_kwargs)
    folder = path if path.is_dir() else run_folder(path)
    if (folder / SHARED_POLICY_FILE).is_file():
        meta = read_shared_meta(folder / SHARED_POLICY_FILE)
        return folder / SHARED_POLICY_FILE, str(meta["env"]), dict(meta.get("env_kwargs") or {})
    config = folder / "config.yaml"
    data = read_run_config(config)
    if data is None or data.get("env") not in ENV_IDS:
        return None  # no training run's config: the policy's own checks name what they miss
    return config, str(data["env"]), dict(data.get("env_kwargs") or {})


def check_trained_settings(path: str | Path, env_id: str, env_kwargs: dict[str, Any]) -> None:
    """ValueError naming the run's file and every carried setting whose value in training differs from the env's
    (``env_id`` with ``env_kwargs``, the registered arguments merged as ``gymnasium.make`` merges them)."""
    from laddermill_gym.control.rl_config import CARRIED_KWARGS, env_family

    found = training_settings(path)
    if found is None:
        return
    source, trained_env, trained_kwargs = found
    if trained_env not in ENV_IDS or not same_task(trained_env, env_id):
        return  # another env: the policy's env check names it
    keys = [k for k in CARRIED_KWARGS[env_family(env_id)] if k not in PHYSICS_KEYS]
    trained, here = settings_of(trained_env, trained_kwargs, keys), settings_of(env_id, env_kwargs, keys)
    differ = [k for k in keys if trained[k] != here[k]]
    if differ:
        was = ", ".join(f"{k} = {trained[k]!r}" for k in differ)
        now = ", ".join(f"{here[k]!r}" for k in differ)
        raise ValueError(f"{source}: trained with {was}; {env_id} here has {now}: its actions and observations "
                         "would mean other things (evaluate it with its own settings: laddermill evaluate and "
                         "gust-bench carry them over)")
