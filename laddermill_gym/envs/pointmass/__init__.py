"""Gymnasium environment over a scene at the point-mass fidelity: actions are the kites' commanded attitude."""
