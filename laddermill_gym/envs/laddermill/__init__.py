"""LadderMill-v0 and -v1: the moving-cable laddermill as an environment: its operating point (the periodic
stationary motion, memoised), the batched task (``task``; rewards and terminations in ``evaluate``), the single env
(``env``), the native vector env (``vector``), v1's env classes (``env_v1``: the same task with the v1 scene and
authority 0.2 registered), slot actions, the slot observation layout, settings and the renderer. Imports
``envs``' shared modules (and the rotorcraft's settings) and the layers below ``envs``."""
