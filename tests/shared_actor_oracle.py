"""A loop-by-loop oracle of the shared per-wing actor's features (written from the formula of
control/shared_policy.py's module doc, not from its code), used by the SB3 and the numpy evaluators' tests."""

from __future__ import annotations

import numpy as np

from laddermill_gym.control.shared_controller import LATERAL_FIELDS
from laddermill_gym.envs.observation import OBS_INDEX


def oracle_features(obs: np.ndarray, n: int, k: int, block: int, nb: int, trim: np.ndarray, scales: np.ndarray):
    """Features of one local observation by explicit loops: slot from the position entry, each seen wing's six
    lateral entries less its slot's trim, wrapped yaw, over the scales, zero when absent, then a 1; times the
    hat functions max(0, 1 - |p - j / (nb - 1)| (nb - 1))."""
    flags = obs[block * (2 * k + 1): block * (2 * k + 1) + 2 * k]
    p = obs[block * (2 * k + 1) + 2 * k]
    i = int(round(p * (n - 1)))
    offsets = [0] + [d for d in range(-k, k + 1) if d != 0]
    z = []
    for j, d in enumerate(offsets):
        present = 1.0 if j == 0 else flags[j - 1]
        s = min(max(i + d, 0), n - 1)
        row = []
        for f, name in enumerate(LATERAL_FIELDS):
            v = obs[j * block + OBS_INDEX[name]]
            if name == "phi":
                v -= trim[s, 0]
            if name == "psi":
                v = (v - trim[s, 1] + np.pi) % (2 * np.pi) - np.pi
            row.append(present * v / scales[f])
        z.extend(row)
    z.append(1.0)
    h = [max(0.0, 1.0 - abs(p - j / (nb - 1)) * (nb - 1)) for j in range(nb)]
    return np.outer(h, z).ravel()
