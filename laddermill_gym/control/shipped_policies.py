"""Trained policies shipped with the package (``laddermill_gym/policies/<name>/``), so a fresh install can run
them without training: ``make_controller("ppo_tethered_wing", "laddermill_gym/TetheredWing-v0")``,
``laddermill evaluate --controllers ppo_tethered_wing``, ``laddermill gust-bench --controllers ppo_rotorcraft``.

Each folder is a trimmed training run folder (``laddermill train <config> --seed <seed>``): ``model.zip`` (the
SB3 model), ``vecnormalize.pkl`` (its observation statistics), ``config.yaml`` (the training config, which names
the env), ``algorithm.txt`` and ``README.md`` (the command and seed that reproduce it, and its scores). A shared
per-wing policy of the mill (``ppo_mill``: ``laddermill train ppo_mill_v1``; ``ppo_mill_v3``: ``laddermill train
ppo_mill_v3``) has ``shared_policy.yaml`` instead of
``vecnormalize.pkl`` (its actor scales its inputs by fixed Bryson scales), its config is the shared training's
(``ppo_mill_v1.yaml``, ``ppo_mill_v3.yaml``), and
``linear_actor.npz`` (its linear actor exported from ``model.zip``) lets it run without torch
(``control/shared_controller.py``).
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["POLICY_DIR", "SHIPPED_POLICIES", "shipped_policy_path"]

#: The folder of the shipped policies (package data, see pyproject.toml)
POLICY_DIR: Path = Path(__file__).resolve().parent.parent / "policies"

#: Shipped policy name -> the env id it was trained on (its config.yaml's ``env``)
SHIPPED_POLICIES: dict[str, str] = {
    "ppo_tethered_wing": "laddermill_gym/TetheredWing-v0",
    "ppo_rotorcraft": "laddermill_gym/Rotorcraft-v0",
    "ppo_mill": "laddermill_gym/LadderMill-v1",  # a shared per-wing policy (shared_policy.yaml, no vecnormalize.pkl)
    "ppo_chain": "laddermill_gym/LadderChain-v0",  # shared per-wing too (laddermill train ppo_chain_v0)
    "ppo_mill_v3": "laddermill_gym/LadderMill-v3",  # the newest mill id's (laddermill train ppo_mill_v3)
}


def shipped_policy_path(name: str) -> Path:
    """The folder of the shipped policy ``name``; ValueError naming the known names for another name,
    FileNotFoundError naming the folder when the package was installed without its policy files."""
    if name not in SHIPPED_POLICIES:
        raise ValueError(f"policy = {name!r}: not a shipped policy (shipped: {', '.join(sorted(SHIPPED_POLICIES))})")
    folder = POLICY_DIR / name
    if not (folder / "model.zip").is_file():
        raise FileNotFoundError(f"{folder / 'model.zip'}: missing; the shipped policy {name!r} was not installed "
                                "with the package (reinstall it, or train one: laddermill train "
                                f"configs/agents/{name}.yaml)")
    return folder
