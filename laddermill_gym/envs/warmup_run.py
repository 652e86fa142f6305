"""The second process of the kernel warm-up (``envs/kernel_warmup.py``, issue 32 point 1): ``python -m
laddermill_gym.envs.warmup_run`` reads ``(target, task_kwargs)`` pickled on stdin and calls ``target``
(``"module:function"``) with ``task_kwargs``; the target compiles the task's kernels into numba's on-disk cache."""

from __future__ import annotations

import importlib
import pickle
import sys

__all__ = ["run"]


def run(target: str, task_kwargs: dict) -> None:
    """Import ``target``'s module and call its function with ``task_kwargs``."""
    module, _, name = target.partition(":")
    getattr(importlib.import_module(module), name)(task_kwargs)


def main() -> int:
    """The warm-up process: ``(target, task_kwargs)`` pickled on stdin."""
    import os
    import warnings

    from laddermill_gym.envs import compile_trace
    from laddermill_gym.envs.kernel_warmup import SWITCH

    os.environ[SWITCH] = "off"  # the tasks it builds start no warm-up of their own
    warnings.simplefilter("ignore")
    target, task_kwargs = pickle.loads(sys.stdin.buffer.read())
    if os.environ.get(compile_trace.VARIABLE):  # the start-up profile's timeline (envs/compile_trace.py)
        compile_trace.record(os.environ[compile_trace.VARIABLE], target)
    run(target, task_kwargs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
