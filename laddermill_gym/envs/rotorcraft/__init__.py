"""Rotorcraft-v0: the batched task (``task``), the single env (``env``), the native vector env (``vector``), the
observation layout, the trim and trim action, the settings and the renderer. Imports
``envs``' shared modules and the layers below ``envs``."""
