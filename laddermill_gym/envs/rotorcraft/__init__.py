"""Rotorcraft-v0 and v1: the batched task (``task``), the single and the native vector env (``env``; v1's in
``env_v1``), the observation layout, the trim and trim action, the settings and the renderer. Imports ``envs``'
shared modules and the layers below ``envs``."""
