"""Offline tools that derive the data sets in ``configs/`` (not imported by the simulator)."""
