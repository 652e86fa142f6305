"""Gymnasium environment over a scene at the point-mass fidelity: actions are the kites' commanded attitude. Imports
``envs``' shared modules and the layers below ``envs``."""
