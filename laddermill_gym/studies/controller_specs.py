"""Controller specs of the commands (``laddermill evaluate``, ``gust-bench``, ``demo``) against an environment: the
control settings a trained policy carries (:func:`policy_env_kwargs`) and every spec built before any episode runs
(:func:`build_controllers`; for a command, a spec the environment refuses is one line, ``--controllers 'SPEC':
...``). A shared module of ``studies`` (any topic, and ``harness``, may import it); imports ``control`` and
``envs``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from laddermill_gym.envs import ENV_IDS
from laddermill_gym.studies.commands import UsageError

__all__ = ["policy_env_kwargs", "build_controllers"]


def policy_env_kwargs(spec: str, env_id: str | None = None) -> dict:
    """The control settings a trained policy was trained with (the ``CARRIED_KWARGS`` of the ``config.yaml`` in its
    run folder, or of the ``env_kwargs`` of an rl-zoo3 run: action groups, surfaces, model; a shared per-wing
    policy's ``shared_policy.yaml`` ``env_kwargs``), so that its evaluation env has the policy's action and
    observation layout; {} for a controller that is not a run folder or a model file in one. An rl-zoo3 run trained
    on another task than ``env_id`` (``envs.same_task``: the same task on another physics step is accepted) raises
    ValueError naming both."""
    from laddermill_gym.control.rl_config import CARRIED_KWARGS, env_family, load_rl_config
    from laddermill_gym.control.zoo_run import find_zoo_run, read_zoo_run
    from laddermill_gym.envs import same_task

    path = Path(spec)
    if path.exists() and find_zoo_run(path) is not None:
        run = read_zoo_run(path)
        if run.env_id not in ENV_IDS:
            raise ValueError(f"{run.folder}: an rl-zoo3 run on {run.env_id!r}, not a laddermill_gym environment")
        if env_id is not None and not same_task(run.env_id, env_id):
            raise ValueError(f"{run.folder}: an rl-zoo3 run on {run.env_id!r}, evaluated on {env_id!r} (--env)")
        keys = CARRIED_KWARGS[env_family(run.env_id)]
        return {k: v for k, v in run.env_kwargs.items() if k in keys}
    if not path.exists():
        return {}
    from laddermill_gym.control.sb3_policy import run_folder
    from laddermill_gym.control.shared_controller import SHARED_POLICY_FILE, read_shared_meta

    folder = path if path.is_dir() else run_folder(path)  # a checkpoint's: the run folder above
    if not (folder / "config.yaml").is_file():
        return {}
    if (folder / SHARED_POLICY_FILE).is_file():  # a shared per-wing policy: its own description holds the env's
        # control settings (laddermill train ppo_mill_v1; its config.yaml is not an SB3 run's)
        return dict(read_shared_meta(folder / SHARED_POLICY_FILE).get("env_kwargs") or {})
    return load_rl_config(folder / "config.yaml").carried_env_kwargs()


def build_controllers(specs, env_id: str, env_kwargs: dict | None = None, build: Callable | None = None,
                      option: str | None = None) -> dict[str, tuple]:
    """spec -> (controller, env kwargs) for every controller spec, all built before any episode runs: the env kwargs
    are ``env_kwargs`` with the policy's control settings (:func:`policy_env_kwargs`) over them, the controller is
    ``build(spec, env_id, kw)`` (default :func:`~laddermill_gym.control.factory.make_controller`). A spec the
    environment refuses raises what the build raises (ValueError, FileNotFoundError); with ``option`` (a command's
    ``"--controllers"``) a ValueError or OSError becomes a :class:`UsageError` ``OPTION 'SPEC': <message>``."""
    if build is None:
        from laddermill_gym.control.factory import make_controller as build
    out = {}
    for spec in specs:
        try:
            kw = dict(env_kwargs or {}, **policy_env_kwargs(spec, env_id))
            out[spec] = (build(spec, env_id, kw), kw)
        except (ValueError, OSError) as err:  # FileNotFoundError is an OSError, ConfigError a ValueError
            if option is None:
                raise
            raise UsageError(f"{option} {spec!r}: {err}") from None
    return out
