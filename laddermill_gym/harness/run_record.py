"""The record of how a training run was made: ``run.yaml`` in the run folder of ``laddermill train`` (and
``laddermill train-seeds``, and the shared per-wing policy's ``harness/shared_train.py``).

It holds the command line (``command``: ``sys.argv`` as a list of strings), the training seed (``seed``), torch's
thread count (``torch_threads``) and the versions of the packages the result depends on (``versions``: laddermill_gym,
stable_baselines3, torch, numpy, gymnasium and python). Nothing reads it to load a policy: a run folder without one
(the shipped policies, older runs) loads as before; it is for a person reproducing the run.
"""

from __future__ import annotations

import platform
import sys
from pathlib import Path
from typing import Any

__all__ = ["RUN_RECORD", "VERSIONED_PACKAGES", "package_versions", "run_record", "write_run_record"]

#: The file name in the run folder
RUN_RECORD = "run.yaml"
#: The packages whose versions are recorded (besides python's)
VERSIONED_PACKAGES = ("laddermill_gym", "stable_baselines3", "torch", "numpy", "gymnasium")


def package_versions() -> dict[str, str]:
    """``{package: version}`` of :data:`VERSIONED_PACKAGES` (their ``__version__``) and ``python``
    (``platform.python_version()``)."""
    import importlib

    versions = {name: str(importlib.import_module(name).__version__) for name in VERSIONED_PACKAGES}
    versions["python"] = platform.python_version()
    return versions


def run_record(seed: int, command: list[str] | None = None) -> dict[str, Any]:
    """The mapping ``run.yaml`` holds: ``command`` (``command``, default ``sys.argv``), ``seed``, ``torch_threads``
    (torch's thread count now: call it after setting that) and ``versions`` (:func:`package_versions`)."""
    import torch

    return dict(command=[str(a) for a in (sys.argv if command is None else command)], seed=int(seed),
                torch_threads=int(torch.get_num_threads()), versions=package_versions())


def write_run_record(out: Path, seed: int, command: list[str] | None = None) -> Path:
    """Write :func:`run_record` to ``out / run.yaml``; returns the path."""
    import yaml

    path = Path(out) / RUN_RECORD
    path.write_text(yaml.safe_dump(run_record(seed, command), sort_keys=False, default_flow_style=False))
    return path
