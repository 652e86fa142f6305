"""Rotorcraft-v0: the craft's environment, its settings, vector adapter and renderer."""
