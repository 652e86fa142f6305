"""The entry points Gymnasium calls for the registered ids (``envs.register_envs``): ``TetheredWing_v0`` builds
``laddermill_gym/TetheredWing-v0``'s single env, ``TetheredWing_v0_vector`` its native vector env, and so for every
id of ``envs.ENV_IDS`` (the id's name with ``-`` as ``_``). Each builds the id's class of ``envs.ENTRY_POINTS`` from
the registered defaults merged with the caller's arguments (``envs.registered_arguments``): Gymnasium itself only
replaces a default by the caller's value, so ``scene_options={"overrides": ...}`` would drop the id's registered
``scene_options``."""

from __future__ import annotations

import importlib

from laddermill_gym.envs import ENTRY_POINTS, ENV_IDS, registered_arguments

__all__ = ["RegisteredEntryPoint"]


class RegisteredEntryPoint:
    """The env class of ``env_id`` (single, or the native vector env where ``vector``) called with the registered
    defaults merged with the caller's arguments; ``metadata`` is the class's (Gymnasium reads its render modes)."""

    def __init__(self, env_id: str, vector: bool):
        self.env_id, self.vector = env_id, bool(vector)

    @property
    def env_class(self) -> type:
        module, name = ENTRY_POINTS[self.env_id][1 if self.vector else 0].split(":")
        return getattr(importlib.import_module(module), name)

    @property
    def metadata(self) -> dict:
        return self.env_class.metadata

    def __call__(self, *args, **kwargs):
        return self.env_class(*args, **registered_arguments(self.env_id, kwargs))

    def __repr__(self) -> str:
        return f"RegisteredEntryPoint({self.env_id!r}, vector={self.vector})"


def __getattr__(name: str) -> RegisteredEntryPoint:
    """``<Name>_v<N>`` and ``<Name>_v<N>_vector`` for every registered id (PEP 562: looked up on use, so an id added
    to ``ENV_IDS`` has its entry points without another line here)."""
    for env_id in ENV_IDS:
        base = env_id.split("/")[-1].replace("-", "_")
        if name in (base, base + "_vector"):
            return RegisteredEntryPoint(env_id, vector=name != base)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
