"""Gymnasium environments of laddermill_gym: observation layout, action maps, tasks and vector envs."""
