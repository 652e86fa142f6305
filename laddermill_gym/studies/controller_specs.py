"""Controller specs of the commands (``laddermill evaluate``, ``gust-bench``, ``demo``) against an environment: the
control settings a trained policy carries (:func:`policy_env_kwargs`), every spec built before any episode runs
(:func:`build_controllers`; for a command, a spec the environment refuses is one line, ``--controllers 'SPEC':
...``), the label of a spec in a command's results (:func:`controller_label`) and the refusal of specs named twice
or labelled alike (:func:`check_labels`). A shipped policy's name (``ppo_tethered_wing``) is the shipped policy
wherever it is read, as ``make_controller`` reads it, whatever the working directory holds. A shared module of
``studies`` (any topic, and ``harness``, may import it); imports ``control`` and ``envs``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from laddermill_gym.envs import ENV_IDS
from laddermill_gym.studies.commands import UsageError

__all__ = ["policy_env_kwargs", "build_controllers", "controller_label", "check_labels", "spec_path"]

#: the prefixes of a spec that names a config file: ``lqr:CONFIG``, ``lqr_guard:CONFIG``, ``crosswind:CONFIG``
CONFIG_PREFIXES = ("lqr:", "lqr_guard:", "crosswind:")


def spec_path(spec: str) -> Path | None:
    """The policy folder or file a controller spec names, as ``make_controller`` reads it: a shipped policy's name
    (``control.shipped_policies.SHIPPED_POLICIES``) is its package folder, before any path of that name in the
    working directory; a spec with a config prefix (:data:`CONFIG_PREFIXES`) or one of the model-based names names
    none (None); any other spec is a path (which need not exist)."""
    from laddermill_gym.control.shipped_policies import POLICY_DIR, SHIPPED_POLICIES

    if spec in SHIPPED_POLICIES:
        return POLICY_DIR / spec
    if spec.startswith(CONFIG_PREFIXES) or spec in ("open_loop", "lqr", "lqr_guard", "scripted", "crosswind"):
        return None
    return Path(spec)


def controller_label(spec: str) -> str:
    """The label of a controller spec in a command's tables, legends and rows: ``PREFIX:<config stem>`` for a spec
    with a config prefix (``lqr:lqr_tethered_wing``), a shipped policy's name as it is, a run folder's name, a model
    file's ``folder/stem``, or the spec itself."""
    from laddermill_gym.control.shipped_policies import SHIPPED_POLICIES

    for prefix in CONFIG_PREFIXES:
        if spec.startswith(prefix):
            return prefix + Path(spec[len(prefix):]).stem
    path = Path(spec)
    if spec in SHIPPED_POLICIES or not path.exists():
        return spec
    return f"{path.parent.name}/{path.stem}" if path.is_file() else path.name


def check_labels(specs, option: str = "--controllers") -> None:
    """UsageError naming ``option`` for a spec named twice, or for two specs whose results would carry the same label
    (:func:`controller_label`; ``lqr:a/lqr_x.yaml`` and ``lqr:b/lqr_x.yaml``, run folders ``a/ppo`` and ``b/ppo``),
    naming both specs and the label: a command keys its results by label, so one would hide or mix with the other."""
    twice = sorted({s for s in specs if list(specs).count(s) > 1})
    if twice:
        raise UsageError(f"{option} {twice}: named twice")
    seen: dict[str, str] = {}
    for spec in specs:
        label = controller_label(spec)
        if label in seen:
            raise UsageError(f"{option} {seen[label]!r} and {spec!r}: both would be labelled {label!r} in the results; "
                             "name one by another path (a copy or a link of another name)")
        seen[label] = spec


def policy_env_kwargs(spec: str, env_id: str | None = None) -> dict:
    """The control settings a trained policy was trained with (the ``CARRIED_KWARGS`` of the ``config.yaml`` in its
    run folder, or of the ``env_kwargs`` of an rl-zoo3 run: action groups, surfaces, model; a shared per-wing
    policy's ``shared_policy.yaml`` ``env_kwargs``), so that its evaluation env has the policy's action and
    observation layout; {} for a controller that is not a run folder or a model file in one. An rl-zoo3 run trained
    on another task than ``env_id`` (``envs.same_task``: the same task on another physics step is accepted) raises
    ValueError naming both."""
    from laddermill_gym.control.rl_config import CARRIED_KWARGS, env_family, load_rl_config
    from laddermill_gym.control.trained_settings import carried_to
    from laddermill_gym.control.zoo_run import find_zoo_run, read_zoo_run
    from laddermill_gym.envs import same_task

    path = spec_path(spec)
    if path is None:
        return {}
    if path.exists() and find_zoo_run(path) is not None:
        run = read_zoo_run(path)
        if run.env_id not in ENV_IDS:
            raise ValueError(f"{run.folder}: an rl-zoo3 run on {run.env_id!r}, not a laddermill_gym environment")
        if env_id is not None and not same_task(run.env_id, env_id):
            raise ValueError(f"{run.folder}: an rl-zoo3 run on {run.env_id!r}, evaluated on {env_id!r} (--env)")
        keys = CARRIED_KWARGS[env_family(run.env_id)]
        return carried_to(run.env_id, env_id, {k: v for k, v in run.env_kwargs.items() if k in keys})
    if not path.exists():
        return {}
    from laddermill_gym.control.sb3_policy import run_folder
    from laddermill_gym.control.shared_controller import SHARED_POLICY_FILE, read_shared_meta

    folder = path if path.is_dir() else run_folder(path)  # a checkpoint's: the run folder above
    if not (folder / "config.yaml").is_file():
        return {}
    if (folder / SHARED_POLICY_FILE).is_file():  # a shared per-wing policy: its own description holds the env's
        # control settings (laddermill train ppo_mill_v1; its config.yaml is not an SB3 run's)
        meta = read_shared_meta(folder / SHARED_POLICY_FILE)
        return carried_to(str(meta["env"]), env_id, dict(meta.get("env_kwargs") or {}))
    cfg = load_rl_config(folder / "config.yaml")
    return carried_to(cfg.env_id, env_id, cfg.carried_env_kwargs())  # another id of the task: its own physics


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
