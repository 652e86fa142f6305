"""Derivations of the shipped model data (the wing's coefficient table and inertia): commands that write
``configs/``; the simulator never imports them. Imports only ``model``."""
