"""Read an rl-zoo3 log folder (``python -m rl_zoo3.train``) for the harness: its algorithm, model file,
observation statistics and environment arguments, or refuse naming what is missing.

rl-zoo3 (2.x, ``rl_zoo3/exp_manager.py``) writes ``<log folder>/<algo>/<env name>_<n>/`` holding

* ``<env name>.zip``: the last model, saved at the end of training;
* ``best_model.zip``: the model of the best evaluation (SB3's ``EvalCallback``, when ``--eval-freq`` > 0);
* ``rl_model_<N>_steps.zip``: checkpoints (``--save-freq``), without statistics;
* ``<env name>/args.yml``: the command line (``algo``, ``env``, ``env_kwargs``);
* ``<env name>/config.yml``: the hyperparameters used (``normalize``, ``env_kwargs``, ``frame_stack``, wrappers);
* ``<env name>/vecnormalize.pkl``: the observation statistics, written at every new best evaluation and again,
  over the same file, with the last model;

where ``<env name>`` is the environment id with "/" replaced by "-" (``laddermill_gym-TetheredWing-v0``). A run
folder therefore holds the statistics of its last model only (or, when training stopped before the final save, of
its best model): :func:`read_zoo_run` takes the last model (as ``python -m rl_zoo3.enjoy`` does without
``--load-best``) and accepts ``best_model.zip`` or a checkpoint only where the statistics on disk are its own.

Which environment arguments each rl-zoo3 script uses (rl-zoo3 2.9, read in its source): ``train`` builds the training
envs with the hyperparameter file's ``env_kwargs`` unless the command line gives ``--env-kwargs`` (which then
replaces them), but its evaluations (``--eval-freq``, SB3's EvalCallback) use ``--eval-env-kwargs``, else the command
line's ``--env-kwargs``, else none: the registered defaults, not the file's (``exp_manager.py``: ``eval_env_kwargs``
is bound before the file is read). ``enjoy`` takes config.yml's ``env_kwargs`` (the file's), replaced by args.yml's
(the command line's) when given; ``record_video`` takes args.yml's only. Giving the file's ``env_kwargs`` on the
command line (:func:`env_kwargs_arguments`; ``python -m laddermill_gym.control.zoo_run FILE ID`` prints them) makes
training, evaluation, ``enjoy`` and ``record_video`` use the same settings, and args.yml records them.
"""

from __future__ import annotations

import argparse
import ast
import importlib
import pickle
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from laddermill_gym.model.configio import YAMLLoader

__all__ = ["ZooRun", "ZOO_ALGORITHMS", "find_zoo_run", "read_zoo_run", "zoo_algorithm_class", "read_zoo_yaml",
           "zoo_env_kwargs", "env_kwargs_arguments"]

#: rl-zoo3's algorithm names (``rl_zoo3.utils.ALGOS``) -> (module, class). Kept here rather than imported from
#: rl_zoo3, so that a run folder can be evaluated where only Stable-Baselines3 (and sb3-contrib) are installed;
#: its recurrent "ppo_lstm" is refused, because the harness calls ``predict`` without a recurrent state.
ZOO_ALGORITHMS: dict[str, tuple[str, str]] = {
    "a2c": ("stable_baselines3", "A2C"), "ddpg": ("stable_baselines3", "DDPG"), "dqn": ("stable_baselines3", "DQN"),
    "ppo": ("stable_baselines3", "PPO"), "sac": ("stable_baselines3", "SAC"), "td3": ("stable_baselines3", "TD3"),
    "ars": ("sb3_contrib", "ARS"), "crossq": ("sb3_contrib", "CrossQ"), "qrdqn": ("sb3_contrib", "QRDQN"),
    "tqc": ("sb3_contrib", "TQC"), "trpo": ("sb3_contrib", "TRPO"),
}
_ORDERED_DICT_TAG = "tag:yaml.org,2002:python/object/apply:collections.OrderedDict"
#: config.yml entries that change what the policy sees in ways the harness's evaluation env does not reproduce
_UNSUPPORTED = ("frame_stack", "env_wrapper", "vec_env_wrapper")


@dataclass(frozen=True)
class ZooRun:
    """An rl-zoo3 run: ``folder`` (``.../<algo>/<env name>_<n>``), ``algo`` (rl-zoo3's name, e.g. "ppo"),
    ``env_id`` (the registered id), ``model_file``, ``vecnormalize`` (the statistics file that goes with it, None
    when observations were not normalised) and ``env_kwargs`` (the training environment's arguments)."""

    folder: Path
    algo: str
    env_id: str
    model_file: Path
    vecnormalize: Path | None
    env_kwargs: dict = field(default_factory=dict)


class _ZooLoader(YAMLLoader):
    """The package's safe loader (YAML 1.2 floats such as ``3e-4`` read as numbers, a key given twice refused) plus
    the one Python tag rl-zoo3 writes (``yaml.dump`` of an OrderedDict), read as a dict; every other Python tag still
    fails (rl-zoo3 reads these files with the unsafe loader)."""


def _ordered_dict(loader: _ZooLoader, node: yaml.Node) -> dict:
    args = loader.construct_sequence(node, deep=True) if isinstance(node, yaml.SequenceNode) else \
        loader.construct_mapping(node, deep=True).get("args", [[]])
    return {k: v for k, v in (args[0] if args else [])}


_ZooLoader.add_constructor(_ORDERED_DICT_TAG, _ordered_dict)


def read_zoo_yaml(path: Path) -> dict[str, Any]:
    """The mapping in rl-zoo3's ``args.yml`` or ``config.yml``; ValueError naming the file otherwise."""
    try:
        data = yaml.load(path.read_text(), Loader=_ZooLoader)  # noqa: S506 (a safe loader with one added tag)
    except yaml.YAMLError as err:
        raise ValueError(f"{path}: not readable as an rl-zoo3 file ({err})") from None
    if not isinstance(data, dict):
        raise ValueError(f"{path}: {type(data).__name__} at the top, expected a mapping")
    return data


def find_zoo_run(path: str | Path) -> tuple[Path, Path] | None:
    """(run folder, its ``<env name>`` subfolder) if ``path`` is an rl-zoo3 run folder or a file in one, else None.
    A run folder ``<env name>_<n>`` is recognised by its subfolder ``<env name>`` holding ``args.yml`` or
    ``config.yml``."""
    path = Path(path)
    folder = path if path.is_dir() else path.parent
    stem, _, number = folder.name.rpartition("_")
    sub = folder / stem
    if stem and number.isdigit() and ((sub / "args.yml").is_file() or (sub / "config.yml").is_file()):
        return folder, sub
    return None


def zoo_algorithm_class(algo: str, where: Path) -> type:
    """The SB3 (or sb3-contrib) class of rl-zoo3's algorithm name ``algo`` (read from ``where``)."""
    if algo == "ppo_lstm":
        raise ValueError(f"{where}: algo = 'ppo_lstm' (RecurrentPPO) is recurrent; the harness evaluates "
                         "feed-forward policies only (it passes no recurrent state)")
    if algo not in ZOO_ALGORITHMS:
        raise ValueError(f"{where}: algo = {algo!r}: not one of rl-zoo3's {sorted(ZOO_ALGORITHMS)}")
    module, name = ZOO_ALGORITHMS[algo]
    try:
        return getattr(importlib.import_module(module), name)
    except ImportError:
        raise ValueError(f"{where}: algo = {algo!r} needs the package {module} (pip install {module})") from None


def _python_mapping(text: str, where: str) -> dict:
    """rl-zoo3's Python text of a mapping (``"dict(norm_obs=True)"`` or ``"{'norm_obs': True}"``), read with
    :mod:`ast` (literals only; rl-zoo3 itself calls eval)."""
    try:
        expr = ast.parse(text, mode="eval").body
        if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) and expr.func.id == "dict" \
                and not expr.args:
            return {kw.arg: ast.literal_eval(kw.value) for kw in expr.keywords}
        value = ast.literal_eval(expr)
    except (SyntaxError, ValueError):
        value = None
    if not isinstance(value, dict):
        raise ValueError(f"{where} = {text!r}: not a literal mapping")
    return value


def _normalized(config: dict, config_file: Path) -> bool:
    """Whether training normalised observations: ``normalize`` in config.yml is a bool, a mapping of VecNormalize
    arguments or its Python text; VecNormalize's default ``norm_obs`` is True."""
    value = config.get("normalize", False)
    if isinstance(value, str):
        value = _python_mapping(value, f"{config_file}: normalize")
    if isinstance(value, dict):
        return bool(value.get("norm_obs", True))
    if isinstance(value, bool):
        return value
    raise ValueError(f"{config_file}: normalize = {value!r}: expected true/false, a mapping or rl-zoo3's text")


def _pick_model(folder: Path, stem: str, path: Path, stats: Path | None) -> tuple[Path, Path | None]:
    """The model file (``path`` itself when it names one) and the statistics that go with it (None: none)."""
    last = folder / f"{stem}.zip"
    if path.is_dir():
        for candidate in (last, folder / "best_model.zip"):
            if candidate.is_file():
                return candidate, stats
        raise FileNotFoundError(f"{folder}: no {last.name} or best_model.zip (training saved no model yet)")
    if stats is None or path == last:
        return path, stats
    if path.name == "best_model.zip":
        if last.is_file():
            raise ValueError(f"{path}: rl-zoo3 wrote {stats} again with the last model ({last.name}) after this "
                             "best model, so its own observation statistics are lost; evaluate the run folder "
                             "(its last model) instead")
        return path, stats
    own = folder / path.name.replace("rl_model_", "rl_model_vecnormalize_").replace(".zip", ".pkl")
    if own.is_file():
        return path, own
    raise ValueError(f"{path}: a checkpoint of a run with normalised observations, but {own.name} (its "
                     "statistics) is missing; evaluate the run folder (its last model) instead")


def read_zoo_run(path: str | Path) -> ZooRun:
    """Read the rl-zoo3 run folder ``path`` (or a model file in one). Raises FileNotFoundError or ValueError
    naming the missing file or the unsupported entry: no ``args.yml`` / ``config.yml``, an unknown or recurrent
    algorithm, frame stacking or wrappers, normalised observations without ``vecnormalize.pkl``."""
    path = Path(path)
    found = find_zoo_run(path)
    if found is None:
        raise ValueError(f"{path}: not an rl-zoo3 run folder (<env name>_<n>/ with <env name>/args.yml)")
    folder, sub = found
    args_file, config_file = sub / "args.yml", sub / "config.yml"
    for needed, what in ((args_file, "the algorithm and environment"), (config_file, "the normalisation")):
        if not needed.is_file():
            raise FileNotFoundError(f"{needed}: missing; rl-zoo3 writes it with the run and it names {what}")
    args, config = read_zoo_yaml(args_file), read_zoo_yaml(config_file)
    for key in ("algo", "env"):
        if not isinstance(args.get(key), str):
            raise ValueError(f"{args_file}: {key} = {args.get(key)!r}: expected a name")
    zoo_algorithm_class(args["algo"], args_file)
    for key in _UNSUPPORTED:
        if config.get(key) is not None:
            raise ValueError(f"{config_file}: {key} = {config[key]!r}: the harness evaluates on the bare "
                             "environment and cannot reproduce it")
    stats = sub / "vecnormalize.pkl"
    if _normalized(config, config_file):
        if not stats.is_file():
            raise FileNotFoundError(f"{stats}: missing, but {config_file} says observations were normalised "
                                    f"(normalize = {config.get('normalize')!r})")
    else:
        stats = None
    model_file, stats = _pick_model(folder, sub.name, path, stats)
    env_kwargs = args.get("env_kwargs") if args.get("env_kwargs") is not None else config.get("env_kwargs")
    return ZooRun(folder, args["algo"], args["env"], model_file, stats, dict(env_kwargs or {}))


#: What unpickling a file that is not a pickle (a text file, a truncated or other file) raises
UNPICKLE_ERRORS = (pickle.UnpicklingError, EOFError, ValueError, TypeError, AttributeError, ImportError, IndexError,
                   KeyError)


def load_vecnormalize(path: Path, model=None, model_file: Path | None = None):
    """The pickled SB3 ``VecNormalize`` in ``path`` (its ``obs_rms``, ``clip_obs``, ``epsilon``, ``norm_obs``).

    ValueError naming ``path`` when the file does not unpickle or holds something else than a ``VecNormalize``;
    with ``model`` (the SB3 model the statistics go with, loaded from ``model_file``), also when normalised
    observations of the statistics' shape (``obs_rms.mean``, (obs_dim,)) are not the model's observation shape
    (statistics of another env or other env arguments), naming both shapes."""
    from stable_baselines3.common.vec_env import VecNormalize

    path = Path(path)
    try:
        with open(path, "rb") as fh:
            stats = pickle.load(fh)
    except UNPICKLE_ERRORS as err:
        raise ValueError(f"{path}: not readable as pickled observation statistics (SB3's VecNormalize.save): "
                         f"{type(err).__name__}: {err}") from None
    if not isinstance(stats, VecNormalize):
        raise ValueError(f"{path}: holds a {type(stats).__module__}.{type(stats).__name__}, not SB3's VecNormalize "
                         "(the observation statistics VecNormalize.save writes)")
    if model is not None and getattr(stats, "norm_obs", True):
        shape = tuple(np.shape(getattr(stats.obs_rms, "mean", None)))
        expected = tuple(model.observation_space.shape)
        if shape != expected:
            raise ValueError(f"{path}: observation statistics of shape {shape}, but the policy "
                             f"{model_file or 'it goes with'} observes shape {expected}: the statistics of another "
                             "env or of other env arguments (keep each model with its own vecnormalize.pkl)")
    return stats


# ------------------------------------------------------------------ the file's env_kwargs on rl-zoo3's command line
def zoo_env_kwargs(conf_file: str | Path, env_id: str) -> dict[str, Any]:
    """The ``env_kwargs`` of ``env_id`` in the rl-zoo3 hyperparameter file ``conf_file`` (a path, or "ppo" / "sac"
    for our shipped ``configs/rl_zoo3/<algo>.yaml``); {} when the entry has none. ValueError naming the file when it
    has no entry for ``env_id``."""
    from laddermill_gym.model.configio import CONFIG_DIR

    path = Path(conf_file)
    if not path.suffix and not path.exists():
        path = CONFIG_DIR / "rl_zoo3" / f"{conf_file}.yaml"
    data = read_zoo_yaml(path)
    if env_id not in data:
        raise ValueError(f"{path}: no entry for {env_id!r} (entries: {sorted(data)})")
    entry = data[env_id]
    kwargs = entry.get("env_kwargs") if isinstance(entry, dict) else None
    if kwargs is not None and not isinstance(kwargs, dict):
        raise ValueError(f"{path}: {env_id}.env_kwargs = {kwargs!r}: expected a mapping")
    return dict(kwargs or {})


def _literal(value: Any, where: str) -> str:
    """``value`` as a Python literal without whitespace (rl-zoo3 evaluates each value with ``eval``; the shell
    splits the printed arguments at whitespace)."""
    if isinstance(value, dict):
        return "{" + ",".join(f"{k!r}:{_literal(v, f'{where}.{k}')}" for k, v in value.items()) + "}"
    if isinstance(value, list | tuple):
        return "[" + ",".join(_literal(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    if isinstance(value, str) and any(c.isspace() for c in value):
        raise ValueError(f"{where} = {value!r}: holds whitespace; give this argument by hand, quoted")
    if value is None or isinstance(value, bool | int | float | str):
        return repr(value)
    raise ValueError(f"{where} = {value!r}: not a YAML scalar, list or mapping")


def env_kwargs_arguments(env_kwargs: dict[str, Any]) -> list[str]:
    """rl-zoo3's ``--env-kwargs`` values for ``env_kwargs``: one ``key:literal`` per key, no whitespace."""
    return [f"{key}:{_literal(value, key)}" for key, value in env_kwargs.items()]


def main(argv: list[str] | None = None) -> int:
    """``python -m laddermill_gym.control.zoo_run FILE ID``: print the ``--env-kwargs`` values of ID's entry."""
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.control.zoo_run",
                                description="Print an rl-zoo3 hyperparameter file's env_kwargs for an id as rl-zoo3 "
                                "command-line values: --env-kwargs $(python -m laddermill_gym.control.zoo_run FILE ID)")
    p.add_argument("file", help="the hyperparameter file, or ppo / sac for ours (configs/rl_zoo3/)")
    p.add_argument("env_id", help="the registered id, e.g. laddermill_gym/TetheredWing-v0")
    a = p.parse_args(argv)
    try:
        args = env_kwargs_arguments(zoo_env_kwargs(a.file, a.env_id))
    except (OSError, ValueError) as err:
        p.error(str(err))
    if not args:
        p.error(f"{a.file}: {a.env_id} has no env_kwargs (nothing to pass)")
    print(" ".join(args))
    return 0


if __name__ == "__main__":
    sys.exit(main())
