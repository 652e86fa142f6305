"""The policies a training config's ``policy`` field may name (``configs/agents/*.yaml``): SB3's default and the
residual policies started at the LQR, by name."""

from __future__ import annotations

from laddermill_gym.control.residual_policy import ResidualPolicy
from laddermill_gym.control.residual_sac import ResidualSACPolicy

__all__ = ["POLICIES", "policy_class"]

#: Policy names a training config's ``policy`` may give: SB3's default, the PPO residual (control/residual_policy.py)
#: and the SAC residual (control/residual_sac.py).
POLICIES = {"MlpPolicy": "MlpPolicy", "ResidualPolicy": ResidualPolicy, "ResidualSACPolicy": ResidualSACPolicy}


def policy_class(name: str):
    """The policy (an SB3 alias or class) of a config's ``policy`` ``name``; ValueError naming the known ones."""
    if name not in POLICIES:
        raise ValueError(f"policy {name!r}: not one of {sorted(POLICIES)}")
    return POLICIES[name]
