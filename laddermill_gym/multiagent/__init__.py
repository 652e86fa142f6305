"""One agent per wing: a PettingZoo ``ParallelEnv`` over the single-agent envs' tasks (``parallel.py``, needs
PettingZoo, the ``multiagent`` extra) and an SB3 VecEnv that makes every agent of B copies one env of a shared
policy (``sb3.py``, needs the ``rl`` extra), both reading the task through the per-wing view of ``agents.py``. May
import ``envs`` and the layers below it (``kernels`` for slot names), never ``control`` or anything above.

``parallel_env(env_id, k=1, **env_kwargs)`` and ``shared_policy_vec_env(env_id, n_copies, k=1, seed=None,
**env_kwargs)`` are imported on first use, so that each needs only its own extra.
"""

import importlib

__all__ = ["parallel_env", "WingParallelEnv", "shared_policy_vec_env", "SharedPolicyVecEnv", "WingAgents",
           "MULTIAGENT_IDS", "AGENT_KINDS"]

_LAZY = {"parallel_env": "parallel", "WingParallelEnv": "parallel", "shared_policy_vec_env": "sb3",
         "SharedPolicyVecEnv": "sb3", "WingAgents": "agents", "MULTIAGENT_IDS": "agents", "AGENT_KINDS": "agents"}


def __getattr__(name: str):
    """The names of :data:`__all__`, imported from their module on first use."""
    if name in _LAZY:
        return getattr(importlib.import_module(f"laddermill_gym.multiagent.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
