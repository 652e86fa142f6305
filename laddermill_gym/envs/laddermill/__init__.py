"""LadderMill-v0: the moving-cable laddermill as an environment: its operating point (the periodic stationary
motion, memoised), the batched task (``task``; rewards and terminations in ``evaluate``), the single env (``env``),
the native vector env (``vector``), slot actions, the slot observation layout, settings and the renderer. Imports
``envs``' shared modules (and the rotorcraft's settings) and the layers below ``envs``."""
