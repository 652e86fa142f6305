"""A trained Stable-Baselines3 policy as a controller of the harness (needs the ``rl`` extra).

Training (``laddermill train``) writes a run folder with the model (``model.zip``, or the best one
``best_model.zip``) and, when observations were normalised, the running statistics that go with each
(``vecnormalize.pkl``, ``best_vecnormalize.pkl``). rl-zoo3 log folders are read as well
(:mod:`laddermill_gym.control.zoo_run`).
:class:`SB3Controller` applies the same normalisation before the policy, so evaluation sees raw
environment observations exactly like the open-loop and LQR controllers.

A policy loaded from disk (:meth:`SB3Controller.load`) whose actor is linear (``net_arch: {pi: []}``: the shipped
``ppo_tethered_wing`` and ``ppo_rotorcraft``) gives its deterministic action in float64 with a fixed order of
summation (:mod:`laddermill_gym.control.exact_actor`): the same bits on any CPU and for any batch size, where torch's
float32 product differs in the last bits between machines. The training's own validations use torch (the policy as
it trains); ``exact=False`` gives that path for a loaded policy too.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from laddermill_gym.envs import same_task

__all__ = ["SB3Controller"]


class SB3Controller:
    """``predict`` of an SB3 model on raw observations.

    Parameters
    ----------
    model : a loaded SB3 algorithm (PPO, SAC, ...)
    obs_mean, obs_var : ndarray (obs_dim,), optional
        Normalisation statistics: the policy sees clip((obs - mean) / sqrt(var + eps), -clip_obs, clip_obs).
    clip_obs, epsilon : as in SB3's ``VecNormalize``.
    exact : bool
        Deterministic actions of a linear actor in float64, summed in a fixed order (:mod:`exact_actor
        <laddermill_gym.control.exact_actor>`); other policies, and stochastic actions, always through torch.

    Attributes
    ----------
    source : Path or None
        The model file it was loaded from (named in every error about it).
    trained_env : str or None
        The env id it was trained on, when the run folder says (``config.yaml``'s ``env``, rl-zoo3's ``args.yml``).
    """

    source: Path | None = None
    trained_env: str | None = None

    def __init__(self, model, obs_mean: np.ndarray | None = None, obs_var: np.ndarray | None = None,
                 clip_obs: float = 10.0, epsilon: float = 1e-8, exact: bool = False):
        from laddermill_gym.control.exact_actor import sb3_linear_actor

        self.model = model
        self.linear = sb3_linear_actor(model.policy) if exact else None
        self.obs_mean = None if obs_mean is None else np.asarray(obs_mean, dtype=np.float64)
        self.obs_std = None if obs_var is None else np.sqrt(np.asarray(obs_var, dtype=np.float64) + epsilon)
        self.clip_obs = float(clip_obs)

    @classmethod
    def from_vecnormalize(cls, model, vecnormalize, exact: bool = False) -> SB3Controller:
        """``model`` with the observation statistics of an SB3 ``VecNormalize`` (None, or one that does not
        normalise observations: none)."""
        if vecnormalize is None or not getattr(vecnormalize, "norm_obs", True):
            return cls(model, exact=exact)
        return cls(model, vecnormalize.obs_rms.mean, vecnormalize.obs_rms.var, vecnormalize.clip_obs,
                   vecnormalize.epsilon, exact=exact)

    @classmethod
    def load(cls, path: str | Path, best: bool = True, exact: bool = True,
             statistics: str | Path | None = None) -> SB3Controller:
        """Load from a training run folder (``best_model.zip`` if present and ``best``, else ``model.zip``)
        or from a model file, with its normalisation statistics next to it if there are any (``statistics``: that
        file instead, a path that need not exist: none); ``exact``: a linear actor's deterministic actions in
        float64, fixed order (the class's ``exact``). Statistics that are not a ``VecNormalize`` or whose
        observation shape is not the model's raise ValueError naming the file and both shapes.

        An rl-zoo3 log folder (``logs/<algo>/<env name>_<n>``, or a model file in one) is read by
        :func:`~laddermill_gym.control.zoo_run.read_zoo_run`: algorithm from its ``args.yml``, statistics from
        ``<env name>/vecnormalize.pkl``, the last model (``best`` does not apply: rl-zoo3 keeps the statistics of
        the last model only); it raises naming what is missing or unsupported."""
        from laddermill_gym.control.zoo_run import find_zoo_run, load_vecnormalize

        path = Path(path)
        if find_zoo_run(path) is not None:
            return cls.load_zoo(path, exact)
        import stable_baselines3 as sb3

        if path.is_dir():
            candidates = (["best_model.zip"] if best else []) + ["model.zip"]
            files = [path / c for c in candidates if (path / c).is_file()]
            if not files:
                raise FileNotFoundError(f"{path}: no model.zip or best_model.zip (is it a training run folder?)")
            model_file, folder = files[0], path
        elif path.is_file():
            model_file, folder = path, run_folder(path)
        else:
            raise FileNotFoundError(f"{path}: no such model file or run folder")
        model = _load_model(sb3, model_file, folder / "algorithm.txt")
        norm = statistics_file(model_file, folder) if statistics is None else Path(statistics)
        ctrl = cls.from_vecnormalize(model, load_vecnormalize(norm, model, model_file) if norm.is_file() else None,
                                     exact)
        ctrl.source, ctrl.trained_env = model_file, _trained_env(folder / "config.yaml")
        return ctrl

    @classmethod
    def load_zoo(cls, path: str | Path, exact: bool = True) -> SB3Controller:
        """Load an rl-zoo3 run folder or a model file in one (:func:`~laddermill_gym.control.zoo_run.read_zoo_run`).
        The schedules pickled in the model (rl-zoo3's own classes) are replaced by constants, as
        ``rl_zoo3.enjoy`` does: evaluation does not train, and rl_zoo3 need not be installed."""
        from laddermill_gym.control.zoo_run import load_vecnormalize, read_zoo_run, zoo_algorithm_class

        run = read_zoo_run(path)
        algo = zoo_algorithm_class(run.algo, run.folder)
        constants = {"learning_rate": 0.0, "lr_schedule": lambda _: 0.0, "clip_range": lambda _: 0.0}
        model = algo.load(run.model_file, device="cpu", custom_objects=constants)
        stats = None if run.vecnormalize is None else load_vecnormalize(run.vecnormalize, model, run.model_file)
        ctrl = cls.from_vecnormalize(model, stats, exact)
        ctrl.source, ctrl.trained_env = run.model_file, run.env_id
        return ctrl

    def check_env(self, env_id: str) -> None:
        """Refuse a policy trained on another env id than ``env_id`` (when its run folder names one), unless the
        two are the same task on other physics steps (``envs.same_task``: TetheredWing-v0 and v1)."""
        if self.trained_env is not None and not same_task(self.trained_env, env_id):
            raise ValueError(f"{self.source}: trained on {self.trained_env}, not {env_id}; evaluate it on "
                             f"{self.trained_env} or train one for {env_id}")

    def check_spaces(self, obs_dim: int, n_actions: int, env_id: str) -> None:
        """Refuse a policy whose observation or action size is not the environment's (``obs_dim``,
        ``n_actions`` of ``env_id`` with the given arguments), naming the file and both sizes."""
        obs_shape, act_shape = self.model.observation_space.shape, self.model.action_space.shape
        for what, mine, env in (("observations", obs_shape, (int(obs_dim),)), ("actions", act_shape,
                                                                                (int(n_actions),))):
            if tuple(mine) != env:
                raise ValueError(f"{self.source or 'policy'}: {what} of shape {tuple(mine)} (trained on "
                                 f"{self.trained_env or 'an unnamed env'}), but {env_id} with these arguments has "
                                 f"{env}: another env, or other env arguments (n_wings, action_mode, groups)")

    def normalize(self, observation: np.ndarray) -> np.ndarray:
        """The observation as the policy saw it in training (float32); refuses one of another size."""
        return self.normalize64(observation).astype(np.float32)

    def normalize64(self, observation: np.ndarray) -> np.ndarray:
        """:meth:`normalize` before the cast to float32 (the exact path's input)."""
        obs = np.asarray(observation, dtype=np.float64)
        expected = self.model.observation_space.shape
        if obs.shape[-len(expected):] != expected:
            raise ValueError(f"{self.source or 'policy'}: expects observations of shape {expected} "
                             f"(trained on {self.trained_env or 'an unnamed env'}), got {obs.shape}: another "
                             "env, or other env arguments (n_wings, observation options)")
        if self.obs_mean is None:
            return obs
        return np.clip((obs - self.obs_mean) / self.obs_std, -self.clip_obs, self.clip_obs)

    def predict(self, observation: np.ndarray, state: Any = None, episode_start: np.ndarray | None = None,
                deterministic: bool = False) -> tuple[np.ndarray, Any]:
        """Actions for batched (n_envs, obs_dim) or single (obs_dim,) raw observations (float64 from the exact
        path, else SB3's float32)."""
        if deterministic and self.linear is not None:
            x = self.normalize64(observation)
            act = self.linear.actions(x.reshape(-1, x.shape[-1]))
            return (act[0] if x.ndim == 1 else act), state
        return self.model.predict(self.normalize(observation), state, episode_start, deterministic)


#: Files ``laddermill train`` writes into a run folder, by which the folder above a ``checkpoints/`` is known as one
RUN_MARKERS = ("config.yaml", "shared_policy.yaml", "algorithm.txt")


def run_folder(model_file: Path) -> Path:
    """The training run folder of a model file: its own folder, or for a checkpoint (``RUN/checkpoints/*.zip`` of
    ``laddermill train``, a folder holding one of :data:`RUN_MARKERS`) the run folder above, which holds its config,
    algorithm and statistics."""
    folder = model_file.parent
    up = folder.parent
    if folder.name == "checkpoints" and any((up / f).is_file() for f in RUN_MARKERS):
        return up
    return folder


def statistics_file(model_file: Path, run: Path) -> Path:
    """The observation statistics that go with ``model_file`` of the run folder ``run`` (the path may not exist:
    no normalisation): ``best_vecnormalize.pkl`` for the best model, ``checkpoints/step_<n>_vecnormalize.pkl``
    for a checkpoint (saved with it since 2026-12-06; for an older run's checkpoint, whose own were not saved, the
    run's last ``vecnormalize.pkl`` with a warning, as ``harness/reselect.py`` flies them), else
    ``vecnormalize.pkl``."""
    import warnings

    if model_file.parent != run:  # a checkpoint
        own = model_file.with_name(model_file.stem + "_vecnormalize.pkl")
        last = run / "vecnormalize.pkl"
        if not own.is_file() and last.is_file():
            warnings.warn(f"{model_file}: its observation statistics were not saved with it; using the run's last, "
                          f"{last} (the policy saw slightly other ones when it was saved)", UserWarning, stacklevel=3)
            return last
        return own
    return run / ("best_vecnormalize.pkl" if model_file.name == "best_model.zip" else "vecnormalize.pkl")


def read_run_config(config: Path) -> dict | None:
    """A training run's ``config.yaml`` as a mapping (None when there is no such file, or it holds no mapping);
    ValueError naming the file when it is not YAML."""
    if not config.is_file():
        return None
    from laddermill_gym.model.configio import load_yaml_text

    # the package's YAML 1.2 reader, as training read the file (YAML 1.1's safe_load reads 5e-2 as a string, and the
    # run's own control_dt: 5e-2 was refused as another setting than the 0.05 it trained at)
    data = load_yaml_text(config.read_text(), str(config))  # ConfigError (a ValueError) naming the file
    return data if isinstance(data, dict) else None


def _trained_env(config: Path) -> str | None:
    """The ``env`` of a training run's ``config.yaml`` (None when there is no such file or field)."""
    env = (read_run_config(config) or {}).get("env")
    return str(env) if env is not None else None


def _load_model(sb3, model_file: Path, meta: Path):
    """The SB3 model in ``model_file`` with the algorithm ``meta`` (algorithm.txt) names. Without that file it
    loads as PPO (what the first run folders held); a model that is not a PPO one then raises naming both files.
    An algorithm of sb3-contrib (TQC, ...) needs that package; a name that is not an algorithm's
    (:func:`algorithm_class`) raises naming ``meta``."""
    check_model_file(model_file)
    if not meta.is_file():
        try:
            return sb3.PPO.load(model_file, device="cpu")
        except LOAD_ERRORS as err:
            raise ValueError(f"{model_file}: does not load as PPO ({type(err).__name__}: {err}) and {meta} is "
                             "missing: write the algorithm it was trained with (PPO, SAC, ...) into that file"
                             ) from None
    return load_as(algorithm_class(meta.read_text().strip(), meta), model_file, meta)


def _algorithm_modules() -> list:
    """stable_baselines3 and, when installed, sb3_contrib."""
    import stable_baselines3 as sb3

    try:
        import sb3_contrib
    except ImportError:
        return [sb3]
    return [sb3, sb3_contrib]


def algorithm_names() -> list[str]:
    """The algorithm class names of stable_baselines3 (and sb3-contrib, when installed): PPO, SAC, TQC, ..."""
    from stable_baselines3.common.base_class import BaseAlgorithm

    return sorted({n for m in _algorithm_modules() for n in dir(m)
                   if isinstance(getattr(m, n), type) and issubclass(getattr(m, n), BaseAlgorithm)})


def algorithm_class(name: str, where: Path) -> type:
    """The SB3 algorithm class that ``name`` (read from ``where``: ``algorithm.txt``, ``shared_policy.yaml``) names:
    a class name of stable_baselines3 or sb3-contrib (``PPO``, ``TQC``), or rl-zoo3's lower-case name of one
    (``ppo``, ``tqc``: :data:`~laddermill_gym.control.zoo_run.ZOO_ALGORITHMS`). ValueError naming ``where``, the
    name and the known names otherwise (a module such as ``stable_baselines3.ppo`` is not an algorithm)."""
    from stable_baselines3.common.base_class import BaseAlgorithm

    from laddermill_gym.control.zoo_run import ZOO_ALGORITHMS, zoo_algorithm_class

    for module in _algorithm_modules():
        cls = getattr(module, name, None)
        if isinstance(cls, type) and issubclass(cls, BaseAlgorithm):
            return cls
    if name in ZOO_ALGORITHMS or name == "ppo_lstm":
        return zoo_algorithm_class(name, where)
    contrib = "" if len(_algorithm_modules()) > 1 else " (sb3-contrib's are not: that package is not installed)"
    raise ValueError(f"{where}: unknown algorithm {name!r}: not a stable_baselines3 or sb3-contrib algorithm class "
                     f"({', '.join(algorithm_names())}) nor rl-zoo3's name of one ({', '.join(sorted(ZOO_ALGORITHMS))})"
                     f"{contrib}")


#: What SB3's ``load`` raises for a file that is not a model of that algorithm (AssertionError: a zip without
#: SB3's data, "No data found in the saved file")
LOAD_ERRORS = (KeyError, ValueError, RuntimeError, TypeError, AttributeError, AssertionError)


def check_model_file(model_file: Path) -> None:
    """ValueError naming ``model_file`` unless it is a zip archive (what every SB3 model file is)."""
    import zipfile

    if not zipfile.is_zipfile(model_file):
        raise ValueError(f"{model_file}: not a zip archive, so not a Stable-Baselines3 model file")


def load_as(cls, model_file: Path, named_in: Path):
    """``cls.load(model_file)`` (an SB3 algorithm class that ``named_in`` names), on the CPU; ValueError naming the
    file, the algorithm and ``named_in`` when the file does not load as one."""
    check_model_file(model_file)
    try:
        return cls.load(model_file, device="cpu")
    except LOAD_ERRORS as err:
        raise ValueError(f"{model_file}: does not load as {cls.__name__} ({named_in}): {type(err).__name__}: "
                         f"{err}") from None
