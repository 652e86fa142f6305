"""Command-line agents of laddermill_gym, run from the repository root: ``python -m agents.lqr`` (LQR design
and closed-loop eigenvalues), ``python -m agents.train`` (Stable-Baselines3 PPO / SAC from
configs/agents/*.yaml) and ``python -m agents.evaluate`` (any controller on seeded episodes)."""
