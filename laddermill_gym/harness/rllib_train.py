"""Train a laddermill_gym environment with RLlib's PPO on remote env runners (needs the ``rllib`` extra).

    python -m laddermill_gym.harness.rllib_train --env laddermill_gym/TetheredWing-v0 --env-runners 2 \\
        --iterations 20 --episode-time 60

RLlib's env runners are Ray worker processes of their own. They make the environment by its Gymnasium id, and
Gymnasium knows our ids only after ``import laddermill_gym``: the driver has imported it, the workers never do, so
``config.environment("laddermill_gym/TetheredWing-v0")`` with remote runners fails in every worker with Gymnasium's
``NamespaceNotFound: Namespace laddermill_gym not found``. Two ways that work, both here (``--how``):

* ``entry`` (the default): the id in Gymnasium's ``"module:id"`` form, ``"laddermill_gym:laddermill_gym/
  TetheredWing-v0"`` (:func:`entry_id`): whichever process makes the env imports ``laddermill_gym`` first;
* ``register``: ``ray.tune.registry.register_env(env_id, partial(make_env, env_id))``; Ray ships the creator to
  every runner by reference to this module, whose :func:`make_env` imports the package. Once registered, the plain
  id names the creator for the rest of the Ray session.

``env_config`` (``--episode-time`` and the JSON of ``--env-config``) is passed to ``gymnasium.make`` as keyword
arguments, merged with the id's registered defaults as in ``gymnasium.make``. Each runner steps
``--envs-per-runner`` copies in Gymnasium's synchronous vector env. Everything else is RLlib's PPO with its
defaults; the arguments set only the batch sizes and the network. Tune runs it the same way:
``ray.tune.Tuner("PPO", param_space=ppo_config(...))``.

Ray 2.60's ``ray[rllib]`` pins ``gymnasium==1.2.2`` (this package otherwise allows any gymnasium >= 1.0): install
the ``rllib`` extra in a virtual environment of its own. ``tests/test_rllib.py`` trains one iteration on one
remote runner both ways and shows the plain id failing.
"""

from __future__ import annotations

import argparse
import functools
import json
import sys
from typing import Any

__all__ = ["RLLIB_HINT", "entry_id", "make_env", "ppo_config", "train", "main"]

#: What to install for this module.
RLLIB_HINT = 'RLlib is an optional extra: pip install "laddermill_gym[rllib]" (or "ray[rllib]" and torch)'


def entry_id(env_id: str) -> str:
    """``env_id`` in Gymnasium's ``"module:id"`` form, so that the process that makes it imports laddermill_gym."""
    return env_id if ":" in env_id else f"laddermill_gym:{env_id}"


def make_env(env_id: str, env_config: dict):
    """RLlib's env creator for ``register_env`` (bound to ``env_id`` with functools.partial):
    ``gymnasium.make(env_id, **env_config)``. RLlib passes an ``EnvContext`` (a dict with the runner's index as
    attributes)."""
    import gymnasium as gym

    import laddermill_gym  # noqa: F401  (registers the ids in this worker)

    return gym.make(env_id, **dict(env_config))


def _ray_modules():
    try:
        from ray.rllib.algorithms.ppo import PPOConfig
        from ray.rllib.core.rl_module.default_model_config import DefaultModelConfig
        from ray.tune.registry import register_env
    except ImportError as err:  # the missing module named: a present but broken RLlib (a dependency missing) too
        raise RuntimeError(f"{RLLIB_HINT} ({err})") from None
    return PPOConfig, DefaultModelConfig, register_env


def check_runner_cpus(env_runners: int) -> str | None:
    """Start Ray (or join ``RAY_ADDRESS``'s cluster) as RLlib would and return the error text when ``env_runners``
    exceeds the cluster's CPUs (a runner takes one: those beyond would never start, and the first iteration would
    wait for them without end); None when they fit."""
    import ray

    if not ray.is_initialized():
        ray.init(logging_level="warning")
    cpus = int(ray.cluster_resources().get("CPU", 0))
    if env_runners > cpus:
        return (f"--env-runners {env_runners}: the Ray cluster has {cpus} CPUs, one per env runner (the runners beyond "
                "them would never start)")
    return None


def ppo_config(env_id: str = "laddermill_gym/TetheredWing-v0", env_config: dict | None = None, how: str = "entry",
               env_runners: int = 1, envs_per_runner: int = 1, train_batch: int = 4000, minibatch: int = 500,
               epochs: int = 10, hidden: tuple[int, ...] = (64, 64), seed: int | None = 0):
    """RLlib's ``PPOConfig`` for ``env_id`` on ``env_runners`` remote runners (0: the driver samples itself) of
    ``envs_per_runner`` copies each; ``how`` is "entry" or "register" (module doc); ``train_batch`` env steps per
    iteration, split into minibatches of ``minibatch`` over ``epochs`` passes; ``hidden`` the layer widths of the
    policy and value networks. RLlib seeds each runner from ``seed`` and its index, so the same seed with another
    number of runners samples other episodes (a 1-runner and a 2-runner run differ from the first iteration)."""
    PPOConfig, DefaultModelConfig, register_env = _ray_modules()
    env_config = dict(env_config or {})
    if how == "entry":
        env = entry_id(env_id)
    elif how == "register":
        env = env_id
        register_env(env_id, functools.partial(make_env, env_id))
    else:
        raise ValueError(f"how = {how!r}: 'entry' or 'register'")
    return (PPOConfig()
            .environment(env=env, env_config=env_config)
            .env_runners(num_env_runners=env_runners, num_envs_per_env_runner=envs_per_runner,
                         rollout_fragment_length="auto")
            .training(train_batch_size_per_learner=train_batch, minibatch_size=minibatch, num_epochs=epochs)
            .rl_module(model_config=DefaultModelConfig(fcnet_hiddens=list(hidden)))
            .debugging(seed=seed))


def train(config, iterations: int, progress: bool = True) -> list[dict[str, Any]]:
    """Build the algorithm of ``config`` and train ``iterations`` iterations; their result dicts (RLlib's: the
    runners' episode statistics under ``"env_runners"``). Stops the algorithm's actors before returning."""
    algo = config.build_algo()
    results = []
    try:
        for i in range(iterations):
            r = algo.train()
            results.append(r)
            if progress:
                er = r.get("env_runners", {})
                print(f"iteration {i + 1}: {er.get('num_env_steps_sampled_lifetime', 0):.0f} env steps, episode "
                      f"return {er.get('episode_return_mean', float('nan')):.4g}, length "
                      f"{er.get('episode_len_mean', float('nan')):.4g}", flush=True)
    finally:
        algo.stop()
    return results


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m laddermill_gym.harness.rllib_train",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default="laddermill_gym/TetheredWing-v0", help="registered id")
    p.add_argument("--how", choices=("entry", "register"), default="entry", help="how the runners find the id")
    p.add_argument("--env-runners", type=int, default=2, help="remote env runners (Ray workers)")
    p.add_argument("--envs-per-runner", type=int, default=1)
    p.add_argument("--iterations", type=int, default=10)
    p.add_argument("--train-batch", type=int, default=4000, help="env steps per iteration")
    p.add_argument("--minibatch", type=int, default=500)
    p.add_argument("--epochs", type=int, default=10)
    p.add_argument("--episode-time", type=float, help="[s] episode length (default: the id's)")
    p.add_argument("--env-config", default="{}", help="more env keyword arguments, as JSON")
    p.add_argument("--seed", type=int, default=0)
    a = p.parse_args(argv)
    for name in ("env_runners", "iterations", "train_batch", "minibatch", "epochs", "envs_per_runner"):
        value = getattr(a, name)
        if value < (0 if name == "env_runners" else 1):
            p.error(f"--{name.replace('_', '-')} {value}: must be >= {0 if name == 'env_runners' else 1}")
    try:
        env_config = json.loads(a.env_config)
    except json.JSONDecodeError as err:
        p.error(f"--env-config {a.env_config!r}: not JSON ({err})")
    if not isinstance(env_config, dict):
        p.error(f"--env-config {a.env_config!r}: must be a JSON object")
    if a.episode_time is not None:
        env_config["episode_time"] = a.episode_time
    if a.seed < 0:
        p.error(f"--seed {a.seed}: must be >= 0")
    if a.minibatch > a.train_batch:
        p.error(f"--minibatch {a.minibatch}: must not exceed --train-batch {a.train_batch}")
    import gymnasium as gym

    try:  # the env built here once: a bad --env-config named now, not in every runner's log after Ray started
        make_env(a.env, env_config).close()
    except (ValueError, TypeError, gym.error.Error) as err:  # gymnasium's: an id it does not know
        p.error(f"--env {a.env} with --env-config {json.dumps(env_config)}: {err}")
    try:
        config = ppo_config(a.env, env_config, a.how, a.env_runners, a.envs_per_runner, a.train_batch,
                            a.minibatch, a.epochs, seed=a.seed)
    except RuntimeError as err:
        p.error(str(err))
    too_many = check_runner_cpus(a.env_runners)
    if too_many:
        p.error(too_many)
    train(config, a.iterations)
    return 0


if __name__ == "__main__":
    from laddermill_gym.studies.commands import run_guarded

    sys.exit(run_guarded("rllib_train", main))
